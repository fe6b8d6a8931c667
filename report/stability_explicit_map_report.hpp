// The explicit stability map (study/stability_explicit_map.hpp) as a CSV table (units in the
// column names), a Markdown table and two gnuplot charts: largest stable step vs ω_max (log–log,
// with β_I/ω) and the model × step stability map (green stable, red unstable, the theoretical
// boundary drawn over it).
#pragma once

#include <string>

#include "report/output_directory.hpp"
#include "study/stability_explicit_map.hpp"

namespace ffrf::report {

std::string explicit_stability_csv(const study::ExplicitStabilityMap& map);
std::string explicit_stability_markdown(const study::ExplicitStabilityMap& map);

// Writes explicit_stability.csv, the chart data and scripts, and draws stable_step_vs_frequency.png
// and stability_map.png; throws std::runtime_error when gnuplot is missing or fails.
void write_explicit_stability_map(const StagedDirectory& out, const study::ExplicitStabilityMap& map);

}  // namespace ffrf::report
