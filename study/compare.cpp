// The comparison of boom models against the converged reference (see compare.hpp).
#include "study/compare.hpp"

#include "study/recommend_reasoning.hpp"

namespace ffrf::study {

std::vector<ComparedModel> compared_models(const scene::Scene& scene) {
  using scene::BoomKind;
  std::vector<ComparedModel> models{
      {{BoomKind::rigid, 1}, true},
      {{BoomKind::nodal, 1}, true},  // the paper's one-element boom
      {{BoomKind::nodal, 16}, false},
  };
  for (const bool static_modes : {false, true}) {
    for (const int k : {1, 2, 4}) {
      models.push_back({{BoomKind::modal, 16, k, static_modes}, k == 2});
    }
  }
  // The mode set as an axis: the free-free set in the same tangent frame, and for a pinned boom the
  // chord frame's pinned-pinned set.
  std::vector<fem::Boundary> sets{fem::Boundary::free_free};
  if (scene.boom.mount && scene.boom.mount->pinned) sets.push_back(fem::Boundary::pinned_pinned);
  for (const fem::Boundary set : sets) {
    for (const bool static_modes : {false, true}) {
      for (const int k : {1, 2, 4}) {
        scene::BoomChoice choice{BoomKind::modal, 16, k, static_modes};
        choice.mode_set = set;
        models.push_back({choice, false});
      }
    }
  }
  return models;
}

Comparison compare(const scene::Scene& scene, const CompareRequest& request,
                   const std::function<void(const std::string&)>& progress, modal::ModeCache* modes) {
  const auto tell = [&](const std::string& what) {
    if (progress) progress(what);
  };
  modal::ModeCache own;
  modal::ModeCache& cache = modes != nullptr ? *modes : own;
  judge({}, 0.0, 0.0, request.tolerance);  // the tolerance is valid before anything runs
  Comparison c;
  c.settings = request.settings;
  c.stiffening_from_physics = !request.stiffening;
  c.stiffening = request.stiffening.value_or(physics_stiffening(scene, request.tolerance));
  scene::Scene modelled = scene;
  modelled.boom.stiffening = c.stiffening;
  scene::CraneModelCache models(modelled, &cache);  // nodal N = 16 is a reference level and a compared model: built once
  tell("reference");
  c.reference = converged_reference(models, request.reference, request.settings.duration);
  c.window_start = error_window(scene, request.settings.duration);
  c.judged = judged_outputs(scene);
  for (const ComparedModel& model : compared_models(scene)) {
    tell(model.choice.label());
    PreparedRun prepared = prepare_run(models, model.choice);
    c.runs.push_back(integrate_run(modelled, prepared, request.settings));
    c.plotted.push_back(model.plotted);
    c.errors.push_back(multibody::compare_runs(c.runs.back().result, c.reference.run.result, c.window_start));
    c.split.push_back(split_errors(c.runs.back(), c.reference.run, c.window_start));
    c.worst.push_back(worst_error(c.errors.back(), c.judged));
    c.stress.push_back(stress_recovery_errors(c.runs.back().result, c.reference.run.result, c.window_start));
    const ModelRun& done = c.runs.back();
    c.irregular.push_back(irregular_errors(scene, done.result.samples, done.statics.outputs, c.reference.run.result.samples,
                                           c.reference.run.statics.outputs, done.window.first,
                                           scene.simulation.output_interval));
  }
  c.verdict = judge(measured_models(c), c.reference.run.result.stats.wall_seconds, c.reference.run.work(), request.tolerance);
  // The chosen model is drawn on the charts beside the fixed set.
  if (c.verdict.cheapest) c.plotted[*c.verdict.cheapest] = true;
  return c;
}

std::vector<MeasuredModel> measured_models(const Comparison& c) {
  std::vector<MeasuredModel> models;
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    MeasuredModel model;
    model.label = c.runs[m].choice.label();
    model.error = c.worst[m].error;
    model.worst_output = std::string(multibody::channel_name(c.worst[m].channel));
    model.wall_seconds = c.runs[m].result.stats.wall_seconds;
    model.work = c.runs[m].work();
    models.push_back(std::move(model));
  }
  return models;
}

}  // namespace ffrf::study
