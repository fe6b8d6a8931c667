// Running the sweep's configurations (sweep_grid.hpp) against one reference, in parallel, and
// their results as CSV rows. One row per configuration; a solver failure is a row with status
// `failed` and the reason, never an exception. Timing columns are the ones named `*_s`.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/sweep_grid.hpp"
#include "cases/scene.hpp"
#include "coupling/error_metrics.hpp"

namespace ffrf::app {

enum class RunStatus { ok, failed, skipped };
std::string_view to_string(RunStatus status);

struct SweepResult {
  SweepConfig config;
  RunStatus status = RunStatus::ok;
  std::string reason;           // failed/skipped: why
  double step = 0.0;            // fixed step actually taken [s] (0: adaptive)
  double stable_step = 0.0;     // ARKODE rows: the explicit stability limit [s] (0: not computed)
  coupling::RunErrors errors;   // ok rows
  coupling::SolverStats stats;  // ok rows
};

struct SweepSetup {
  const cases::Scene* scene = nullptr;
  const coupling::RunResult* reference = nullptr;
  double window_start = 0.0;
  double duration = 0.0;
  double output_interval = 0.05;
  long max_explicit_steps = 2'000'000;  // ARKODE runs needing more steps are skipped (with the reason)
};

// Runs one configuration (thread-safe; builds its own crane).
SweepResult run_configuration(const SweepSetup& setup, const SweepConfig& config);

// Runs the configurations over `jobs` threads; results in the order of `configs`. `progress` is
// called (serialized) after each run with the number done.
std::vector<SweepResult> run_sweep(const SweepSetup& setup, const std::vector<SweepConfig>& configs, int jobs,
                                   const std::function<void(const SweepResult&, std::size_t done)>& progress);

// The CSV header line (with '\n') and one result's line (with '\n').
std::string sweep_csv_header();
std::string sweep_csv_line(const SweepResult& result);

}  // namespace ffrf::app
