// Experiment 5 of the stability map: the BDF order on undamped stiff modes (hub scenes with an
// undamped boom). BDF 3–5 are not A-stable: their stability regions leave out a band along the
// imaginary axis, so an undamped stiff mode iω of the boom (whose error never decays) can be
// stepped over only with h small enough that hω lies in the region: the step size collapses to
// resolve the highest frequency. BDF 1–2 are A-stable and step over it. CVODE on the same run with
// max_order 5 and 2: steps, evaluations, wall time and their ratio.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "study/stability.hpp"

namespace ffrf::study {

BdfOrderStudy bdf_order_study(const scene::Scene& scene, const StabilityOptions& options) {
  BdfOrderStudy study;
  study.choice = {scene::BoomKind::nodal, scene.boom.mesh.element_count};
  DynamicsRequest request;
  request.duration = std::min(scene.simulation.duration, options.quick ? 2.0 : 10.0);
  study.duration = *request.duration;
  modal::ModeCache modes;
  for (int order : {2, 5}) {
    request.max_order = order;
    const multibody::RunSettings settings = integrator_settings(scene, request);
    study.relative_tolerance = settings.relative_tolerance;
    if (options.progress) {
      options.progress(fmt::format("BDF order: cvode max_order {} on {}, {} s", order, study.choice.label(), settings.duration));
    }
    OrderRun run{order, std::nullopt, std::nullopt};
    try {
      run.stats = run_model(scene, study.choice, settings, &modes).result.stats;
    } catch (const solve::SolverFailure& failure) {
      run.failure = failure.detection();
    }
    study.runs.push_back(run);
  }
  study.step_ratio = study.runs[0].stats && study.runs[1].stats
                         ? static_cast<double>(study.runs[1].stats->steps) / static_cast<double>(study.runs[0].stats->steps)
                         : NAN;
  return study;
}

}  // namespace ffrf::study
