// Experiment 4 of the stability map: the slack wire and its snap loads (scenes with a cargo). The
// cargo is raised by simulation.cargo_lift (1 m when the scene has none) and released at rest: the
// wire goes slack, the cargo falls freely and the wire snaps taut. For a rigid boom and an undamped
// wire the snap peak follows by hand (docs/stability.md): with s = mg/k the static stretch,
// ω = √(k/m) and d the lift, the cargo meets the taut wire at speed √(2g(d − s)) and swings to the
// amplitude A = √(s² + 2g(d − s)/ω²) about the static stretch: peak tension k(s + A).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "study/stability.hpp"

namespace ffrf::study {

WireStudy wire_study(const scene::Scene& scene, const StabilityOptions& options) {
  WireStudy study;
  scene::Scene lifted = scene;
  study.lift_from_scene = scene.simulation.cargo_lift > 0.0;
  if (!study.lift_from_scene) lifted.simulation.cargo_lift = 1.0;
  study.lift = lifted.simulation.cargo_lift;
  DynamicsRequest request;
  request.duration = std::min(scene.simulation.duration, options.quick ? 3.0 : 20.0);
  study.settings = integrator_settings(lifted, request);
  const int elements = scene.boom.mesh.element_count;
  study.runs = {{{scene::BoomKind::rigid, elements}, {}, {}, {}, {}}, {{scene::BoomKind::nodal, elements}, {}, {}, {}, {}}};
  for (WireRun& wire : study.runs) {
    if (options.progress) {
      options.progress(fmt::format("wire: cargo lifted {} m, {}, {} s", study.lift, wire.choice.label(), study.settings.duration));
    }
    try {
      wire.run = run_model(lifted, wire.choice, study.settings);
      wire.slack = wire.run->slack_intervals;  // judged by the run's own limits (its static tension added)
      wire.snaps = wire.run->snap_loads;
    } catch (const solve::SolverFailure& failure) {
      wire.failure = failure.detection();
    }
  }
  // The hand result (rigid boom, undamped wire, hook above G2).
  study.mass = scene.cargo->mass;
  study.stiffness = scene.wire->stiffness;
  study.gravity = scene.environment.gravity;
  study.static_stretch = study.mass * study.gravity / study.stiffness;
  study.omega = std::sqrt(study.stiffness / study.mass);
  study.amplitude = std::sqrt(study.static_stretch * study.static_stretch +
                              2.0 * study.gravity * (study.lift - study.static_stretch) / (study.omega * study.omega));
  study.hand_peak = study.stiffness * (study.static_stretch + study.amplitude);
  return study;
}

}  // namespace ffrf::study
