// Convergence-checked nodal reference (see reference.hpp).
#include "study/reference.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "multibody/error_metrics.hpp"
#include "study/error_measure.hpp"
#include "study/work_limits.hpp"

namespace ffrf::study {

void validate(const ReferenceOptions& o) {
  if (o.max_levels < 1 || o.max_levels > 6) {
    throw SettingError(Setting::reference_levels, fmt::format("{}", o.max_levels),
                       "not a valid level count (valid range [1, 6])");
  }
  // The finest level (N0·2^(levels−1) elements, rtol0·10^−(levels−1)) within the work limits.
  const int doubling = 1 << (o.max_levels - 1);
  const int max_start = std::max(1, max_nodal_elements() / doubling);
  if (o.start_elements < 1 || o.start_elements > max_start) {
    throw SettingError(Setting::reference_elements, fmt::format("{}", o.start_elements),
                       fmt::format("not a valid element count for {} levels (valid range [1, {}]: the finest level's "
                                   "{}·{} elements within the memory limit)",
                                   o.max_levels, max_start, max_start, doubling));
  }
  const double finest = std::pow(0.1, o.max_levels - 1);
  if (!(o.start_relative_tolerance >= min_tolerance / finest && o.start_relative_tolerance <= max_tolerance)) {
    throw SettingError(Setting::reference_tolerance, fmt::format("{}", o.start_relative_tolerance),
                       fmt::format("not a valid tolerance for {} levels (valid range [{:g}, {:g}]: the finest level "
                                   "divides it by {:g})",
                                   o.max_levels, min_tolerance / finest, max_tolerance, 1.0 / finest));
  }
  if (!(o.bound > 0.0 && o.bound < 1.0)) {
    throw SettingError(Setting::reference_bound, fmt::format("{}", o.bound), "not a valid bound (valid range (0, 1))");
  }
}

ConvergedReference converged_reference(const scene::Scene& scene, const ReferenceOptions& options, double duration,
                                       modal::ModeCache* modes) {
  scene::CraneModelCache models(scene, modes);
  return converged_reference(models, options, duration);
}

ConvergedReference converged_reference(scene::CraneModelCache& models, const ReferenceOptions& options, double duration) {
  validate(options);
  const scene::Scene& scene = models.scene();
  ConvergedReference reference;
  reference.bound = options.bound;
  reference.window_start = error_window(scene, duration);
  const int levels = reference.window_start > 0.0 || ramp_end(scene) == 0.0 ? options.max_levels : 1;
  for (int level = 0; level < levels; ++level) {
    scene::BoomChoice choice;
    choice.kind = scene::BoomKind::nodal;
    choice.elements = options.start_elements << level;
    DynamicsRequest request;
    request.relative_tolerance = request.absolute_tolerance = options.start_relative_tolerance * std::pow(0.1, level);
    request.duration = duration;
    const multibody::RunSettings settings = integrator_settings(scene, request);
    PreparedRun prepared = prepare_run(models, choice);
    ModelRun run = integrate_run(scene, prepared, settings);
    ReferenceLevel record{choice.elements, settings.relative_tolerance, 0.0, run.result.stats};
    if (level > 0) {
      record.change = convergence_change(scene, multibody::compare_runs(reference.run.result, run.result, reference.window_start));
    }
    reference.levels.push_back(record);
    reference.choice = choice;
    reference.settings = settings;
    reference.run = std::move(run);
    if (level > 0 && record.change < options.bound) {
      reference.converged = true;
      break;
    }
  }
  return reference;
}

}  // namespace ffrf::study
