// Crane equations, part 1: loads on the bodies and the minimal-coordinate ODE.
// Velocity transformation of the clamp at B: Ṙ_B = ṙ1 + θ̇1 Ĩ A1 b, θ̇_B = θ̇1, so with
// J_r = [[1, 0, −(A1 b)_y], [0, 1, (A1 b)_x], [0, 0, 1]] and J̇ż = (−θ̇1² A1 b, 0):
//   hull rows:    (M_h + J_rᵀ M_RR J_r) z̈_h + J_rᵀ M_Rf η̈ = Q_h + J_rᵀ (Q_B,ref − M_B,ref,R J̇ż)
//   elastic rows: M_fR J_r z̈_h + M_ff η̈ = Q_B,f − M_fR,R J̇ż
// solved by the Schur complement of the constant M_ff (factored once). A held or driven base has no
// hull rows: its prescribed acceleration joins J̇ż as the known frame acceleration. Without a cargo
// the cargo rows are absent.
#pragma once

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords>
CraneEquationsOf<Coords>::CraneEquationsOf(std::shared_ptr<const CraneModelOf<Coords>> shared)
    : shared_(std::move(shared)),
      m_(shared_->model),
      n_(shared_->n),
      cargo_at_(shared_->cargo_at),
      elastic_at_(shared_->elastic_at),
      boom_work_(m_.boom.workspace()),
      boom_q_(3 + n_), boom_v_(3 + n_), boom_force_(3 + n_), elastic_rhs_(n_), schur_rhs_column_(n_),
      boom_coupling_(3, n_), hull_elastic_mass_(3, n_), schur_columns_(n_, 3), schur_rhs_(n_),
      radiation_(m_.hull.radiation_memory), boom_a_(3 + n_), wire_boom_force_(3 + n_) {
  pair_rhs_.resize(n_, 2);
  pair_solution_.resize(n_, 2);
  frame_columns_.resize(n_, 3);
  for (Eigen::VectorXd* v : {&jacobian_base_, &jacobian_shifted_, &jacobian_x_, &jacobian_x_dot_}) {
    v->resize(std::max(minimal_size(), full_size()));
  }
  full_inertia_.resize(full_size());
}

