// The building blocks of `ffrf stability` (the stability map report, issue 5 "where methods fail"):
// one cell of a map (green: the method held, with the number that says how well; red: the failure
// named by kind, with when and the number behind it), one section per experiment (what was run,
// the table, the charts, the finding), and the formatting shared by the experiments
// (app/stability_*.cpp) and the report writer (app/command_stability.cpp).
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "app/crane_run.hpp"
#include "app/json_writer.hpp"
#include "app/output_directory.hpp"
#include "cases/crane_builder.hpp"
#include "cases/scene.hpp"
#include "coupling/failure.hpp"

namespace ffrf::app {

struct StabilityCell {
  std::string row;     // the method or model ("nodal N=10, no stiffening")
  std::string column;  // the condition ("Ωs = 4 rad/s", "max drift")
  bool ok = true;      // green
  std::string status;  // "ok", or the failure kind (coupling::to_string), or what the cell measured
  double time = NAN;   // when the failure was detected [s] (NaN: none)
  double value = NAN;  // the number behind the cell
  std::string unit;    // of value
  std::string detail;  // the cause with its numbers, or what the value is
  std::vector<std::pair<std::string, double>> extra;  // further numbers (summary.json), names with units
};

// A red cell from a detection or a solver failure (its kind, time, value and cause).
StabilityCell failure_cell(std::string row, std::string column, const coupling::Detection& detection, std::string unit);
// "✅ 0.123 m" or "❌ divergence at t = 9.87 s (0.81 1/s)": the Markdown text of a cell.
std::string cell_markdown(const StabilityCell& cell);

struct StabilitySection {
  std::string key;         // "explicit", "drift", "spin", "wire", "bdf_order", "buckling" (summary.json)
  std::string title;
  std::string provenance;  // Markdown: models, integrator, tolerances, durations
  std::string table;       // Markdown
  std::vector<std::string> charts;  // PNG file names in the output directory
  std::string finding;     // one paragraph with the numbers
  std::vector<StabilityCell> cells;
  std::vector<std::pair<std::string, double>> numbers;  // the section's key results (summary.json)
};

struct StabilityOptions {
  bool quick = false;     // fewer models, shorter horizons (< 20 s in all)
  bool progress = false;  // one line per run on stderr (terminals only)
};

// A Markdown table: header row, then rows of already formatted cells.
std::string markdown_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
// gnuplot single-quoted string (a quote doubled).
std::string gnuplot_quoted(const std::string& text);
// A progress line on stderr when options.progress.
void stability_progress(const StabilityOptions& options, const std::string& line);

// The integrator settings of one experiment's run: `ffrf run`'s for these options and scene, without
// the progress line (the command prints its own); throws std::invalid_argument for bad options.
coupling::IntegratorSettings experiment_settings(const DynamicsOptions& dynamics, const cases::Scene& scene);
// Engineering numbers for the report ("-" when not finite).
std::string shown(double value, int digits = 4);

// summary.json: one object per section with its cells and numbers.
void write_section_json(JsonWriter& json, const StabilitySection& section);

// The experiments (app/stability_*.cpp). Each runs its models, writes its CSVs, gnuplot scripts and
// PNG charts into `out`, and returns the section; solver failures inside are red cells.
StabilitySection explicit_step_section(const cases::Scene& scene, const StabilityOptions& options,
                                       const StagedDirectory& out);                   // stability_explicit.cpp
StabilitySection constraint_drift_section(const cases::Scene& scene, const StabilityOptions& options,
                                          const StagedDirectory& out);                // stability_drift.cpp
StabilitySection spin_section(const cases::Scene& scene, const StabilityOptions& options,
                              const StagedDirectory& out);                            // stability_spin.cpp
StabilitySection wire_section(const cases::Scene& scene, const StabilityOptions& options,
                              const StagedDirectory& out);                            // stability_wire.cpp
StabilitySection bdf_order_section(const cases::Scene& scene, const StabilityOptions& options,
                                   const StagedDirectory& out);                       // stability_bdf_order.cpp
StabilitySection buckling_section(const cases::Scene& scene, const StabilityOptions& options,
                                  const StagedDirectory& out);                        // stability_buckling.cpp

}  // namespace ffrf::app
