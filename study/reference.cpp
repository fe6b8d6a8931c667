// Convergence-checked nodal reference (see header).
#include "cases/reference_model.hpp"

#include <cmath>

#include "coupling/error_metrics.hpp"
#include "coupling/static_equilibrium.hpp"

namespace ffrf::cases {

double ramp_end(const Scene& scene) { return scene.wave ? scene.wave->ramp_periods * scene.wave->period : 0.0; }

ConvergedReference converged_reference(const Scene& scene, const ReferenceRequest& request) {
  ConvergedReference reference;
  reference.bound = request.bound;
  reference.window_start = ramp_end(scene);
  coupling::RunResult previous;
  for (int level = 0; level < request.max_levels; ++level) {
    BoomChoice choice;
    choice.kind = BoomKind::nodal;
    choice.elements = request.start_elements << level;
    coupling::IntegratorSettings settings;
    settings.kind = coupling::Integrator::cvode;
    settings.relative_tolerance = request.start_relative_tolerance * std::pow(0.1, level);
    settings.absolute_tolerance = settings.relative_tolerance;
    settings.duration = request.duration > 0.0 ? request.duration : scene.simulation.duration;
    settings.output_interval = scene.simulation.output_interval;
    auto equations = build_crane(scene, choice);
    const auto equilibrium = coupling::solve_static_equilibrium(*equations, equations->initial_guess());
    coupling::RunResult run = coupling::integrate(*equations, equilibrium.z, settings);
    ReferenceLevel record{choice.elements, settings.relative_tolerance, 0.0, run.stats};
    if (level > 0) record.change = coupling::compare_runs(previous, run, reference.window_start).worst_normalized_rms();
    reference.levels.push_back(record);
    reference.choice = choice;
    reference.settings = settings;
    previous = std::move(run);
    if (level > 0 && record.change < request.bound) {
      reference.converged = true;
      break;
    }
  }
  reference.run = std::move(previous);
  return reference;
}

}  // namespace ffrf::cases
