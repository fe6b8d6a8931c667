// The expected solver work of a candidate (see expected_work.hpp). The constants are measured on
// the reference scene (docs/recommend.md §2 gives the runs).
#include "study/expected_work.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "study/stability_theory.hpp"

namespace ffrf::study {
namespace {

constexpr double bdf_steps_per_period = 13.0;     // s at rtol 1e-4, per period of ω_f
constexpr double bdf_steps_rtol_exponent = 0.1;   // s ∝ rtol^(−0.1) (1e-4 → 1e-8: × 2.5)
constexpr double bdf_evaluations_per_step = 1.4;  // c_BDF: Newton iterations and Jacobians per step (1.40 measured)
constexpr double erk_evaluations_per_step = 5.0;  // c_ERK: ARKODE's default explicit table
constexpr double erk_accuracy_step_ratio = 2.0;   // r: an adaptive ERK run's steps over BDF's

}  // namespace

WorkForecast work_forecast(const scene::Scene& scene, const RecommendReasoning& reasoning, double duration,
                           int rigid_coordinates) {
  WorkForecast f;
  f.duration = duration;
  f.rigid_coordinates = rigid_coordinates;
  f.fast_frequency = std::max(reasoning.excitation_top, wire_cargo_frequency(scene));
  if (f.fast_frequency <= 0.0 && !reasoning.modes.empty()) f.fast_frequency = reasoning.modes.front().angular_frequency;
  const double periods = duration * f.fast_frequency / (2.0 * std::numbers::pi);
  f.accuracy_steps = std::max(1.0, periods * bdf_steps_per_period *
                                       std::pow(1e-4 / reasoning.relative_tolerance, bdf_steps_rtol_exponent));
  return f;
}

double expected_solver_work(const WorkForecast& f, int elastic_dof, solve::Integrator integrator,
                            double explicit_step_limit) {
  const double state_size = 2.0 * (f.rigid_coordinates + elastic_dof);
  if (integrator == solve::Integrator::arkode) {
    const double stability_steps = explicit_step_limit > 0.0 ? f.duration / explicit_step_limit : 0.0;
    return state_size * erk_evaluations_per_step * std::max(erk_accuracy_step_ratio * f.accuracy_steps, stability_steps);
  }
  return state_size * bdf_evaluations_per_step * f.accuracy_steps;
}

}  // namespace ffrf::study
