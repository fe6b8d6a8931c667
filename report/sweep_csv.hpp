// sweep.csv, the sweep's one table of results (study/sweep.hpp): one row per configuration, written
// from the study's results and read back, so that a merge of shard CSVs and an unsharded run produce
// the same outputs. Absolute errors in the channel's unit, pitch in degrees; work = RHS evaluations ×
// state size (study::solver_work). Timing columns are the ones named `*_s`; a failed or skipped row has empty
// error and cost cells and its reason, never NaN.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "study/sweep.hpp"

namespace ffrf::report {

// The CSV header line (with '\n') and one result's line (with '\n').
std::string sweep_csv_header();
std::string sweep_csv_line(const study::SweepResult& result);

// One CSV row, with what the charts and the report need parsed out of it.
struct SweepRow {
  int id = 0;
  std::string model, family, integrator, status, reason;
  std::string radiation;                              // "constant", "state-space", "convolution"; empty: the scene's
  int elements = 0, modes = 0;
  bool static_modes = false;
  std::optional<double> rtol, step;
  std::optional<double> worst, cargo_heave, daf_error;  // normalized RMS errors (ok rows)
  std::optional<double> wall;                         // integration wall time [s] (ok rows)
  long steps = 0, rhs_evaluations = 0;                // RHS evaluations include those for Jacobians
  int state_size = 0;                                 // 2 × minimal coordinates (ok rows)
  double work() const { return study::solver_work(rhs_evaluations, state_size); }  // RHS evaluations × state size
  std::string line;                                   // the CSV line as written, with '\n'
  bool ok() const { return status == "ok" && worst && wall; }
  std::string settings() const;  // "cvode rtol 1e-06", "generalized-alpha h 0.01 s", "…, state-space radiation"
};

// Splits one CSV line (no trailing newline) into fields; "..." quoting with "" for a quote.
std::vector<std::string> split_csv_line(const std::string& line);

// Parses a sweep CSV (the header must be sweep_csv_header()); throws std::runtime_error naming
// the file and line on anything else.
std::vector<SweepRow> read_sweep_csv(const std::string& text, const std::string& name);
// Header and rows sorted by id; throws std::runtime_error on a duplicate id.
std::string sweep_csv(std::vector<SweepRow>& rows);

}  // namespace ffrf::report
