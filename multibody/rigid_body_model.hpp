// The crane's rigid bodies beside the hull and the boom, as a list (CraneParameters::bodies): the
// cargo, an A-frame, a second load. Each is its mass and its rotary inertia about its centre of mass
// G — the origin of its body frame, so that its mass matrix over (x_G, θ) is diagonal — and how it is
// held:
//  * free: its pose (x, y, θ of G) is three coordinates of its own (the cargo on its hoist wire);
//  * pinned to the hull: it turns about a pivot fixed on the hull (a revolute joint), its angle γ
//    relative to the hull its one coordinate (the A-frame on its deck pin). Its pose then follows from
//    the hull's: R_G = r1 + A(θ1) p − A(θ) s, θ = θ1 + α + γ, with p the pivot on the hull (hull frame at
//    G1), s the pivot in the body frame (from G) and α the body's angle on the hull at γ = 0
//    (multibody/rigid_body.hpp: pinned_body_motion).
// The types come from the model's space (linalg/space.hpp); a pin is a hinge with one angle in either
// space (its axis the plane's normal in the planar one).
#pragma once

#include <string>

#include "linalg/space.hpp"

namespace ffrf::multibody {

enum class RigidMount { free, pinned_to_hull };

template <linalg::Space S>
struct RigidBodyOf {
  std::string name;                          // "cargo", "A-frame": for messages and residual rows
  double mass = 0.0;                         // [kg]
  typename S::RotaryInertia rotary_inertia{};  // about G [kg m²]
  RigidMount mount = RigidMount::free;
  // free: the pose (G, θ) a static solve starts from, in the global frame (the cargo's guess is made
  // from its hoist wire instead: multibody/crane_equations_minimal.ipp).
  typename S::Pose initial_pose = S::Pose::Zero();
  // pinned to the hull: the pivot on the hull (hull frame, from G1), the pivot in the body frame (from
  // G) and the body frame's angle relative to the hull's at γ = 0 [rad].
  typename S::Vector pivot_on_hull = S::Vector::Zero();
  typename S::Vector pivot_on_body = S::Vector::Zero();
  double angle = 0.0;

  bool pinned() const { return mount == RigidMount::pinned_to_hull; }
  // Its coordinates in the minimal set: a free body's pose, a pinned body's angle.
  int minimal_dofs() const { return pinned() ? 1 : S::body_dofs; }
  // Its rotary inertia about the pivot (a pinned body's: I_G + m |s|²).
  double inertia_about_pivot() const { return rotary_inertia + mass * pivot_on_body.squaredNorm(); }
};

using RigidBodyModel = RigidBodyOf<linalg::Planar>;

}  // namespace ffrf::multibody
