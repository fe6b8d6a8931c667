// The outputs of `ffrf sweep` from its CSV rows (so that a merge of shard CSVs and an unsharded
// run produce the same files): reading sweep.csv back, the Pareto front of error vs wall time, the
// accuracy–speed and mode-count charts (gnuplot data and scripts) and report.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/output_directory.hpp"

namespace ffrf::app {

// One CSV row, with what the charts and the report need parsed out of it.
struct SweepRow {
  int id = 0;
  std::string model, family, integrator, status, reason;
  int elements = 0, modes = 0;
  bool static_modes = false;
  std::optional<double> rtol, step;
  std::optional<double> worst, cargo_heave, daf_error;  // normalized RMS errors (ok rows)
  std::optional<double> wall;                         // integration wall time [s] (ok rows)
  long steps = 0;
  std::string line;                                   // the CSV line as written, with '\n'
  bool ok() const { return status == "ok" && worst && wall; }
  std::string settings() const;                       // "cvode rtol 1e-06", "generalized-alpha h 0.01 s"
};

// Splits one CSV line (no trailing newline) into fields; "..." quoting with "" for a quote.
std::vector<std::string> split_csv_line(const std::string& line);

// Parses a sweep CSV (the header must be sweep_csv_header()); throws std::runtime_error naming
// the file and line on anything else.
std::vector<SweepRow> read_sweep_csv(const std::string& text, const std::string& name);
// Header and rows sorted by id; throws std::runtime_error on a duplicate id.
std::string sweep_csv(std::vector<SweepRow>& rows);

// Indices (into rows) of the Pareto-optimal ok rows: no other row is both faster and more
// accurate (worst normalized RMS error); sorted by wall time.
std::vector<std::size_t> pareto_front(const std::vector<SweepRow>& rows);

// Writes the chart data and scripts and draws accuracy_speed.png and mode_count.png.
void draw_sweep_charts(const StagedDirectory& out, const std::vector<SweepRow>& rows, const std::string& subtitle);

// report.md: `preamble` (scene, grid, reference and its convergence table), counts, the Pareto
// table, the charts, the per-model best errors and the failures.
std::string sweep_markdown(const std::vector<SweepRow>& rows, const std::string& preamble, double duration);

}  // namespace ffrf::app
