// Crane equations, the rigid bodies' part: the rigid block of the minimal coordinates — the hull's
// pose, the angles of the bodies pinned to it, the pinned heel's angle (multibody/crane_layout.hpp) —
// its values, its own inertia, and the pinned bodies' share of its mass and forces. A body pinned to the
// hull moves with the velocity transformation J_b over the rigid block (multibody/rigid_body.hpp):
//   J_b = [[I₂, Ĩ (l_h − l_b), −Ĩ l_b], [0 0, 1, 1]]  over (r1, θ1 | γ)   (no hull columns when it is held),
// with a known acceleration a₀_b = (−θ̇1² l_h + θ̇² l_b, 0) plus, on a driven base,
// (r̈1 + θ̈1 Ĩ (l_h − l_b), θ̈1). Its diagonal mass M_b = diag(m, m, I_G) and its loads F_b (weight, wires)
// enter the rigid rows as J_bᵀ M_b J_b and J_bᵀ (F_b − M_b a₀_b) (Shabana 2005 §6, as the boom frame's).
#pragma once

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::mount_pinned_body(int body, double gamma, double gamma_rate) {
  const RigidBodyModel& b = m_.bodies[body];
  bodies_[body] = pinned_body_motion(hull_q_, hull_v_, b.pivot_on_hull, b.pivot_on_body, b.angle, gamma, gamma_rate);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
typename CraneEquationsOf<Coords, Articulated>::RigidMatrix CraneEquationsOf<Coords, Articulated>::rigid_inertia() const {
  if constexpr (Articulated) {
    RigidMatrix inertia = RigidMatrix::Zero(layout_.rigid_size(), layout_.rigid_size());
    if (hull_free()) inertia.template topLeftCorner<3, 3>() = hull_rigid_inertia();
    return inertia;
  } else {
    return hull_rigid_inertia();
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
typename CraneEquationsOf<Coords, Articulated>::RigidMatrix CraneEquationsOf<Coords, Articulated>::rigid_mass() const {
  RigidMatrix mass = rigid_inertia() + frame_jacobian_.transpose() * boom_reference_mass_ * frame_jacobian_;
  if constexpr (Articulated) {
    if (has_pinned_bodies()) mass += pinned_mass_;
  }
  return mass;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
typename CraneEquationsOf<Coords, Articulated>::RigidVector CraneEquationsOf<Coords, Articulated>::rigid_part(ConstRef z) const {
  RigidVector rigid;
  if constexpr (Articulated) {
    rigid.resize(layout_.rigid_size());
    for (int i = 0; i < rigid.size(); ++i) rigid(i) = z(layout_.rigid_coordinates[i]);
  } else {
    if (hull_free()) rigid = z.segment<3>(layout_.hull);
  }
  return rigid;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::scatter_rigid(const RigidVector& rigid, Ref z) const {
  if constexpr (Articulated) {
    for (int i = 0; i < rigid.size(); ++i) z(layout_.rigid_coordinates[i]) = rigid(i);
  } else {
    if (hull_free()) z.segment<3>(layout_.hull) = rigid;
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
typename CraneEquationsOf<Coords, Articulated>::BodyJacobian CraneEquationsOf<Coords, Articulated>::pinned_body_jacobian(int body) const {
  const PinnedBodyMotion& motion = bodies_[body];
  BodyJacobian jacobian = BodyJacobian::Zero(3, layout_.rigid_size());
  if (hull_free()) {
    jacobian.template leftCols<3>().setIdentity();
    jacobian.template block<2, 1>(0, 2) = perp(motion.hull_lever - motion.body_lever);
  }
  const int column = layout_.bodies[body].rigid;
  jacobian.template block<2, 1>(0, column) = -perp(motion.body_lever);
  jacobian(2, column) = 1.0;
  return jacobian;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::add_pinned_bodies(double t, const std::vector<Eigen::Vector3d>& forces, RigidVector& rigid,
                                                              bool with_mass) {
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!layout_.bodies[i].pinned) continue;
    const int body = static_cast<int>(i);
    const BodyJacobian jacobian = pinned_body_jacobian(body);
    Eigen::Vector3d load = forces[i];
    if (with_mass) {
      const PinnedBodyMotion& motion = bodies_[i];
      Eigen::Vector3d known = Eigen::Vector3d::Zero();
      known.head<2>() = -hull_v_(2) * hull_v_(2) * motion.hull_lever + motion.velocity(2) * motion.velocity(2) * motion.body_lever;
      if (m_.hull.prescribed) {
        const Eigen::Vector3d base_a = base_acceleration(t);
        known.head<2>() += base_a.head<2>() + base_a(2) * perp(motion.hull_lever - motion.body_lever);
        known(2) = base_a(2);
      }
      const Eigen::Vector3d inertia = body_inertia(body);
      load -= inertia.cwiseProduct(known);
      // (coefficient-wise products: these blocks are at most 6 × 3, and Eigen's blocked matrix product
      // would be instantiated for them in this translation unit for nothing)
      pinned_mass_.noalias() += (jacobian.transpose() * inertia.asDiagonal()).lazyProduct(jacobian);
    }
    rigid.noalias() += jacobian.transpose().lazyProduct(load);
  }
}

}  // namespace ffrf::multibody::detail
