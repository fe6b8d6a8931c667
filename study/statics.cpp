// The static equilibrium of one model with its still-water checks (see statics.hpp).
#include "study/statics.hpp"

#include <cmath>
#include <limits>
#include <memory>

#include "multibody/run_monitor.hpp"
#include "multibody/crane_run.hpp"
#include "study/run_pipeline.hpp"
#include "study/work_limits.hpp"

namespace ffrf::study {

StaticsResult solve_statics(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* modes) {
  // prepare_run's model and solve (its initial state aside), with how the solve went.
  check_run_memory(choice);
  const std::unique_ptr<multibody::CraneEquations> equations = scene::build_crane_equations(scene, choice, modes);
  const Eigen::VectorXd guess = equations->initial_guess();
  StaticsResult result;
  result.choice = choice;
  result.elastic_dof = equations->elastic_size();
  result.statics = multibody::solve_static_equilibrium(*equations, guess, result.path);
  const multibody::CraneOutputs& o = result.statics.outputs;
  // The hull's coordinates lead the minimal ones when it floats; a held or driven hub keeps its pose.
  result.rest_pose = scene.is_crane() ? Eigen::Vector3d(guess.head<3>()) : o.hull;
  result.hull_offset = o.hull - result.rest_pose;
  result.draft = draft_at_mid_length(scene, o);
  result.wire_stretch = scene.wire ? o.wire_length - scene.wire->unstretched_length : std::numeric_limits<double>::quiet_NaN();
  result.cargo_weight = scene.cargo ? scene.cargo->mass * scene.environment.gravity : 0.0;

  // The detectors of a run, on the one sample at rest in still water.
  multibody::MonitorLimits limits = monitor_limits(scene);
  limits.water.wave_amplitude = 0.0;
  limits.static_tension = o.wire_tension;
  multibody::RunResult at_rest;
  at_rest.time = {0.0};
  at_rest.samples = {o};
  result.buckling_ratio = multibody::max_buckling_load_ratio(at_rest, limits);
  for (const solve::Detection& found : multibody::post_run_detections(at_rest, limits)) {
    if (found.kind == solve::FailureKind::deck_submerged || found.kind == solve::FailureKind::cargo_in_water) {
      throw solve::SolverFailure(found.kind, "static equilibrium", found.cause + " at rest in still water", 0.0, found.remedy,
                                    found.value);
    }
    result.notes.push_back(found);
  }
  return result;
}

}  // namespace ffrf::study
