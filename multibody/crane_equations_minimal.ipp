// Crane equations, part 1: loads on the bodies and the minimal-coordinate ODE.
// The heel at B is a velocity transformation from the rigid minimal coordinates z_r (the hull's
// (r1, θ1) when it floats, the pinned bodies' angles γ, then the pinned heel's luffing angle β) to the
// boom frame: the frame is
// at R_B = r1 + A(θ1) b, θ_B = θ1 + α (+ β), so Ṙ_B = ṙ1 + θ̇1 Ĩ A1 b, θ̇_B = θ̇1 (+ β̇), i.e.
// q̇_B = J ż_r with J = [J_r | e3], J_r = [[1, 0, −(A1 b)_y], [0, 1, (A1 b)_x], [0, 0, 1]], e3 = (0, 0, 1)
// (the pin's column), and q̈_B = J z̈_r + J̇ż, J̇ż = (−θ̇1² A1 b, 0). Then (Shabana 2005 §6, M_z = JᵀMJ,
// Q_z = Jᵀ(Q − M J̇ż)):
//   rigid rows:   (M_r + Jᵀ M_RR J) z̈_r + Jᵀ M_Rf η̈ = Q_r + Jᵀ (Q_B,ref − M_RR J̇ż)
//   elastic rows: M_fR J z̈_r + M_ff η̈ = Q_B,f − M_fR J̇ż
// with M_r, Q_r the hull's own inertia and loads (none on the heel's row), solved by the Schur
// complement of the constant M_ff (factored once). A body pinned to the hull adds its own velocity
// transformation J_b over z_r (multibody/rigid_body.hpp): J_bᵀ M_b J_b to the rigid rows' mass and
// J_bᵀ (F_b − M_b a₀_b) to their forces (its γ column moves neither the boom frame nor the hull). A held
// or driven base has no hull rows: its prescribed acceleration joins J̇ż as the known frame (and pinned
// bodies') acceleration. A free body (the cargo) has its own diagonal block: M_c z̈_c = F_c.
#pragma once

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Articulated>
CraneEquationsOf<Coords, Articulated>::CraneEquationsOf(std::shared_ptr<const CraneModelOf<Coords>> shared)
    : shared_(std::move(shared)),
      m_(shared_->model),
      layout_(shared_->layout),
      n_(shared_->n),
      boom_work_(m_.boom.workspace()),
      bodies_(m_.bodies.size()), boom_q_(3 + n_), boom_v_(3 + n_), boom_force_(3 + n_),
      body_forces_(m_.bodies.size(), Eigen::Vector3d::Zero()), wire_body_forces_(m_.bodies.size(), Eigen::Vector3d::Zero()),
      elastic_rhs_(n_), schur_rhs_column_(n_),
      boom_coupling_(3, n_), schur_rhs_(n_), wires_(m_.wires.size()),
      radiation_(m_.hull.radiation_memory), boom_a_(3 + n_), wire_boom_force_(3 + n_) {
  const int r = Articulated ? layout_.rigid_size() : 3;  // (a clamped boom's blocks are the hull's, unused when it is held)
  if constexpr (Articulated) {
    rigid_rhs_.resize(r);
    frame_jacobian_.resize(3, r);
    pinned_mass_.setZero(r, r);
  }
  rigid_elastic_mass_.resize(r, n_);
  schur_columns_.resize(n_, r);
  pair_rhs_.resize(n_, 2);
  pair_solution_.resize(n_, 2);
  frame_columns_.resize(n_, 3);
  for (Eigen::VectorXd* v : {&jacobian_base_, &jacobian_shifted_, &jacobian_x_, &jacobian_x_dot_}) {
    v->resize(std::max(minimal_size(), full_size()));
  }
  full_inertia_.resize(full_size());
}

