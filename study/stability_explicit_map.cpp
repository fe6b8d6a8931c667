// Measured vs theoretical explicit step limits per boom model (see stability_explicit_map.hpp).
#include "study/stability_explicit_map.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "multibody/crane_run.hpp"
#include "study/run_pipeline.hpp"
#include "study/stability_theory.hpp"
#include "study/wall_clock.hpp"

namespace ffrf::study {
namespace {

ExplicitStabilityRow measure_model(const scene::Scene& scene, const scene::BoomChoice& choice,
                                   const solve::StableStepSearch& search, modal::ModeCache& modes) {
  const auto start = std::chrono::steady_clock::now();
  ExplicitStabilityRow row;
  row.choice = choice;
  row.label = choice.label();
  try {
    PreparedRun prepared = prepare_run(scene, choice, &modes);
    row.elastic_dof = prepared.equations->elastic_size();
    const Eigen::VectorXd omega = boom_angular_frequencies(scene, choice, &modes);
    row.highest_frequency = omega.size() == 0 ? 0.0 : omega.maxCoeff();
    row.boom_undamped_step = undamped_boom_step_limit(row.highest_frequency);
    row.boom_damped_step = damped_boom_step_limit(omega, scene::boom_stiffness_damping(scene));
    // The limit belongs to the linearization about the static equilibrium (not the lifted start).
    const Eigen::VectorXd& z0 = prepared.statics.z;
    row.jacobian_step = solve::explicit_stable_step(*prepared.equations, z0);
    // The bracket starts below the theory so the measured ends are not pinned to it.
    row.measured = solve::measure_stable_step(*prepared.equations, z0, 0.8 * row.jacobian_step, search);
    if (!row.measured.converged) {
      row.failure = fmt::format("search capped after {} trials, {} RHS evaluations", row.measured.trials,
                                row.measured.rhs_evaluations);
    }
  } catch (const solve::SolverFailure& failure) {
    row.failure = failure.what();
  }
  row.wall_seconds = seconds_since(start);
  return row;
}

}  // namespace

std::string ExplicitStabilityRow::limiting_part() const {
  return std::isfinite(boom_damped_step) && boom_damped_step <= 1.1 * jacobian_step ? "boom" : "crane";
}

std::vector<scene::BoomChoice> default_stability_models() {
  std::vector<scene::BoomChoice> models;
  for (int n = 1; n <= 64; n *= 2) models.push_back({scene::BoomKind::nodal, n, 0, false});
  for (int k = 1; k <= 12; ++k) models.push_back({scene::BoomKind::modal, 16, k, true});
  return models;
}

ExplicitStabilityMap explicit_stability_map(const scene::Scene& scene, const std::vector<scene::BoomChoice>& models,
                                            const solve::StableStepSearch& search,
                                            const std::function<void(const ExplicitStabilityRow&)>& progress) {
  scene::Scene calm = scene;
  calm.wave.reset();
  ExplicitStabilityMap map;
  map.scene_file = scene.file;
  map.scene_name = scene.name;
  map.imaginary_axis_boundary = solve::explicit_imaginary_axis_boundary();
  map.wire_cargo_frequency = wire_cargo_frequency(scene);
  map.relative_precision = search.relative_precision;
  modal::ModeCache modes;
  for (const scene::BoomChoice& choice : models) {
    map.rows.push_back(measure_model(calm, choice, search, modes));
    if (progress) progress(map.rows.back());
  }
  return map;
}

}  // namespace ffrf::study
