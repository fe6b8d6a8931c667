// Convergence-checked nodal reference (see reference.hpp).
#include "study/reference.hpp"

#include <fmt/format.h>

#include <cmath>

#include "coupling/error_metrics.hpp"
#include "study/error_measure.hpp"

namespace ffrf::study {

void validate(const ReferenceOptions& o) {
  if (o.start_elements < 1) {
    throw SettingError(Setting::reference_elements, fmt::format("{}", o.start_elements),
                       "not a valid element count (valid range [1, inf))");
  }
  if (!(o.start_relative_tolerance > 0.0 && o.start_relative_tolerance < 1.0)) {
    throw SettingError(Setting::reference_tolerance, fmt::format("{}", o.start_relative_tolerance),
                       "not a valid tolerance (valid range (0, 1))");
  }
  if (!(o.bound > 0.0 && std::isfinite(o.bound))) {
    throw SettingError(Setting::reference_bound, fmt::format("{}", o.bound), "not a valid bound (valid range (0, inf))");
  }
  if (o.max_levels < 1 || o.max_levels > 6) {
    throw SettingError(Setting::reference_levels, fmt::format("{}", o.max_levels),
                       "not a valid level count (valid range [1, 6])");
  }
}

ConvergedReference converged_reference(const scene::Scene& scene, const ReferenceOptions& options, double duration,
                                       modal::ModeCache* modes) {
  validate(options);
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
    const coupling::IntegratorSettings settings = integrator_settings(scene, request);
    ModelRun run = run_model(scene, choice, settings, modes);
    ReferenceLevel record{choice.elements, settings.relative_tolerance, 0.0, run.result.stats};
    if (level > 0) {
      record.change = coupling::compare_runs(reference.run.result, run.result, reference.window_start).worst_normalized_rms();
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
