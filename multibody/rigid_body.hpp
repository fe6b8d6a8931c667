// A rigid planar body's points and point forces (the hull, the cargo, an A-frame): a point fixed in the
// body at p (body frame) is at r = R + A(θ) p with velocity Ṙ + θ̇ Ĩ A p; a force F there adds
// (F, (A p) × F) to the body's generalized force over (R, θ) (virtual work, Shabana 2005 §3).
// A body pinned to the hull (multibody/rigid_body_model.hpp) has its pose from the hull's and its angle
// γ: with the levers l_h = A(θ1) p (pivot from G1) and l_b = A(θ) s (pivot from G),
//   R_G = r1 + l_h − l_b,  θ = θ1 + α + γ,
//   Ṙ_G = ṙ1 + θ̇1 Ĩ l_h − θ̇ Ĩ l_b,  θ̇ = θ̇1 + γ̇,
// so its velocity transformation over (r1, θ1, γ) is
//   J = [[I₂, Ĩ (l_h − l_b), −Ĩ l_b], [0 0, 1, 1]]
// and its acceleration J z̈ + a₀ with the velocity-product part a₀ = (−θ̇1² l_h + θ̇² l_b, 0)
// (d/dt Ĩ A = −A θ̇ for a planar rotation, Ĩ Ĩ = −I).
#pragma once

#include <Eigen/Dense>

#include "multibody/planar.hpp"

namespace ffrf::multibody {

// A point's motion with its lever A(θ) p from the reference point.
struct RigidPointMotion {
  Eigen::Vector2d lever, position, velocity;
};

inline RigidPointMotion rigid_point_motion(const Eigen::Vector3d& pose, const Eigen::Vector3d& rate, const Eigen::Vector2d& point) {
  RigidPointMotion m;
  m.lever = rotation(pose(2)) * point;
  m.position = pose.head<2>() + m.lever;
  m.velocity = rate.head<2>() + rate(2) * perp(m.lever);
  return m;
}

inline void add_rigid_point_force(const RigidPointMotion& m, const Eigen::Vector2d& force, Eigen::Vector3d& generalized) {
  generalized.head<2>() += force;
  generalized(2) += cross(m.lever, force);
}

// A pinned body's pose and velocity (of G) from the hull's pose and velocity and its angle γ, γ̇, with
// the two levers: hull_lever = A(θ1) p, body_lever = A(θ) s.
struct PinnedBodyMotion {
  Eigen::Vector3d pose, velocity;
  Eigen::Vector2d hull_lever, body_lever;
};

inline PinnedBodyMotion pinned_body_motion(const Eigen::Vector3d& hull_pose, const Eigen::Vector3d& hull_rate,
                                           const Eigen::Vector2d& pivot_on_hull, const Eigen::Vector2d& pivot_on_body,
                                           double angle, double gamma, double gamma_rate) {
  PinnedBodyMotion m;
  m.pose(2) = hull_pose(2) + angle + gamma;
  m.velocity(2) = hull_rate(2) + gamma_rate;
  m.hull_lever = rotation(hull_pose(2)) * pivot_on_hull;
  m.body_lever = rotation(m.pose(2)) * pivot_on_body;
  m.pose.head<2>() = hull_pose.head<2>() + m.hull_lever - m.body_lever;
  m.velocity.head<2>() = hull_rate.head<2>() + hull_rate(2) * perp(m.hull_lever) - m.velocity(2) * perp(m.body_lever);
  return m;
}

}  // namespace ffrf::multibody
