// What `ffrf compare` reports (study/compare.hpp): the Markdown report (report.md) that embeds the
// charts and gives a verdict, the JSON summary and the short text summary on stdout, and the
// file names of each model's time series.
#pragma once

#include <string>

#include "report/run_report.hpp"
#include "study/compare.hpp"

namespace ffrf::report {

std::string timeseries_name(const study::ModelRun& run);  // "timeseries_nodal_N16.csv"
inline constexpr const char* reference_timeseries_name = "timeseries_reference.csv";

// `context`: the scene and the compared models' settings.
std::string compare_markdown(const RunContext& context, const study::Comparison& comparison);
std::string compare_json(const RunContext& context, const study::Comparison& comparison);
std::string compare_text(const RunContext& context, const study::Comparison& comparison);

}  // namespace ffrf::report
