// The verdict of compare and sweep (study/verdict.hpp) in words and JSON, and how the reports show
// an error channel to a human: pitch angles in degrees (the charts' unit), everything else in SI.
#pragma once

#include <string>
#include <vector>

#include "multibody/error_metrics.hpp"
#include "report/json.hpp"
#include "study/verdict.hpp"

namespace ffrf::report {

// The unit a report shows a channel's absolute errors in ("deg" for pitch, else the SI unit) and
// the factor from the SI value.
std::string_view display_unit(multibody::OutputChannel channel);
double display_scale(multibody::OutputChannel channel);

// "5.3× less" / "1.2× more" (of a speed-up ratio reference / model); "-" when not finite.
std::string speedup_words(double ratio);
// "5.3×" (a table cell); "-" when not finite.
std::string speedup_cell(double ratio);

// The verdict's headline: the cheapest model that passes by the decisive measure, solver work
// (study::solver_work_measure, named in the sentence), to what error, its solver work against
// `reference` and, reported but not decisive, its wall time; how many pass; or that none does and
// which came closest. `what` names the measured things ("models", "configurations"); `scope` narrows
// them (" at rtol 1e-06, the model-choice rtol": only those may be named the cheapest).
std::string verdict_headline(const study::Verdict& verdict, const std::vector<study::MeasuredModel>& models,
                             const std::string& reference, const std::string& what, const std::string& scope = "");
// "Fail: rigid 2.6 (cargo_heave), modal k=1 (N=16) 6.1e-02 (cargo_heave)." (empty when all pass).
std::string failed_list(const study::Verdict& verdict, const std::vector<study::MeasuredModel>& models);
// "pass" / "FAIL" / "not run"
std::string pass_cell(const study::Verdict& verdict, const std::vector<study::MeasuredModel>& models, std::size_t i);

// {tolerance, passed, failed, cheapest: {label, error, worst_output, wall_speedup, work_speedup} | null,
//  reference_wall_s, reference_work, sentence}
Json verdict_json(const study::Verdict& verdict, const std::vector<study::MeasuredModel>& models,
                  const std::string& sentence);

}  // namespace ffrf::report
