// The verdict of a comparison against a tolerance, one rule for `ffrf compare`, `ffrf sweep`,
// `ffrf recommend` and operability's per-cell model: a measured model passes when its worst error
// over the judged outputs (study/error_measure.hpp: the total error, static and dynamic together) is
// within the tolerance τ; the cheapest that passes is the one with the least **solver work**, RHS
// evaluations × state size (the evaluations include those that build Jacobians; the count does not
// depend on the machine's load, wall time does), wall time breaking a tie; only models integrated at
// the model-choice tolerance (model_choice_rtol) compete, so that every command names its cheapest
// model from runs at the same integrator accuracy. Speed-ups are the reference's wall time and
// solver work over the model's; the models that fail are named (error beyond τ, or run failed).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ffrf::study {

// The decisive measure of cost, and its name in every report's verdict sentence.
inline constexpr std::string_view solver_work_measure = "RHS evaluations × state size";
double solver_work(long rhs_evaluations, int state_size);

// The integrator tolerance (CVODE rtol = atol) at which a model is judged for the choice of the
// cheapest: the decade at or below τ/10⁴ (10⁻⁶ at τ = 1 %). A BDF run's global error measured on
// the reference scene reaches ~100× its rtol (nodal N = 1: 1.0×10⁻² at rtol 10⁻⁴, of which 2.4×10⁻³
// is the model's), so at τ/10⁴ the integrator's share stays near τ/100 and the model decides.
double model_choice_rtol(double tolerance);

// One measured model (a compare model, a sweep configuration, a recommend candidate).
struct MeasuredModel {
  std::string label;
  bool ran = true;             // false: its run failed or was skipped (reason)
  std::string reason;
  double error = std::numeric_limits<double>::quiet_NaN();  // worst normalized RMS over the judged outputs
  std::string worst_output;
  double wall_seconds = 0.0;   // integration
  double work = 0.0;           // solver_work(RHS evaluations, state size)
  bool at_choice_rtol = true;  // integrated at model_choice_rtol(τ): may be named the cheapest
};

struct ModelVerdict {
  bool passed = false;
  double wall_speedup = std::numeric_limits<double>::quiet_NaN();  // reference wall time / the model's
  double work_speedup = std::numeric_limits<double>::quiet_NaN();  // reference work / the model's
};

struct Verdict {
  double tolerance = 0.0;
  double reference_wall_seconds = 0.0, reference_work = 0.0;
  std::vector<ModelVerdict> models;        // per measured model, in its order
  std::optional<std::size_t> cheapest;     // cheapest_passing(models, tolerance)
  std::optional<std::size_t> most_accurate;  // the ran model with the smallest error (finite)
  std::vector<std::size_t> failed;         // models that did not pass, in order
  std::size_t passed_count() const { return models.size() - failed.size(); }
};

// Whether a measured model passes τ (it ran and its error is finite and ≤ τ).
bool passes(const MeasuredModel& model, double tolerance);

// The cheapest model that passes: among those that pass and ran at the model-choice rtol, the
// least work; equal work: the least wall time, then the first. Empty when none does.
std::optional<std::size_t> cheapest_passing(const std::vector<MeasuredModel>& models, double tolerance);

// Throws SettingError (Setting::tolerance) unless 0 < tolerance < 1.
Verdict judge(const std::vector<MeasuredModel>& models, double reference_wall_seconds, double reference_work,
              double tolerance);

}  // namespace ffrf::study
