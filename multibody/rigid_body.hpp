// A rigid planar body's points and point forces (the hull and the cargo): a point fixed in the body
// at p (body frame) is at r = R + A(θ) p with velocity Ṙ + θ̇ Ĩ A p; a force F there adds (F, (A p) × F)
// to the body's generalized force over (R, θ) (virtual work, Shabana 2005 §3).
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

}  // namespace ffrf::multibody