template <fem::ElasticCoordinates Coords, bool Articulated>
Eigen::Matrix3d CraneEquationsOf<Coords, Articulated>::hull_rigid_inertia() const {
  Eigen::Matrix3d inertia = (Eigen::Vector3d(m_.hull.mass, m_.hull.mass, m_.hull.pitch_inertia) + m_.hull.added_mass).asDiagonal();
  if (radiation_.active()) inertia += radiation_.added_mass();
  return inertia;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::set_minimal_state(double t, ConstRef z, ConstRef z_dot, bool moving) {
  if (hull_free()) {
    hull_q_ = z.segment<3>(layout_.hull);
    hull_v_ = moving ? Eigen::Vector3d(z_dot.segment<3>(layout_.hull)) : Eigen::Vector3d::Zero();
  } else {
    hull_q_ = base_pose(t);
    hull_v_ = moving ? base_velocity(t) : Eigen::Vector3d::Zero();
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (block.pinned) {
      mount_pinned_body(static_cast<int>(i), z(block.minimal), moving ? z_dot(block.minimal) : 0.0);
    } else {
      bodies_[i].pose = z.segment<3>(block.minimal);
      bodies_[i].velocity = moving ? Eigen::Vector3d(z_dot.segment<3>(block.minimal)) : Eigen::Vector3d::Zero();
    }
  }
  const double beta = clamped() ? 0.0 : z(layout_.heel);
  const double beta_rate = clamped() || !moving ? 0.0 : z_dot(layout_.heel);
  mount_boom(beta, beta_rate);
  boom_q_.tail(n_) = z.tail(n_);
  if (moving) {
    boom_v_.tail(n_) = z_dot.tail(n_);
  } else {
    boom_v_.tail(n_).setZero();
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::set_full_state(double t, ConstRef q, ConstRef v) {
  hull_q_ = hull_free() ? Eigen::Vector3d(q.segment<3>(layout_.hull)) : base_pose(t);
  hull_v_ = hull_free() ? Eigen::Vector3d(v.segment<3>(layout_.hull)) : base_velocity(t);
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    bodies_[i].pose = q.segment<3>(layout_.bodies[i].full);
    bodies_[i].velocity = v.segment<3>(layout_.bodies[i].full);
  }
  boom_q_ = q.tail(3 + n_);
  boom_v_ = v.tail(3 + n_);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::mount_boom(double beta, double beta_rate) {
  mount_offset_ = rotation(hull_q_(2)) * m_.mount.root;
  boom_q_.head<2>() = hull_q_.head<2>() + mount_offset_;
  boom_q_(2) = hull_q_(2) + m_.mount.angle;
  boom_v_.head<2>() = hull_v_.head<2>() + hull_v_(2) * perp(mount_offset_);
  boom_v_(2) = hull_v_(2);
  if (!clamped()) {
    boom_q_(2) += beta;
    boom_v_(2) += beta_rate;
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::evaluate_loads(double t, bool with_wave) {
  const double g = m_.gravity;
  const HullModel& hull = m_.hull;
  const Eigen::Vector3d& hull_q = hull_q_;
  const Eigen::Vector3d& hull_v = hull_v_;
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
  boom_and_wire_loads(!with_wave);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::boom_and_wire_loads(bool bilateral_wires) {
  m_.boom.loads_and_mass_blocks(boom_q_, boom_v_, Eigen::Vector2d(0.0, -m_.gravity), boom_force_, boom_reference_mass_,
                                boom_coupling_, boom_work_);
  for (std::size_t i = 0; i < body_forces_.size(); ++i) body_forces_[i] = Eigen::Vector3d(0.0, -m_.bodies[i].mass * m_.gravity, 0.0);
  add_wire_loads(bilateral_wires, boom_force_, hull_force_, body_forces_);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
Eigen::Vector3d CraneEquationsOf<Coords, Articulated>::frame_known_acceleration(double t) const {
  Eigen::Vector3d known;
  known.head<2>() = -hull_v_(2) * hull_v_(2) * mount_offset_;
  known(2) = 0.0;
  if (m_.hull.prescribed) {
    const Eigen::Vector3d base_a = base_acceleration(t);
    known.head<2>() += base_a.head<2>() + base_a(2) * perp(mount_offset_);
    known(2) = base_a(2);
  }
  return known;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
typename CraneEquationsOf<Coords, Articulated>::FrameJacobian CraneEquationsOf<Coords, Articulated>::frame_jacobian() const {
  FrameJacobian jacobian;
  if constexpr (Articulated) {
    jacobian.setZero(3, layout_.rigid_size());
  } else {
    jacobian.setZero();
  }
  if (hull_free()) {
    jacobian.template leftCols<3>().setIdentity();
    jacobian(0, 2) = -mount_offset_.y();
    jacobian(1, 2) = mount_offset_.x();
  }
  if (!clamped()) jacobian(2, layout_.rigid_size() - 1) = 1.0;  // the heel's angle: the last of the rigid block
  return jacobian;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::add_frame_acceleration(const RigidVector& rigid_a, Eigen::Vector3d& frame_a) const {
  if (hull_free()) {
    frame_a.head<2>() += rigid_a.template head<2>() + rigid_a(2) * perp(mount_offset_);
    frame_a(2) += rigid_a(2);
  }
  if (!clamped()) frame_a(2) += rigid_a(rigid_a.size() - 1);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::minimal_forces(double t, ConstRef z, ConstRef z_dot, bool with_wave) {
  set_minimal_state(t, z, z_dot);
  evaluate_loads(t, with_wave);
  frame_known_acc_ = frame_known_acceleration(t);  // (the mass blocks came with the loads)
  const Eigen::Vector3d boom_reference_rhs = boom_force_.head<3>() - boom_reference_mass_ * frame_known_acc_;
  elastic_rhs_.noalias() = boom_force_.tail(n_) - boom_coupling_.transpose() * frame_known_acc_;
  if (layout_.rigid_size() == 0) return;
  frame_jacobian_ = frame_jacobian();
  rigid_rhs_ = frame_jacobian_.transpose() * boom_reference_rhs;
  if (hull_free()) rigid_rhs_.template head<3>() += hull_force_;
  if constexpr (Articulated) {
    if (has_pinned_bodies()) {
      pinned_mass_.setZero();
      add_pinned_bodies(t, body_forces_, rigid_rhs_, true);
    }
  }
  rigid_elastic_mass_.noalias() = frame_jacobian_.transpose() * boom_coupling_;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::minimal_accelerations(double t, ConstRef z, ConstRef z_dot, Ref z_ddot) {
  minimal_forces(t, z, z_dot, true);
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (!block.pinned) z_ddot.segment<3>(block.minimal) = body_forces_[i].cwiseQuotient(body_inertia(static_cast<int>(i)));
  }
  const int r = layout_.rigid_size();
  RigidVector rigid_a;
  if (n_ > 0 && r == 0) schur_rhs_ = shared_->elastic_mass_factor.solve(elastic_rhs_);
  if (r > 0) {
    const FrameJacobian& jr = frame_jacobian_;
    RigidMatrix schur = rigid_mass();
    RigidVector rhs = rigid_rhs_;
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
      schur -= rigid_elastic_mass_ * schur_columns_;
      rhs -= rigid_elastic_mass_ * schur_rhs_;
    }
    // LDLᵀ reads the lower triangle: the hull block is symmetric because the added mass is (checked
    // when the model is made, multibody/crane_model_of.hpp), so this is the matrix the residual uses.
    const Eigen::LDLT<RigidMatrix> schur_factor(schur);
    // A non-finite state is a divergence for the integrator to report, not a mass-matrix failure.
    if (schur.allFinite() &&
        (schur_factor.info() != Eigen::Success || !schur_factor.isPositive() || !(schur_factor.vectorD().minCoeff() > 0.0))) {
      throw MassMatrixError(schur_factor.vectorD().minCoeff());
    }
    rigid_a = schur_factor.solve(rhs);
    scatter_rigid(rigid_a, z_ddot);
    if (n_ > 0) z_ddot.tail(n_) = schur_rhs_ - schur_columns_ * rigid_a;
  } else if (n_ > 0) {
    z_ddot.tail(n_) = schur_rhs_;
  }
  // Joint reaction on the boom at B: M_B q̈_B − Q_B over the frame rows (force, moment about B).
  Eigen::Vector3d frame_a = frame_known_acc_;
  if (r > 0) add_frame_acceleration(rigid_a, frame_a);
  joint_reaction_ = boom_reference_mass_ * frame_a - boom_force_.head<3>();
  if (n_ > 0) joint_reaction_ += boom_coupling_ * z_ddot.tail(n_);
  frame_acceleration_ = frame_a;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::gather_minimal_forces(Ref forces) const {
  if (layout_.rigid_size() > 0) scatter_rigid(rigid_rhs_, forces);
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!layout_.bodies[i].pinned) forces.segment<3>(layout_.bodies[i].minimal) = body_forces_[i];
  }
  forces.tail(n_) = elastic_rhs_;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::static_residual(ConstRef z, Ref residual) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(z.size());
  minimal_forces(0.0, z, zero, false);
  gather_minimal_forces(residual);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::minimal_generalized_forces(double t, ConstRef z, ConstRef z_dot, Ref forces) {
  minimal_forces(t, z, z_dot, true);
  gather_minimal_forces(forces);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
Eigen::VectorXd CraneEquationsOf<Coords, Articulated>::initial_guess() const {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(minimal_size());
  const Eigen::Vector3d hull_q = base_pose(0.0);
  if (hull_free()) z.segment<3>(layout_.hull) = hull_q;
  // Free bodies at their given poses, pinned ones at γ = 0, ...
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!layout_.bodies[i].pinned) z.segment<3>(layout_.bodies[i].minimal) = m_.bodies[i].initial_pose;
  }
  if (m_.cargo < 0) return z;
  // ... and the cargo hanging straight below the undeformed tip, its wire stretched by its weight.
  const WireConnector& hoist = m_.wires[m_.hoist_wire];
  const Eigen::Vector2d root = hull_q.head<2>() + rotation(hull_q(2)) * m_.mount.root;
  const Eigen::Vector2d tip = root + rotation(hull_q(2) + m_.mount.angle) * hoist.from.point.undeformed;
  const double cargo_mass = m_.bodies[m_.cargo].mass;
  const double stretch = hoist.rope.stiffness > 0.0 ? cargo_mass * m_.gravity / hoist.rope.stiffness : 0.0;
  const Eigen::Vector2d hook = tip - Eigen::Vector2d(0.0, hoist.rope.unstretched_length + stretch);
  z.segment<2>(cargo_offset()) = hook - hoist.to.point.undeformed;
  z(cargo_offset() + 2) = 0.0;
  return z;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
Eigen::VectorXd CraneEquationsOf<Coords, Articulated>::static_residual_scale() const {
  // 1 / (weight of the inertia on each row over 1 m): forces of order M_ii g.
  Eigen::VectorXd scale(minimal_size());
  const double g = m_.gravity;
  if (hull_free()) {
    double total = m_.hull.mass + m_.boom.coords().mass();
    for (const RigidBodyModel& body : m_.bodies) total += body.mass;
    scale.segment<3>(layout_.hull) =
        Eigen::Vector3d(1.0 / (total * g), 1.0 / (total * g), 1.0 / ((m_.hull.pitch_inertia + 1.0) * g));
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (block.pinned) {
      scale(block.minimal) = 1.0 / ((m_.bodies[i].inertia_about_pivot() + 1.0) * std::max(g, 1e-3));
    } else {
      scale.segment<3>(block.minimal) = body_inertia(static_cast<int>(i)).cwiseInverse() / std::max(g, 1e-3);
    }
  }
  if (!clamped()) scale(layout_.heel) = 1.0 / ((shared_->heel_inertia + 1.0) * std::max(g, 1e-3));
  // Elastic rows: inertia under gravity plus the stiffness times a 1 cm displacement, so that the
  // round-off of K η (K grows like 1/h³) does not dominate the scaled residual.
  const Eigen::MatrixXd elastic_mass(m_.boom.coords().mass_ff());
  const Eigen::MatrixXd elastic_stiffness(m_.boom.coords().stiffness());
  for (int i = 0; i < n_; ++i) {
    scale(layout_.elastic + i) = 1.0 / (elastic_mass(i, i) * g + 0.01 * std::abs(elastic_stiffness(i, i)));
  }
  return scale;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
Eigen::VectorXd CraneEquationsOf<Coords, Articulated>::coordinate_scale() const {
  return shared_->minimal_scale;  // 1 m, 0.01 rad for the pitches and angles, the elastic ones' 1 cm (crane_model_of.hpp)
}

}  // namespace ffrf::multibody::detail
