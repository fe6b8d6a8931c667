// The solver work a candidate model is expected to cost before it runs — the order of recommend's
// ladder (docs/recommend.md §2): W = S × E, the state size S = 2 (n_rigid + n_elastic) times the
// expected RHS evaluations E (the measure of study::solver_work, Jacobian evaluations included).
//  * BDF (CVODE): the steps follow the fastest motion the scene excites and the accuracy, not the
//    model's stiffest frequency (the top modes are damped and BDF's order is limited for them: the
//    reference scene takes 2 878–3 550 steps at rtol 10⁻⁴ for every model from modal k = 2, top
//    frequency 23.7 rad/s, to nodal N = 16, explicit step limit 10⁻⁶ s). n = T ω_f/(2π) · s(rtol) steps, ω_f
//    the faster of the excitation's top and the wire–cargo bounce, s the steps per period measured at
//    that rtol; E = c_BDF n. So among BDF candidates the state size decides, and a static-mode model
//    (k + 5 static modes: their Rayleigh frequencies are the boom's stiffest, which BDF does not feel)
//    sits where its k + 5 coordinates put it.
//  * Explicit RK (ARKODE): c_ERK evaluations per step over the larger of the steps its accuracy needs
//    (r n, measured) and T/h, h its stability limit: a static-mode model's stiff Rayleigh frequencies
//    count here.
#pragma once

#include "multibody/crane_run.hpp"
#include "scene/scene.hpp"
#include "study/recommend_reasoning.hpp"

namespace ffrf::study {

struct WorkForecast {
  double duration = 0.0;         // T [s]
  double fast_frequency = 0.0;   // ω_f [rad/s]
  double accuracy_steps = 0.0;   // n: a BDF run's expected steps at the candidates' rtol
  int rigid_coordinates = 0;     // n_rigid: the crane's minimal coordinates with a rigid boom
};

// The forecast for a scene's runs of `duration` seconds at the reasoning's rtol; `rigid_coordinates`
// from the rigid crane's equations. Throws nothing.
WorkForecast work_forecast(const scene::Scene& scene, const RecommendReasoning& reasoning, double duration,
                           int rigid_coordinates);

// Expected RHS evaluations × state size of a model with `elastic_dof` coordinates under `integrator`
// (ARKODE: `explicit_step_limit` [s], its stability limit).
double expected_solver_work(const WorkForecast& forecast, int elastic_dof, solve::Integrator integrator,
                            double explicit_step_limit);

}  // namespace ffrf::study
