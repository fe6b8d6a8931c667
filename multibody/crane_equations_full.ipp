// Crane equations, part 2: full coordinates q = (hull | rigid bodies | boom R_B, θ_B, η) with the heel
// at B and the pinned bodies' pins as constraints (paper eq. 31 plus, for a clamp, the orientation row
// of eq. 32):
//   heel:   C = [r1 + A(θ1) b − R_B ; θ_B − θ1 − α] = 0   (a pin keeps the first two rows only),
//           C_q = [[I, Ĩ A1 b, −I, 0, 0], [0, −1, 0, 1, 0]] over (r1, θ1, R_B, θ_B, η),
//   a body pinned to the hull at p (hull frame), its own pivot s (body frame from G):
//           C = r1 + A(θ1) p − R_G − A(θ) s = 0,   C_q = [I, Ĩ A1 p, −I, −Ĩ A s] over (r1, θ1, R_G, θ),
// with M(q) q̈ = Q − C_qᵀλ; the reaction on the boom at B is −C_q,Bᵀλ = (λ1, λ2, −λ3) (no moment
// through a pin). The rate terms γ = C_q q̈ = −(C_q q̇)_q q̇: θ̇1² A1 b at the heel, θ̇1² A1 p − θ̇² A s
// at a pin.
// A held or driven base (r1, θ1 given functions of t) makes the heel a driving constraint:
//   C(q, t) = [r1(t) + A(θ1(t)) b − R_B ; θ_B − θ1(t) − α],  C_t = [ṙ1 + θ̇1 Ĩ A1 b ; −θ̇1],
//   C_tt = [r̈1 + θ̈1 Ĩ A1 b − θ̇1² A1 b ; −θ̈1],  and C_q (over R_B, θ_B only) is constant;
// a pin on it likewise (C_t = ṙ1 + θ̇1 Ĩ A1 p, C_tt = r̈1 + θ̈1 Ĩ A1 p − θ̇1² A1 p).
#pragma once

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::full_from_minimal(double t, ConstRef z, ConstRef z_dot, Ref q, Ref v) const {
  Eigen::Vector3d hull_q = base_pose(t), hull_v = base_velocity(t);
  if (hull_free()) {
    hull_q = z.segment<3>(layout_.hull);
    hull_v = z_dot.segment<3>(layout_.hull);
    q.segment<3>(layout_.hull) = hull_q;
    v.segment<3>(layout_.hull) = hull_v;
  }
  for (std::size_t i = 0; i < m_.bodies.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (block.pinned) {
      const RigidBodyModel& body = m_.bodies[i];
      const PinnedBodyMotion motion = pinned_body_motion(hull_q, hull_v, body.pivot_on_hull, body.pivot_on_body, body.angle,
                                                         z(block.minimal), z_dot(block.minimal));
      q.segment<3>(block.full) = motion.pose;
      v.segment<3>(block.full) = motion.velocity;
    } else {
      q.segment<3>(block.full) = z.segment<3>(block.minimal);
      v.segment<3>(block.full) = z_dot.segment<3>(block.minimal);
    }
  }
  const Eigen::Vector2d offset = rotation(hull_q(2)) * m_.mount.root;
  const int b = layout_.frame;
  q.segment<2>(b) = hull_q.head<2>() + offset;
  q(b + 2) = hull_q(2) + m_.mount.angle;
  v.segment<2>(b) = hull_v.head<2>() + hull_v(2) * perp(offset);
  v(b + 2) = hull_v(2);
  if (!clamped()) {
    q(b + 2) += z(layout_.heel);
    v(b + 2) += z_dot(layout_.heel);
  }
  q.tail(n_) = z.tail(n_);
  v.tail(n_) = z_dot.tail(n_);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::full_mass_times(ConstRef q, ConstRef a, Ref out) {
  const int b = layout_.frame;
  if (hull_free()) out.segment<3>(layout_.hull) = hull_rigid_inertia() * a.segment<3>(layout_.hull);
  for (std::size_t i = 0; i < m_.bodies.size(); ++i) {
    const int at = layout_.bodies[i].full;
    out.segment<3>(at) = body_inertia(static_cast<int>(i)).cwiseProduct(a.segment<3>(at));
  }
  boom_q_ = q.tail(3 + n_);
  m_.boom.mass_blocks(boom_q_, boom_reference_mass_, boom_coupling_, boom_work_);
  out.segment<3>(b) = boom_reference_mass_ * a.segment<3>(b) + boom_coupling_ * a.tail(n_);
  out.tail(n_).noalias() = m_.boom.coords().mass_ff() * a.tail(n_);
  out.tail(n_).noalias() += boom_coupling_.transpose() * a.segment<3>(b);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::full_mass_matrix(ConstRef q, Eigen::MatrixXd& mass) {
  const int size = full_size(), b = layout_.frame;
  mass.setZero(size, size);
  if (hull_free()) mass.block<3, 3>(layout_.hull, layout_.hull) = hull_rigid_inertia();
  for (std::size_t i = 0; i < m_.bodies.size(); ++i) {
    const int at = layout_.bodies[i].full;
    mass.block<3, 3>(at, at) = body_inertia(static_cast<int>(i)).asDiagonal();
  }
  boom_q_ = q.tail(3 + n_);
  m_.boom.mass_blocks(boom_q_, boom_reference_mass_, boom_coupling_, boom_work_);
  mass.block<3, 3>(b, b) = boom_reference_mass_;
  mass.block(b, b + 3, 3, n_) = boom_coupling_;
  mass.block(b + 3, b, n_, 3) = boom_coupling_.transpose();
  mass.bottomRightCorner(n_, n_) = shared_->elastic_mass_dense;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::full_forces(double t, ConstRef q, ConstRef v, Ref out) {
  set_full_state(t, q, v);
  evaluate_loads(t, true);
  if (hull_free()) out.segment<3>(layout_.hull) = hull_force_;
  for (std::size_t i = 0; i < m_.bodies.size(); ++i) out.segment<3>(layout_.bodies[i].full) = body_forces_[i];
  out.tail(3 + n_) = boom_force_;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::constraint(double t, ConstRef q, Ref c) const {
  const Eigen::Vector3d hull_q = hull_free() ? Eigen::Vector3d(q.segment<3>(layout_.hull)) : base_pose(t);
  const Eigen::Matrix2d hull_rotation = rotation(hull_q(2));
  const int b = layout_.frame;
  c.head<2>() = hull_q.head<2>() + hull_rotation * m_.mount.root - q.segment<2>(b);
  if (clamped()) c(2) = q(b + 2) - hull_q(2) - m_.mount.angle;
  for (std::size_t i = 0; i < m_.bodies.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (!block.pinned) continue;
    const RigidBodyModel& body = m_.bodies[i];
    c.segment<2>(block.constraint) = hull_q.head<2>() + hull_rotation * body.pivot_on_hull - q.segment<2>(block.full) -
                                     rotation(q(block.full + 2)) * body.pivot_on_body;
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const {
  jacobian.setZero(constraint_count(), full_size());
  const int b = layout_.frame, h = layout_.hull;
  if (hull_free()) {
    jacobian.block<2, 2>(0, h).setIdentity();
    jacobian.block<2, 1>(0, h + 2) = perp(rotation(q(h + 2)) * m_.mount.root);
    if (clamped()) jacobian(2, h + 2) = -1.0;
  }
  jacobian.block<2, 2>(0, b) = -Eigen::Matrix2d::Identity();
  if (clamped()) jacobian(2, b + 2) = 1.0;
  for (std::size_t i = 0; i < m_.bodies.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (!block.pinned) continue;
    const RigidBodyModel& body = m_.bodies[i];
    const int row = block.constraint;
    if (hull_free()) {
      jacobian.block<2, 2>(row, h).setIdentity();
      jacobian.block<2, 1>(row, h + 2) = perp(rotation(q(h + 2)) * body.pivot_on_hull);
    }
    jacobian.block<2, 2>(row, block.full) = -Eigen::Matrix2d::Identity();
    jacobian.block<2, 1>(row, block.full + 2) = -perp(rotation(q(block.full + 2)) * body.pivot_on_body);
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::constraint_time_derivative(double t, Ref c_t) const {
  c_t.setZero();
  if (hull_free() || !m_.hull.prescribed) return;
  const Eigen::Vector3d pose = base_pose(t), rate = base_velocity(t);
  const Eigen::Matrix2d hull_rotation = rotation(pose(2));
  c_t.head<2>() = rate.head<2>() + rate(2) * perp(hull_rotation * m_.mount.root);
  if (clamped()) c_t(2) = -rate(2);
  for (std::size_t i = 0; i < m_.bodies.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (block.pinned) c_t.segment<2>(block.constraint) = rate.head<2>() + rate(2) * perp(hull_rotation * m_.bodies[i].pivot_on_hull);
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::constraint_rate_terms(double t, ConstRef q, ConstRef v, Ref gamma) const {
  gamma.setZero();
  Eigen::Vector3d pose = Eigen::Vector3d::Zero(), rate = Eigen::Vector3d::Zero(), acc = Eigen::Vector3d::Zero();
  if (hull_free()) {
    const int h = layout_.hull;
    pose = q.segment<3>(h);
    rate = v.segment<3>(h);
    gamma.head<2>() = v(h + 2) * v(h + 2) * (rotation(q(h + 2)) * m_.mount.root);
  } else if (m_.hull.prescribed) {  // γ = −C_tt
    pose = base_pose(t);
    rate = base_velocity(t);
    acc = base_acceleration(t);
    const Eigen::Vector2d arm = rotation(pose(2)) * m_.mount.root;
    gamma.head<2>() = -(acc.head<2>() + acc(2) * perp(arm) - rate(2) * rate(2) * arm);
    if (clamped()) gamma(2) = acc(2);
  } else {
    pose = base_pose(t);
  }
  for (std::size_t i = 0; i < m_.bodies.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (!block.pinned) continue;
    const double body_rate = v(block.full + 2);
    const Eigen::Vector2d hull_arm = rotation(pose(2)) * m_.bodies[i].pivot_on_hull;
    const Eigen::Vector2d body_arm = rotation(q(block.full + 2)) * m_.bodies[i].pivot_on_body;
    Eigen::Vector2d terms = -body_rate * body_rate * body_arm;
    if (hull_free()) {
      terms += rate(2) * rate(2) * hull_arm;
    } else if (m_.hull.prescribed) {
      terms -= acc.head<2>() + acc(2) * perp(hull_arm) - rate(2) * rate(2) * hull_arm;
    }
    gamma.segment<2>(block.constraint) = terms;
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::wire_stretches_full(double t, ConstRef q, Ref stretch) {
  set_full_state(t, q, q);  // (the velocities are not read)
  wire_stretches(stretch);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
CraneOutputs CraneEquationsOf<Coords, Articulated>::full_outputs(double t, ConstRef q, ConstRef v, ConstRef lambda) {
  if (hull_free()) record_hull_velocity(t, v.segment<3>(layout_.hull));
  Eigen::VectorXd forces(full_size());
  full_forces(t, q, v, forces);
  CraneOutputs out = common_outputs();
  out.joint_reaction = Eigen::Vector3d(lambda(0), lambda(1), clamped() ? -lambda(2) : 0.0);
  out.root_axial_force = root_axial_force(out.joint_reaction, q(layout_.frame + 2));
  ConstraintVector c = ConstraintVector::Zero(constraint_count());
  constraint(t, q, c);
  out.constraint_residual = c.head<2>().norm() + (clamped() ? std::abs(c(2)) * m_.boom_tip.undeformed.x() : 0.0);
  for (const BodyBlock& block : layout_.bodies) {
    if (block.pinned) out.constraint_residual += c.segment<2>(block.constraint).norm();
  }
  if (m_.stress) {
    Eigen::VectorXd elastic_acceleration;
    const Eigen::Vector3d frame_acceleration = full_boom_accelerations(lambda, elastic_acceleration);
    add_boom_stress(frame_acceleration, elastic_acceleration, out);
  }
  return out;
}

}  // namespace ffrf::multibody::detail
