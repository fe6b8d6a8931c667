// Experiment 1 of the stability map: the largest stable explicit Runge–Kutta step per boom model,
// measured by trial runs against the theory (study/stability_explicit_map.hpp).
#include <fmt/format.h>

#include <algorithm>

#include "study/stability.hpp"

namespace ffrf::study {
namespace {

// --quick: four nodal meshes and three modal bases with static modes.
std::vector<scene::BoomChoice> quick_models(const scene::Scene& scene) {
  std::vector<scene::BoomChoice> models;
  for (int n : {1, 2, 4, 8}) models.push_back({scene::BoomKind::nodal, n});
  const int mesh = std::max(8, scene.boom.mesh.element_count);
  for (int k : {1, 2, 4}) models.push_back({scene::BoomKind::modal, mesh, k, true});
  return models;
}

}  // namespace

ExplicitStepStudy explicit_step_study(const scene::Scene& scene, const StabilityOptions& options) {
  ExplicitStepStudy study;
  study.quick = options.quick;
  if (options.quick) study.search.relative_precision = 0.1;
  const std::vector<scene::BoomChoice> models = options.quick ? quick_models(scene) : default_stability_models();
  if (options.progress) options.progress(fmt::format("explicit step limits: {} models", models.size()));
  study.map = explicit_stability_map(scene, models, study.search, [&](const ExplicitStabilityRow& row) {
    if (!options.progress) return;
    options.progress(row.ok() ? fmt::format("{:<26} h = {:.4g} s ({} trials, {:.2f} s)", row.label, row.measured.stable_step,
                                            row.measured.trials, row.wall_seconds)
                              : fmt::format("{:<26} {}", row.label, row.failure));
  });
  return study;
}

}  // namespace ffrf::study
