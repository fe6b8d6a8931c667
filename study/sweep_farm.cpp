// The accuracy–speed sweep on the distributed engine (see sweep.hpp): every process computes the
// converged reference (the same deterministic runs), then the grid's configurations are the farm's
// tasks — one configuration per task, keyed by its id and labels, journaled as they finish, the
// shard's slice for array jobs. Each process builds each distinct model once (the reference's levels
// included) and shares it among its threads (scene/crane_model_cache.hpp). A task's record is the caller's text form of its SweepResult (the
// CSV line), so the journal holds exactly the rows of the table.
#include <fmt/format.h>

#include "solve/stop_request.hpp"
#include "distributed/errors.hpp"
#include "study/sweep.hpp"

namespace ffrf::study {

SweepOnEngine sweep_on_engine(distributed::Session& session, const scene::Scene& scene, const SweepRequest& request,
                              distributed::FarmOptions farm_options,
                              const std::function<std::string(const SweepResult&)>& record_of) {
  modal::ModeCache modes;
  SweepOnEngine out;
  out.study = sweep_scene(scene, request);
  scene::CraneModelCache models(out.study.scene, &modes);  // this process's shared models: the reference's and the tasks'
  measure_reference(out.study, request, models);
  const std::vector<SweepConfig> grid =
      sweep_grid(request.grid, request.radiation_axis, model_choice_rtol(request.tolerance), request.mode_set_axis);
  std::vector<std::string> keys;
  for (const SweepConfig& config : grid) {
    keys.push_back(fmt::format("id={} {} {}{}", config.id, config.choice.label(), integrator_label(config),
                               config.radiation ? " radiation " + radiation_name(config) : std::string()));
  }
  const std::vector<distributed::Task> tasks = distributed::make_tasks(keys);
  const SweepSetup setup{&out.study.scene, &out.study.reference, out.study.window_start, out.study.judged, request.duration,
                         request.max_explicit_steps, &models};
  const distributed::WorkFunction work = [&](const distributed::Task& task) {
    try {
      return record_of(run_configuration(setup, grid[task.index]));
    } catch (const solve::Interrupted& stop) {  // not a row: the rerun computes it again
      throw distributed::TaskAbandoned(fmt::format("{}: interrupted by signal {}", task.key, stop.signal));
    }
  };
  farm_options.shard = request.shard;
  out.farm = distributed::run_farm(session, tasks, work, farm_options);
  for (const distributed::TaskOutcome& outcome : out.farm.outcomes) {
    if (outcome.ok) {
      out.records.push_back(outcome.record);
      continue;
    }
    SweepResult failed;  // the work function itself threw (run_configuration turns solver failures into rows)
    failed.config = grid[outcome.index];
    failed.status = RunStatus::failed;
    failed.reason = outcome.error;
    out.records.push_back(record_of(failed));
  }
  out.farm.outcomes.clear();
  out.study.models_built = models.models_built() - out.study.reference_models_built;
  out.study.eigen_solves = modes.eigen_solves();
  return out;
}

}  // namespace ffrf::study