template <fem::ElasticCoordinates Coords>
Eigen::Matrix3d CraneEquationsOf<Coords>::hull_rigid_inertia() const {
  Eigen::Matrix3d inertia = (Eigen::Vector3d(m_.hull.mass, m_.hull.mass, m_.hull.pitch_inertia) + m_.hull.added_mass).asDiagonal();
  if (radiation_.active()) inertia += radiation_.added_mass();
  return inertia;
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::mount_boom(const Eigen::Vector3d& hull_q, const Eigen::Vector3d& hull_v) {
  mount_offset_ = rotation(hull_q(2)) * m_.mount.root;
  boom_q_.head<2>() = hull_q.head<2>() + mount_offset_;
  boom_q_(2) = hull_q(2) + m_.mount.angle;
  boom_v_.head<2>() = hull_v.head<2>() + hull_v(2) * perp(mount_offset_);
  boom_v_(2) = hull_v(2);
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::evaluate_loads(double t, const Eigen::Vector3d& hull_q, const Eigen::Vector3d& hull_v,
                                         const Eigen::Vector3d& cargo_q, const Eigen::Vector3d& cargo_v, bool with_wave) {
  const double g = m_.gravity;
  const HullModel& hull = m_.hull;
  hull_force_ = Eigen::Vector3d(0.0, -hull.mass * g, 0.0);
  // Froude–Krylov has one owner: the pressure of the incident wave, or the BEM excitation.
  if (hull.hydrostatics) {
    const sea::WaveField* wave = (with_wave && m_.wave && !hull.bem_excitation) ? &*m_.wave : nullptr;
    std::optional<sea::HullLoad> recorded;
    if (wave && hull.wave_record) {
      recorded = sea::recorded_hull_pressure_load(hull.section, *hull.wave_record, *wave, wave_polynomials_, wave->ramp(t),
                                             m_.water_density, g, hull_q.head<2>(), hull_q(2), t);
    }
    if (wave) ++(recorded ? hull_load_counts_.recorded : hull_load_counts_.exact);
    const sea::HullLoad load =
        recorded ? *recorded : sea::hull_pressure_load(hull.section, wave, m_.water_density, g, hull_q.head<2>(), hull_q(2), t);
    hull_force_.head<2>() += load.force;
    hull_force_(2) += load.moment;
  }
  hull_force_ -= hull.radiation_damping.cwiseProduct(hull_v);
  hull_force_ -= (hull.added_linear_damping + hull.quadratic_damping.cwiseProduct(hull_v.cwiseAbs())).cwiseProduct(hull_v);
  if (with_wave) {  // the dynamic problem (the static one is at rest in calm water)
    if (hull.bem_excitation && m_.wave) {
      hull_force_ += m_.wave->ramp(t) * (hull.bem_excitation_record ? hull.bem_excitation_record->at(t) : hull.bem_excitation->at(t));
    }
    if (radiation_.active() && hull_free()) hull_force_ -= radiation_.force(t, hull_v);
  }
  hull_force_(0) -= hull.mooring_stiffness * hull_q(0);
  hull_force_ -= hull.support_stiffness.cwiseProduct(hull_q - hull.support_pose);
  boom_and_wire_loads(cargo_q, cargo_v, !with_wave);
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::boom_and_wire_loads(const Eigen::Vector3d& cargo_q, const Eigen::Vector3d& cargo_v,
                                              bool bilateral_wire) {
  const double g = m_.gravity;
  m_.boom.loads_and_mass_blocks(boom_q_, boom_v_, Eigen::Vector2d(0.0, -g), boom_force_, boom_reference_mass_, boom_coupling_,
                                boom_work_);
  if (!has_cargo()) {
    cargo_force_.setZero();
    wire_ = WireState{};
    return;
  }
  cargo_force_ = Eigen::Vector3d(0.0, -m_.cargo.mass * g, 0.0);
  add_wire_loads(cargo_q, cargo_v, bilateral_wire, boom_force_, cargo_force_);
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::add_wire_loads(const Eigen::Vector3d& cargo_q, const Eigen::Vector3d& cargo_v, bool bilateral,
                                         Ref boom, Eigen::Vector3d& cargo) {
  const auto tip = m_.boom.point_motion(boom_q_, boom_v_, m_.boom_tip);
  const Eigen::Vector2d hook_arm = rotation(cargo_q(2)) * m_.cargo.hook;
  const Eigen::Vector2d hook = cargo_q.head<2>() + hook_arm;
  const Eigen::Vector2d hook_v = cargo_v.head<2>() + cargo_v(2) * perp(hook_arm);
  wire_ = wire_state(m_.wire, tip.position, tip.velocity, hook, hook_v, bilateral);
  const Eigen::Vector2d pull = wire_.tension * wire_.direction;  // on the tip, towards the hook
  m_.boom.add_point_force(tip, m_.boom_tip, pull, boom);
  cargo.head<2>() -= pull;
  cargo(2) -= cross(hook_arm, pull);
}

template <fem::ElasticCoordinates Coords>
Eigen::Vector3d CraneEquationsOf<Coords>::frame_known_acceleration(double t, const Eigen::Vector3d& hull_v) const {
  Eigen::Vector3d known;
  known.head<2>() = -hull_v(2) * hull_v(2) * mount_offset_;
  known(2) = 0.0;
  if (m_.hull.prescribed) {
    const Eigen::Vector3d base_a = base_acceleration(t);
    known.head<2>() += base_a.head<2>() + base_a(2) * perp(mount_offset_);
    known(2) = base_a(2);
  }
  return known;
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::split_minimal(double t, ConstRef z, ConstRef z_dot, Eigen::Vector3d& hull_q,
                                        Eigen::Vector3d& hull_v) const {
  if (hull_free()) {
    hull_q = z.head<3>();
    hull_v = z_dot.head<3>();
  } else {
    hull_q = base_pose(t);
    hull_v = base_velocity(t);
  }
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::minimal_forces(double t, ConstRef z, ConstRef z_dot, bool with_wave) {
  Eigen::Vector3d hull_q, hull_v;
  split_minimal(t, z, z_dot, hull_q, hull_v);
  mount_boom(hull_q, hull_v);
  boom_q_.tail(n_) = z.tail(n_);
  boom_v_.tail(n_) = z_dot.tail(n_);
  const Eigen::Vector3d no_cargo = Eigen::Vector3d::Zero();
  evaluate_loads(t, hull_q, hull_v, has_cargo() ? Eigen::Vector3d(z.segment<3>(cargo_at_)) : no_cargo,
                 has_cargo() ? Eigen::Vector3d(z_dot.segment<3>(cargo_at_)) : no_cargo, with_wave);
  frame_known_acc_ = frame_known_acceleration(t, hull_v);  // (the mass blocks came with the loads)
  const Eigen::Vector3d boom_reference_rhs = boom_force_.head<3>() - boom_reference_mass_ * frame_known_acc_;
  elastic_rhs_.noalias() = boom_force_.tail(n_) - boom_coupling_.transpose() * frame_known_acc_;
  Eigen::Matrix3d jr = Eigen::Matrix3d::Identity();
  jr(0, 2) = -mount_offset_.y();
  jr(1, 2) = mount_offset_.x();
  hull_rhs_ = hull_force_ + jr.transpose() * boom_reference_rhs;
  hull_elastic_mass_.noalias() = jr.transpose() * boom_coupling_;
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::minimal_accelerations(double t, ConstRef z, ConstRef z_dot, Ref z_ddot) {
  minimal_forces(t, z, z_dot, true);
  if (has_cargo()) z_ddot.segment<3>(cargo_at_) = cargo_force_.cwiseQuotient(cargo_inertia());
  Eigen::Vector3d hull_a = Eigen::Vector3d::Zero();
  if (n_ > 0 && !hull_free()) schur_rhs_ = shared_->elastic_mass_factor.solve(elastic_rhs_);
  if (hull_free()) {
    const Eigen::Matrix3d jr = mount_jacobian();
    Eigen::Matrix3d schur = hull_rigid_inertia() + jr.transpose() * boom_reference_mass_ * jr;
    Eigen::Vector3d rhs = hull_rhs_;
    if (n_ > 0) {
      // M_ff⁻¹ M_fR = M_ff⁻¹ [S̄ᵀAᵀ, −(cᵀ + S̃ᵀη)] = [(M_ff⁻¹S̄ᵀ) Aᵀ, −(M_ff⁻¹cᵀ + M_ff⁻¹S̃ᵀη)]: the first
      // two columns and M_ff⁻¹cᵀ are constant, so one two-column solve (the right-hand side and S̃ᵀη)
      // does what four did.
      pair_rhs_.col(0) = elastic_rhs_;
      pair_rhs_.col(1) = -(boom_coupling_.row(2) + m_.boom.coords().u0_cross_shape()).transpose();  // S̃ᵀη
      pair_solution_ = shared_->elastic_mass_factor.solve(pair_rhs_);
      schur_rhs_ = pair_solution_.col(0);
      const Eigen::Matrix2d frame_rotation = rotation(boom_q_(2));
      frame_columns_.leftCols<2>().noalias() = shared_->mass_inverse_shape * frame_rotation.transpose();
      frame_columns_.col(2) = -(shared_->mass_inverse_cross + pair_solution_.col(1));
      schur_columns_.noalias() = frame_columns_ * jr;
      schur -= hull_elastic_mass_ * schur_columns_;
      rhs -= hull_elastic_mass_ * schur_rhs_;
    }
    // LDLᵀ reads the lower triangle: the hull block is symmetric because the added mass is (checked
    // when the model is made, multibody/crane_model_of.hpp), so this is the matrix the residual uses.
    const Eigen::LDLT<Eigen::Matrix3d> schur_factor(schur);
    // A non-finite state is a divergence for the integrator to report, not a mass-matrix failure.
    if (schur.allFinite() &&
        (schur_factor.info() != Eigen::Success || !schur_factor.isPositive() || !(schur_factor.vectorD().minCoeff() > 0.0))) {
      throw MassMatrixError(schur_factor.vectorD().minCoeff());
    }
    hull_a = schur_factor.solve(rhs);
    z_ddot.head<3>() = hull_a;
    if (n_ > 0) z_ddot.tail(n_) = schur_rhs_ - schur_columns_ * hull_a;
  } else if (n_ > 0) {
    z_ddot.tail(n_) = schur_rhs_;
  }
  // Joint reaction on the boom at B: M_B q̈_B − Q_B over the frame rows (force, moment about B).
  Eigen::Vector3d frame_a = frame_known_acc_;
  frame_a.head<2>() += hull_a.head<2>() + hull_a(2) * perp(mount_offset_);
  frame_a(2) += hull_a(2);
  joint_reaction_ = boom_reference_mass_ * frame_a - boom_force_.head<3>();
  if (n_ > 0) joint_reaction_ += boom_coupling_ * z_ddot.tail(n_);
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::gather_minimal_forces(Ref forces) const {
  if (hull_free()) forces.head<3>() = hull_rhs_;
  if (has_cargo()) forces.segment<3>(cargo_at_) = cargo_force_;
  forces.tail(n_) = elastic_rhs_;
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::static_residual(ConstRef z, Ref residual) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(z.size());
  minimal_forces(0.0, z, zero, false);
  gather_minimal_forces(residual);
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::minimal_generalized_forces(double t, ConstRef z, ConstRef z_dot, Ref forces) {
  minimal_forces(t, z, z_dot, true);
  gather_minimal_forces(forces);
}

template <fem::ElasticCoordinates Coords>
Eigen::VectorXd CraneEquationsOf<Coords>::initial_guess() const {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(minimal_size());
  const Eigen::Vector3d hull_q = base_pose(0.0);
  if (hull_free()) z.head<3>() = hull_q;
  if (!has_cargo()) return z;
  // Cargo hanging straight below the undeformed tip, wire stretched by the cargo's weight.
  const Eigen::Vector2d root = hull_q.head<2>() + rotation(hull_q(2)) * m_.mount.root;
  const Eigen::Vector2d tip = root + rotation(hull_q(2) + m_.mount.angle) * m_.boom_tip.undeformed;
  const double stretch = m_.wire.stiffness > 0.0 ? m_.cargo.mass * m_.gravity / m_.wire.stiffness : 0.0;
  const Eigen::Vector2d hook = tip - Eigen::Vector2d(0.0, m_.wire.unstretched_length + stretch);
  z.segment<2>(cargo_at_) = hook - m_.cargo.hook;
  return z;
}

template <fem::ElasticCoordinates Coords>
Eigen::VectorXd CraneEquationsOf<Coords>::static_residual_scale() const {
  // 1 / (weight of the inertia on each row over 1 m): forces of order M_ii g.
  Eigen::VectorXd scale(minimal_size());
  const double g = m_.gravity;
  if (hull_free()) {
    const double total = m_.hull.mass + m_.boom.coords().mass() + m_.cargo.mass;
    scale.head<3>() = Eigen::Vector3d(1.0 / (total * g), 1.0 / (total * g), 1.0 / ((m_.hull.pitch_inertia + 1.0) * g));
  }
  if (has_cargo()) scale.segment<3>(cargo_at_) = cargo_inertia().cwiseInverse() / std::max(g, 1e-3);
  // Elastic rows: inertia under gravity plus the stiffness times a 1 cm displacement, so that the
  // round-off of K η (K grows like 1/h³) does not dominate the scaled residual.
  const Eigen::MatrixXd elastic_mass(m_.boom.coords().mass_ff());
  const Eigen::MatrixXd elastic_stiffness(m_.boom.coords().stiffness());
  for (int i = 0; i < n_; ++i) {
    scale(elastic_at_ + i) = 1.0 / (elastic_mass(i, i) * g + 0.01 * std::abs(elastic_stiffness(i, i)));
  }
  return scale;
}

template <fem::ElasticCoordinates Coords>
Eigen::VectorXd CraneEquationsOf<Coords>::coordinate_scale() const {
  return shared_->minimal_scale;  // 1 m, 0.01 rad for the pitches, the elastic ones' 1 cm (crane_model_of.hpp)
}

template <fem::ElasticCoordinates Coords>
void CraneEquationsOf<Coords>::boom_tip_kinematics(const Eigen::Vector3d& cargo_q, Eigen::Vector2d& tip, Eigen::Vector2d& hook) const {
  tip = m_.boom.position(boom_q_, m_.boom_tip);
  hook = cargo_q.head<2>() + rotation(cargo_q(2)) * m_.cargo.hook;
}

template <fem::ElasticCoordinates Coords>
double CraneEquationsOf<Coords>::wire_stretch_minimal(double t, ConstRef z) {
  if (!has_cargo()) return 1.0;
  Eigen::Vector3d hull_q, hull_v;
  split_minimal(t, z, z, hull_q, hull_v);
  mount_boom(hull_q, Eigen::Vector3d::Zero());
  boom_q_.tail(n_) = z.tail(n_);
  Eigen::Vector2d tip, hook;
  boom_tip_kinematics(z.segment<3>(cargo_at_), tip, hook);
  return (hook - tip).norm() - m_.wire.unstretched_length;
}

template <fem::ElasticCoordinates Coords>
CraneOutputs CraneEquationsOf<Coords>::minimal_outputs(double t, ConstRef z, ConstRef z_dot) {
  if (hull_free()) record_hull_velocity(t, z_dot.head<3>());
  Eigen::VectorXd z_ddot(z.size());
  minimal_accelerations(t, z, z_dot, z_ddot);
  Eigen::Vector3d hull_q, hull_v;
  split_minimal(t, z, z_dot, hull_q, hull_v);
  const Eigen::Vector3d no_cargo = Eigen::Vector3d::Zero();
  CraneOutputs out = common_outputs(hull_q, hull_v, has_cargo() ? Eigen::Vector3d(z.segment<3>(cargo_at_)) : no_cargo,
                                    has_cargo() ? Eigen::Vector3d(z_dot.segment<3>(cargo_at_)) : no_cargo);
  out.joint_reaction = joint_reaction_;
  out.root_axial_force = root_axial_force(joint_reaction_, boom_q_(2));
  out.constraint_residual = 0.0;
  return out;
}

template <fem::ElasticCoordinates Coords>
CraneOutputs CraneEquationsOf<Coords>::common_outputs(const Eigen::Vector3d& hull_q, const Eigen::Vector3d& hull_v,
                                                 const Eigen::Vector3d& cargo_q, const Eigen::Vector3d& cargo_v) {
  CraneOutputs out;
  out.hull = hull_q;
  out.cargo = cargo_q;
  out.tip_deflection = m_.boom_tip.shape * boom_q_.tail(n_);
  out.wire_tension = wire_.tension;
  out.wire_length = wire_.length;
  const double g = m_.gravity;
  const double cargo_on = has_cargo() ? 1.0 : 0.0;
  out.kinetic_energy = 0.5 * hull_v.dot(hull_rigid_inertia() * hull_v) * (hull_free() ? 1.0 : 0.0) +
                       cargo_on * 0.5 * cargo_v.dot(cargo_inertia().cwiseProduct(cargo_v)) +
                       m_.boom.kinetic_energy(boom_v_, boom_reference_mass_, boom_coupling_, boom_work_);
  out.gravity_energy = (hull_free() ? m_.hull.mass * g * hull_q(1) : 0.0) + cargo_on * m_.cargo.mass * g * cargo_q(1) +
                       m_.boom.gravity_potential(boom_q_, Eigen::Vector2d(0.0, -g));
  out.strain_energy = m_.boom.strain_energy(boom_q_, boom_work_);
  out.wire_energy = has_cargo() ? wire_energy(m_.wire, wire_.length) : 0.0;
  if (hull_free()) {
    const Eigen::Vector3d d = hull_q - m_.hull.support_pose;
    out.spring_energy = 0.5 * m_.hull.mooring_stiffness * hull_q(0) * hull_q(0) +
                        0.5 * d.dot(m_.hull.support_stiffness.cwiseProduct(d));
  }
  return out;
}

}  // namespace ffrf::multibody::detail
