// Running the sweep's configurations against one reference, in parallel (see sweep.hpp).
#include "study/sweep.hpp"

#include "study/radiation_compare.hpp"
#include "study/recommend_reasoning.hpp"

#include <fmt/format.h>

#include <exception>

#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

namespace ffrf::study {
namespace {

// Generalized-α rounds its step down to divide the output interval (theory §8.3).
double dividing_step(double requested, double output_interval) {
  return output_interval / std::ceil(output_interval / requested - 1e-9);
}

}  // namespace

std::string_view to_string(RunStatus status) {
  switch (status) {
    case RunStatus::ok: return "ok";
    case RunStatus::failed: return "failed";
    case RunStatus::skipped: return "skipped";
  }
  return "?";
}

SweepResult run_configuration(const SweepSetup& setup, const SweepConfig& config) {
  SweepResult r;
  r.config = config;
  // The configuration's radiation model: the scene with it — the shared models' (keyed
  // on the radiation model too) or, without shared models, a copy.
  std::optional<scene::Scene> configured;
  if (config.radiation && setup.models == nullptr) configured = with_radiation(*setup.scene, *config.radiation);
  const scene::Scene& scene = setup.models != nullptr ? setup.models->scene(config.radiation)
                              : configured            ? *configured
                                                      : *setup.scene;
  const double output_interval = scene.simulation.output_interval;
  try {
    DynamicsRequest request;
    request.integrator = config.integrator;
    request.relative_tolerance = request.absolute_tolerance = config.rtol > 0.0 ? config.rtol : 1e-6;
    request.duration = setup.duration;
    if (config.step > 0.0) r.step = request.fixed_step = dividing_step(config.step, output_interval);
    multibody::RunSettings settings = integrator_settings(scene, request);
    PreparedRun prepared = setup.models != nullptr ? prepare_run(*setup.models, config.choice, config.radiation)
                                                   : prepare_run(scene, config.choice);
    if (config.integrator == solve::Integrator::arkode) {
      r.stable_step = solve::explicit_stable_step(*prepared.equations, prepared.initial_state);
      const double h = config.stability_factor > 0.0 ? config.stability_factor * r.stable_step : r.stable_step;
      // A model with nothing free to move has no stability limit: it keeps the adaptive step.
      if (config.stability_factor > 0.0 && std::isfinite(h)) r.step = settings.fixed_step = h;
      const double needed = setup.duration / h;
      if (config.stability_factor <= 1.0 && needed > static_cast<double>(setup.max_explicit_steps)) {
        r.status = RunStatus::skipped;
        r.reason = fmt::format("not run: the explicit stability limit {:.3g} s needs about {:.2g} steps for {:g} s, more "
                               "than the sweep's budget of {:.2g}",
                               r.stable_step, needed, setup.duration, static_cast<double>(setup.max_explicit_steps));
        return r;
      }
    }
    const ModelRun run = integrate_run(scene, prepared, settings);
    r.errors = multibody::compare_runs(run.result, setup.reference->run.result, setup.window_start);
    r.worst = worst_error(r.errors, setup.judged);
    r.stats = run.result.stats;
    r.state_size = run.state_size;
  } catch (const solve::SolverFailure& failure) {
    r.status = RunStatus::failed;
    r.reason = fmt::format("{}: {} (t = {:g} s)", failure.solver(), failure.cause(), failure.time());
  } catch (const std::exception& error) {
    r.status = RunStatus::failed;
    r.reason = error.what();
  }
  return r;
}

double default_sweep_duration(const scene::Scene& scene, SweepGrid grid) {
  return grid == SweepGrid::quick ? quick_sweep_duration : scene.simulation.duration;
}

int worker_threads(int jobs) { return jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

void add_scene_axes(SweepRequest& request, const scene::Scene& scene, bool radiation_fixed) {
  request.radiation_axis = scene.bem.has_value() && !radiation_fixed;
  request.mode_set_axis = scene.boom.mount && scene.boom.mount->pinned;
}

SweepStudy sweep_scene(const scene::Scene& scene, const SweepRequest& request) {
  if (request.jobs < 0) {
    throw SettingError(Setting::jobs, fmt::format("{}", request.jobs), "not a thread count (valid range [1, inf), 0: one per core)");
  }
  if (!(request.tolerance > 0.0 && request.tolerance < 1.0)) {
    throw SettingError(Setting::tolerance, fmt::format("{}", request.tolerance), "not a tolerance (valid range (0, 1))");
  }
  SweepStudy study;
  study.tolerance = request.tolerance;
  study.stiffening_from_physics = !request.stiffening;
  study.stiffening = request.stiffening.value_or(physics_stiffening(scene, request.tolerance));
  study.scene = scene;
  study.scene.boom.stiffening = study.stiffening;
  if (request.radiation_axis) study.scene = with_radiation(study.scene, hydro::RadiationKind::convolution);
  return study;
}

void measure_reference(SweepStudy& study, const SweepRequest& request, scene::CraneModelCache& models) {
  const int built = models.models_built();
  study.reference = converged_reference(models, request.reference, request.duration);
  study.reference_models_built = models.models_built() - built;
  study.window_start = error_window(study.scene, request.duration);
  study.judged = judged_outputs(study.scene);
}

SweepStudy sweep_reference(const scene::Scene& scene, const SweepRequest& request, modal::ModeCache* modes) {
  SweepStudy study = sweep_scene(scene, request);
  scene::CraneModelCache models(study.scene, modes);
  measure_reference(study, request, models);
  return study;
}

std::vector<SweepConfig> sweep_configurations(const SweepRequest& request) {
  std::vector<SweepConfig> configs;
  for (const SweepConfig& config :
       sweep_grid(request.grid, request.radiation_axis, model_choice_rtol(request.tolerance), request.mode_set_axis)) {
    if (in_shard(config, request.shard)) configs.push_back(config);
  }
  return configs;
}

SweepStudy sweep(const scene::Scene& scene, const SweepRequest& request,
                 const std::function<void(const ConvergedReference&)>& on_reference,
                 const std::function<void(const SweepResult&, std::size_t, std::size_t)>& progress) {
  if (request.jobs < 1) {
    throw SettingError(Setting::jobs, fmt::format("{}", request.jobs), "not a thread count (valid range [1, inf))");
  }
  modal::ModeCache modes;
  SweepStudy study = sweep_scene(scene, request);
  const scene::Scene& modelled = study.scene;
  scene::CraneModelCache models(modelled, &modes);  // the reference's levels and the configurations'
  measure_reference(study, request, models);
  if (on_reference) on_reference(study.reference);
  const std::vector<SweepConfig> configs = sweep_configurations(request);
  const SweepSetup setup{&modelled, &study.reference, study.window_start, study.judged, request.duration,
                         request.max_explicit_steps, &models};
  study.results.resize(configs.size());
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex progress_mutex;
  std::exception_ptr escaped;  // what a worker could not turn into a row (an interrupt): rethrown after the join
  auto worker = [&] {
    try {
      for (std::size_t i = next++; i < configs.size(); i = next++) {
        study.results[i] = run_configuration(setup, configs[i]);
        const std::lock_guard lock(progress_mutex);
        ++done;
        if (progress) progress(study.results[i], done, configs.size());
      }
    } catch (...) {
      const std::lock_guard lock(progress_mutex);
      if (!escaped) escaped = std::current_exception();
      next = configs.size();  // hand out nothing more
    }
  };
  std::vector<std::thread> threads;
  const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(request.jobs), configs.size());
  for (std::size_t t = 0; t < count; ++t) threads.emplace_back(worker);
  for (std::thread& thread : threads) thread.join();
  if (escaped) std::rethrow_exception(escaped);
  study.models_built = models.models_built() - study.reference_models_built;
  study.eigen_solves = modes.eigen_solves();
  return study;
}

}  // namespace ffrf::study
