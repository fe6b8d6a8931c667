// The report of `ffrf stability` (the stability map: where each method fails): one cell of a
// map (green: the method held, with the number that says how well; red: the failure named by kind,
// with when and the number behind it), one section per experiment of study/stability.hpp (what was
// run, the table, the charts, the finding), and the whole report (report.md, summary.json).
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "solve/failure.hpp"
#include "report/json.hpp"
#include "report/gnuplot.hpp"
#include "report/output_directory.hpp"
#include "scene/scene.hpp"
#include "study/stability.hpp"

namespace ffrf::report {

struct StabilityCell {
  std::string row;     // the method or model ("nodal N=10, no stiffening")
  std::string column;  // the condition ("Ωs = 4 rad/s", "max drift")
  bool ok = true;      // green
  std::string status;  // "ok", or the failure kind (solve::to_string), or what the cell measured
  double time = NAN;   // when the failure was detected [s] (NaN: none)
  double value = NAN;  // the number behind the cell
  std::string unit;    // of value
  std::string detail;  // the cause with its numbers, or what the value is
  std::vector<std::pair<std::string, double>> extra;  // further numbers (summary.json), names with units
};

// A red cell from a detection or a solver failure (its kind, time, value and cause).
StabilityCell failure_cell(std::string row, std::string column, const solve::Detection& detection, std::string unit);
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

// A Markdown table: header row, then rows of already formatted cells.
std::string markdown_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
// Engineering numbers for the report ("-" when not finite).
std::string shown(double value, int digits = 4);

// summary.json: one object per section with its cells and numbers.
Json section_json(const StabilitySection& section);

// The sections (report/stability_*.cpp). Each writes its CSVs, gnuplot scripts and PNG charts into `out`.
StabilitySection explicit_step_section(const study::ExplicitStepStudy& study, const StagedDirectory& out);
StabilitySection constraint_drift_section(const scene::Scene& scene, const study::DriftStudy& study,
                                          const StagedDirectory& out);
StabilitySection spin_section(const scene::Scene& scene, const study::SpinStudy& study, const StagedDirectory& out);
StabilitySection wire_section(const scene::Scene& scene, const study::WireStudy& study, const StagedDirectory& out);
StabilitySection bdf_order_section(const scene::Scene& scene, const study::BdfOrderStudy& study);
StabilitySection buckling_section(const scene::Scene& scene, const study::BucklingStudy& study);

// The whole report: every section of the map (charts written into `out`), report.md and summary.json.
struct StabilityReport {
  std::string markdown;
  std::string json;
};
StabilityReport stability_report(const scene::Scene& scene, const std::string& scene_file, bool quick,
                                 const study::StabilityMap& map, const StagedDirectory& out);

}  // namespace ffrf::report
