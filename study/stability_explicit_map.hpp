// The explicit stability map of a crane scene (for `ffrf stability`): for each boom model the
// largest fixed step of ARKODE's explicit Runge–Kutta measured by trial runs
// (solve::measure_stable_step) against the theory — the boom's own bound (β_I/ω_max undamped;
// with its stiffness-proportional damping) and the linearized crane's Jacobian bound
// (solve::explicit_stable_step). Its tables and charts: report/stability_explicit_map_report.hpp.
// The scene is analysed in calm water: the limit belongs to the linearization about the static
// equilibrium (the 10 s wave does not move it).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"
#include "solve/explicit_stability.hpp"

namespace ffrf::study {

struct ExplicitStabilityRow {
  scene::BoomChoice choice;
  std::string label;
  int elastic_dof = 0;
  double highest_frequency = 0.0;        // ω_max of the boom's elastic coordinates [rad/s] (0: rigid)
  double boom_undamped_step = 0.0;       // β_I / ω_max [s] (infinity: rigid)
  double boom_damped_step = 0.0;         // with the boom's structural damping [s] (infinity: rigid)
  double jacobian_step = 0.0;            // solve::explicit_stable_step [s]
  solve::StableStepMeasurement measured;
  double wall_seconds = 0.0;             // equilibrium, theory and every trial
  std::string failure;                   // non-empty: the model could not be measured (why)

  bool ok() const { return failure.empty() && measured.converged; }
  // "boom" when the boom's damped bound is within 10 % of the coupled bound, else "crane".
  std::string limiting_part() const;
};

struct ExplicitStabilityMap {
  std::string scene_file, scene_name;
  double imaginary_axis_boundary = 0.0;  // β_I of the ERK table
  double wire_cargo_frequency = 0.0;     // √(k_wire / m_cargo) [rad/s]
  double relative_precision = 0.0;       // of every measurement
  std::vector<ExplicitStabilityRow> rows;
};

// Nodal N = 1, 2, 4, …, 64 and modal k = 1 … 12 with static modes on the N = 16 mesh.
std::vector<scene::BoomChoice> default_stability_models();

// Measures every model (`progress` sees each row as it is done). A model whose static equilibrium
// or measurement fails becomes a row with `failure` set; scene errors (scene::SceneError) propagate.
ExplicitStabilityMap explicit_stability_map(const scene::Scene& scene, const std::vector<scene::BoomChoice>& models,
                                            const solve::StableStepSearch& search = {},
                                            const std::function<void(const ExplicitStabilityRow&)>& progress = {});

}  // namespace ffrf::study
