// A driving constraint on the base body (hub or hull): its pose (x, y, θ) is a given function of
// time instead of a degree of freedom. The position is held; the rotation follows one of
//   fixed:          θ(t) = θ0,
//   constant spin:  θ(t) = θ0 + Ωs t (the base starts turning at t = 0 with the boom at rest in its frame),
//   spin-up:        θ(t) = θ0 + (Ωs/Ts)[t²/2 + (Ts/2π)²(cos(2πt/Ts) − 1)] for t < Ts, θ0 + Ωs(t − Ts/2) after
//                   (Simo & Vu-Quoc 1986, the spin-up benchmark: θ̇ rises smoothly from 0 to Ωs with
//                   θ̈ = (Ωs/Ts)(1 − cos 2πt/Ts), continuous at Ts).
// Pose, velocity and acceleration are exact derivatives of one another (tested by finite differences).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

namespace ffrf::multibody {

enum class RotationProfile { fixed, constant_spin, spin_up };

struct PrescribedMotion {
  Eigen::Vector3d pose0 = Eigen::Vector3d::Zero();  // (x, y, θ) at t = 0
  RotationProfile profile = RotationProfile::fixed;
  double spin_rate = 0.0;     // Ωs [rad/s]
  double spin_up_time = 1.0;  // Ts [s]

  Eigen::Vector3d pose(double t) const { return pose0 + Eigen::Vector3d(0.0, 0.0, angle_change(t)); }
  Eigen::Vector3d velocity(double t) const { return {0.0, 0.0, rate(t)}; }
  Eigen::Vector3d acceleration(double t) const { return {0.0, 0.0, angular_acceleration(t)}; }

  double angle_change(double t) const {
    switch (profile) {
      case RotationProfile::fixed: return 0.0;
      case RotationProfile::constant_spin: return spin_rate * t;
      case RotationProfile::spin_up: {
        const double ts = spin_up_time;
        if (t >= ts) return spin_rate * (t - 0.5 * ts);
        const double c = ts / (2.0 * std::numbers::pi);
        return spin_rate / ts * (0.5 * t * t + c * c * (std::cos(t / c) - 1.0));
      }
    }
    return 0.0;
  }
  double rate(double t) const {
    switch (profile) {
      case RotationProfile::fixed: return 0.0;
      case RotationProfile::constant_spin: return spin_rate;
      case RotationProfile::spin_up: {
        const double ts = spin_up_time;
        if (t >= ts) return spin_rate;
        const double c = ts / (2.0 * std::numbers::pi);
        return spin_rate / ts * (t - c * std::sin(t / c));
      }
    }
    return 0.0;
  }
  double angular_acceleration(double t) const {
    if (profile != RotationProfile::spin_up || t >= spin_up_time) return 0.0;
    const double c = spin_up_time / (2.0 * std::numbers::pi);
    return spin_rate / spin_up_time * (1.0 - std::cos(t / c));
  }
};

}  // namespace ffrf::multibody
