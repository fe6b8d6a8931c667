// What `ffrf compare` reports: the models it runs (one list, in code), the differences of each
// model to the finest one, the Markdown report (report.md) that embeds the charts, the JSON
// summary and the short text summary on stdout.
#pragma once

#include <string>
#include <vector>

#include "app/crane_run.hpp"
#include "app/run_report.hpp"

namespace ffrf::app {

// The compared models, in report order; the one marked `reference` is what differences are taken
// against (the finest model of the comparison, not a converged reference).
struct ComparedModel {
  cases::BoomChoice choice;
  bool reference = false;
};
std::vector<ComparedModel> compared_models();

struct Comparison {
  RunContext context;
  std::vector<ModelRun> runs;                               // in compared_models() order
  std::size_t reference = 0;                                // index into runs
  std::vector<std::vector<SeriesDifference>> differences;  // per run, per crane_series() entry
};
// Differences of every run to the reference run over the reference's statistics window.
Comparison make_comparison(RunContext context, std::vector<ModelRun> runs, std::size_t reference);

std::string timeseries_name(const ModelRun& run);  // "timeseries_nodal_N16.csv"

std::string compare_markdown(const Comparison& comparison);
std::string compare_json(const Comparison& comparison);
std::string compare_text(const Comparison& comparison);

}  // namespace ffrf::app
