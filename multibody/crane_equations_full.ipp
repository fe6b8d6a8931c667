// Crane equations, part 2: full coordinates q = (hull | cargo | boom R_B, θ_B, η) with the heel at
// B as constraints (paper eq. 31 plus, for a clamp, the orientation row of eq. 32):
//   C(q) = [r1 + A(θ1) b − R_B ; θ_B − θ1 − α] = 0   (a pin keeps the first two rows only),
//   C_q  = [[I, Ĩ A1 b, 0, −I, 0, 0], [0, −1, 0, 0, 1, 0]] over (r1, θ1, cargo, R_B, θ_B, η),
// with M(q) q̈ = Q − C_qᵀλ; the reaction on the boom at B is −C_q,Bᵀλ = (λ1, λ2, −λ3) (no moment
// through a pin).
// A held or driven base (r1, θ1 given functions of t) makes the heel a driving constraint:
//   C(q, t) = [r1(t) + A(θ1(t)) b − R_B ; θ_B − θ1(t) − α],  C_t = [ṙ1 + θ̇1 Ĩ A1 b ; −θ̇1],
//   C_tt = [r̈1 + θ̈1 Ĩ A1 b − θ̇1² A1 b ; −θ̈1],  and C_q (over R_B, θ_B only) is constant.
#pragma once

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::full_from_minimal(double t, ConstRef z, ConstRef z_dot, Ref q, Ref v) const {
  Eigen::Vector3d hull_q = base_pose(t), hull_v = base_velocity(t);
  if (hull_free()) {
    hull_q = z.segment<3>(layout_.hull);
    hull_v = z_dot.segment<3>(layout_.hull);
    q.segment<3>(layout_.hull) = hull_q;
    v.segment<3>(layout_.hull) = hull_v;
  }
  if (has_cargo()) {
    q.segment<3>(layout_.cargo) = z.segment<3>(layout_.cargo);
    v.segment<3>(layout_.cargo) = z_dot.segment<3>(layout_.cargo);
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

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::full_mass_times(ConstRef q, ConstRef a, Ref out) {
  const int b = layout_.frame;
  if (hull_free()) out.segment<3>(layout_.hull) = hull_rigid_inertia() * a.segment<3>(layout_.hull);
  if (has_cargo()) out.segment<3>(layout_.cargo) = cargo_inertia().cwiseProduct(a.segment<3>(layout_.cargo));
  boom_q_ = q.tail(3 + n_);
  m_.boom.mass_blocks(boom_q_, boom_reference_mass_, boom_coupling_, boom_work_);
  out.segment<3>(b) = boom_reference_mass_ * a.segment<3>(b) + boom_coupling_ * a.tail(n_);
  out.tail(n_).noalias() = m_.boom.coords().mass_ff() * a.tail(n_);
  out.tail(n_).noalias() += boom_coupling_.transpose() * a.segment<3>(b);
}

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::full_mass_matrix(ConstRef q, Eigen::MatrixXd& mass) {
  const int size = full_size(), b = layout_.frame;
  mass.setZero(size, size);
  if (hull_free()) mass.block<3, 3>(layout_.hull, layout_.hull) = hull_rigid_inertia();
  if (has_cargo()) mass.block<3, 3>(layout_.cargo, layout_.cargo) = cargo_inertia().asDiagonal();
  boom_q_ = q.tail(3 + n_);
  m_.boom.mass_blocks(boom_q_, boom_reference_mass_, boom_coupling_, boom_work_);
  mass.block<3, 3>(b, b) = boom_reference_mass_;
  mass.block(b, b + 3, 3, n_) = boom_coupling_;
  mass.block(b + 3, b, n_, 3) = boom_coupling_.transpose();
  mass.bottomRightCorner(n_, n_) = shared_->elastic_mass_dense;
}

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::full_forces(double t, ConstRef q, ConstRef v, Ref out) {
  set_full_state(t, q, v);
  evaluate_loads(t, true);
  if (hull_free()) out.segment<3>(layout_.hull) = hull_force_;
  if (has_cargo()) out.segment<3>(layout_.cargo) = cargo_force_;
  out.tail(3 + n_) = boom_force_;
}

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::constraint(double t, ConstRef q, Ref c) const {
  const Eigen::Vector3d hull_q = hull_free() ? Eigen::Vector3d(q.segment<3>(layout_.hull)) : base_pose(t);
  const int b = layout_.frame;
  c.head<2>() = hull_q.head<2>() + rotation(hull_q(2)) * m_.mount.root - q.segment<2>(b);
  if (clamped()) c(2) = q(b + 2) - hull_q(2) - m_.mount.angle;
}

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const {
  jacobian.setZero(constraint_count(), full_size());
  const int b = layout_.frame, h = layout_.hull;
  if (hull_free()) {
    jacobian.block<2, 2>(0, h).setIdentity();
    jacobian.block<2, 1>(0, h + 2) = perp(rotation(q(h + 2)) * m_.mount.root);
    if (clamped()) jacobian(2, h + 2) = -1.0;
  }
  jacobian.block<2, 2>(0, b) = -Eigen::Matrix2d::Identity();
  if (clamped()) jacobian(2, b + 2) = 1.0;
}

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::constraint_time_derivative(double t, Ref c_t) const {
  c_t.setZero();
  if (hull_free() || !m_.hull.prescribed) return;
  const Eigen::Vector3d pose = base_pose(t), rate = base_velocity(t);
  c_t.head<2>() = rate.head<2>() + rate(2) * perp(rotation(pose(2)) * m_.mount.root);
  if (clamped()) c_t(2) = -rate(2);
}

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::constraint_rate_terms(double t, ConstRef q, ConstRef v, Ref gamma) const {
  gamma.setZero();
  if (hull_free()) {
    const int h = layout_.hull;
    gamma.head<2>() = v(h + 2) * v(h + 2) * (rotation(q(h + 2)) * m_.mount.root);
  } else if (m_.hull.prescribed) {  // γ = −C_tt
    const Eigen::Vector3d pose = base_pose(t), rate = base_velocity(t), acc = base_acceleration(t);
    const Eigen::Vector2d arm = rotation(pose(2)) * m_.mount.root;
    gamma.head<2>() = -(acc.head<2>() + acc(2) * perp(arm) - rate(2) * rate(2) * arm);
    if (clamped()) gamma(2) = acc(2);
  }
}

template <fem::ElasticCoordinates Coords, bool Pinned>
void CraneEquationsOf<Coords, Pinned>::wire_stretches_full(double t, ConstRef q, Ref stretch) {
  set_full_state(t, q, q);  // (the velocities are not read)
  wire_stretches(stretch);
}

template <fem::ElasticCoordinates Coords, bool Pinned>
CraneOutputs CraneEquationsOf<Coords, Pinned>::full_outputs(double t, ConstRef q, ConstRef v, ConstRef lambda) {
  if (hull_free()) record_hull_velocity(t, v.segment<3>(layout_.hull));
  Eigen::VectorXd forces(full_size());
  full_forces(t, q, v, forces);
  CraneOutputs out = common_outputs();
  out.joint_reaction = Eigen::Vector3d(lambda(0), lambda(1), clamped() ? -lambda(2) : 0.0);
  out.root_axial_force = root_axial_force(out.joint_reaction, q(layout_.frame + 2));
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  constraint(t, q, c.head(constraint_count()));
  out.constraint_residual = c.head<2>().norm() + std::abs(c(2)) * m_.boom_tip.undeformed.x();
  if (m_.stress) {
    Eigen::VectorXd elastic_acceleration;
    const Eigen::Vector3d frame_acceleration = full_boom_accelerations(lambda, elastic_acceleration);
    add_boom_stress(frame_acceleration, elastic_acceleration, out);
  }
  return out;
}

}  // namespace ffrf::multibody::detail
