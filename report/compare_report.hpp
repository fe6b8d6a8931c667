// What `ffrf compare` reports: the models it runs (one list, in code), the errors of each model
// against the converged reference (coupling/error_metrics.hpp), the Markdown report (report.md)
// that embeds the charts, the JSON summary and the short text summary on stdout.
#pragma once

#include <string>
#include <vector>

#include "app/crane_reference.hpp"
#include "app/crane_run.hpp"
#include "app/run_report.hpp"
#include "coupling/error_metrics.hpp"

namespace ffrf::app {

// The compared models, in report order. All are in the tables; the `plotted` ones (and the
// reference) are drawn on the overlaid time-history charts, which stay readable with five curves.
struct ComparedModel {
  cases::BoomChoice choice;
  bool plotted = false;
};
std::vector<ComparedModel> compared_models();

struct Comparison {
  RunContext context;
  cases::ConvergedReference reference;
  ModelRun reference_run;                  // the reference as a run (statistics, time series)
  double window_start = 0.0;               // errors are measured for t >= window_start
  std::vector<ModelRun> runs;              // in compared_models() order
  std::vector<bool> plotted;               // per run
  std::vector<coupling::RunErrors> errors;  // per run, against the reference
};
// Errors of every run against the reference over the error window.
Comparison make_comparison(RunContext context, cases::ConvergedReference reference, std::vector<ModelRun> runs,
                           std::vector<bool> plotted);

std::string timeseries_name(const ModelRun& run);  // "timeseries_nodal_N16.csv"
inline constexpr const char* reference_timeseries_name = "timeseries_reference.csv";

std::string compare_markdown(const Comparison& comparison);
std::string compare_json(const Comparison& comparison);
std::string compare_text(const Comparison& comparison);

}  // namespace ffrf::app
