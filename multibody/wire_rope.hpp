// The wire rope from the boom tip A′ to the hook C: an axial spring–damper that carries tension
// only: T = max(0, k (ℓ − L0) + c ℓ̇) while ℓ > L0, T = 0 when slack (ℓ ≤ L0).
#pragma once

#include <Eigen/Dense>

#include "multibody/crane_parameters.hpp"

namespace ffrf::multibody {

struct WireState {
  double length = 0.0;       // ℓ [m]
  double length_rate = 0.0;  // ℓ̇ [m/s]
  double tension = 0.0;      // T [N]
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // unit vector from A′ to C
};

// bilateral = true drops the tension-only switch (used by the static equilibrium's Newton
// iteration, whose trial points may pass through a slack wire; a hanging cargo keeps it taut).
inline WireState wire_state(const WireModel& wire, const Eigen::Vector2d& tip, const Eigen::Vector2d& tip_velocity,
                            const Eigen::Vector2d& hook, const Eigen::Vector2d& hook_velocity, bool bilateral = false) {
  WireState s;
  const Eigen::Vector2d d = hook - tip;
  s.length = d.norm();
  s.direction = d / s.length;
  s.length_rate = s.direction.dot(hook_velocity - tip_velocity);
  if (bilateral) {
    s.tension = wire.stiffness * (s.length - wire.unstretched_length) + wire.damping * s.length_rate;
  } else if (s.length > wire.unstretched_length) {
    const double t = wire.stiffness * (s.length - wire.unstretched_length) + wire.damping * s.length_rate;
    s.tension = t > 0.0 ? t : 0.0;
  }
  return s;
}

// Elastic energy stored in the rope [J].
inline double wire_energy(const WireModel& wire, double length) {
  const double stretch = length - wire.unstretched_length;
  return stretch > 0.0 ? 0.5 * wire.stiffness * stretch * stretch : 0.0;
}

}  // namespace ffrf::multibody
