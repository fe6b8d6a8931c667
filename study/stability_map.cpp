// The experiments of the stability map that apply to a scene (see stability.hpp).
#include <chrono>

#include "study/stability.hpp"
#include "study/wall_clock.hpp"

namespace ffrf::study {

StabilityMap stability_map(const scene::Scene& scene, const StabilityOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  StabilityMap map;
  map.explicit_steps = explicit_step_study(scene, options);
  map.drift = constraint_drift_study(scene, options);
  if (scene.hub && scene.hub->motion != scene::HubMotion::fixed && scene.hub->spin_rate != 0.0) {
    map.spin = spin_study(scene, options);
  }
  if (scene.has_cargo()) map.wire = wire_study(scene, options);
  if (scene.hub && scene.boom.damping_ratio == 0.0) map.bdf_order = bdf_order_study(scene, options);
  if (scene.has_cargo() && scene.environment.gravity > 0.0) map.buckling = buckling_study(scene, options);
  map.wall_seconds = seconds_since(start);
  return map;
}

}  // namespace ffrf::study
