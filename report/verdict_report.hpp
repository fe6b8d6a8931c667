// The verdict of compare and sweep (study/verdict.hpp) in words and JSON, and how the reports show
// an error channel to a human: pitch angles in degrees (the charts' unit), everything else in SI.
#pragma once

#include <string>
#include <vector>

#include "coupling/error_metrics.hpp"
#include "report/json.hpp"
#include "study/verdict.hpp"

namespace ffrf::report {

// The unit a report shows a channel's absolute errors in ("deg" for pitch, else the SI unit) and
// the factor from the SI value.
std::string_view display_unit(coupling::OutputChannel channel);
double display_scale(coupling::OutputChannel channel);

// "5.3× less" / "1.2× more" (of a speed-up ratio reference / model); "-" when not finite.
std::string speedup_words(double ratio);
// "5.3×" (a table cell); "-" when not finite.
std::string speedup_cell(double ratio);

// The verdict's headline: which model is the cheapest to pass, to what error, how much faster than
// `reference` (wall time and solver work), and how many pass; or that none does and which came
// closest. `what` names the measured things ("models", "configurations").
std::string verdict_headline(const study::Verdict& verdict, const std::vector<study::MeasuredModel>& models,
                             const std::string& reference, const std::string& what);
// "Fail: rigid 2.6 (cargo_heave), modal k=1 (N=16) 6.1e-02 (cargo_heave)." (empty when all pass).
std::string failed_list(const study::Verdict& verdict, const std::vector<study::MeasuredModel>& models);
// "pass" / "FAIL" / "not run"
std::string pass_cell(const study::Verdict& verdict, const std::vector<study::MeasuredModel>& models, std::size_t i);

// {tolerance, passed, failed, cheapest: {label, error, worst_output, wall_speedup, work_speedup} | null,
//  reference_wall_s, reference_work, sentence}
Json verdict_json(const study::Verdict& verdict, const std::vector<study::MeasuredModel>& models,
                  const std::string& sentence);

}  // namespace ffrf::report
