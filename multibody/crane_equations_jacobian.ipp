// Crane equations, part 3: the structured linearizations the Newton solvers use
// (solve/second_order_jacobian.hpp) and the outputs from known accelerations.
// Columns of K = −∂(Q − M a)/∂x and D = −∂(Q − M a)/∂ẋ by three means:
//  * the elastic columns analytically: the boom's own terms (FloatingFrameBody::add_elastic_derivatives:
//    stiffness, damping, stiffening, quadratic velocity, gravity, inertia), mapped to the rigid rows
//    (hull, heel) by Jᵀ in minimal coordinates — no evaluation of the equations;
//  * the wires' share of the columns whose coordinates move a wire's attachment on the boom (the
//    nonzero columns of its shape rows: the tip node's DOFs of a nodal boom, every modal coordinate)
//    by forward differences of the wires' loads alone;
//  * the dense columns (hull, rigid bodies, the heel's angle and, in full coordinates, the boom frame) by
//    forward differences of the whole residual: 12 (minimal) or 18 (full) evaluations for the
//    clamped crane whatever the element count.
// Increments: δ = f·s_j for positions and f·max(|ẋ_j|, s_j) for velocities, s_j the coordinate's
// typical size (coordinate_scale(): 1 m, 0.01 rad, the elastic ones' 1 cm), f = 10⁻⁷ for the whole
// residual and 10⁻⁶ for the wire's loads alone (fewer large terms, so less round-off). These keep the
// Newton matrix within ~10⁻⁶ of central differences (tests/coupling/test_newton_jacobians.cpp); larger
// increments for the whole residual made IDA's step-size control wander (twice the error-test
// failures at N = 64).
#pragma once

#include <algorithm>
#include <array>

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::minimal_residual(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, Ref out) {
  minimal_forces(t, z, z_dot, true);
  const auto eta_ddot = z_ddot.tail(n_);
  out.tail(n_) = elastic_rhs_;
  out.tail(n_).noalias() -= m_.boom.coords().mass_ff() * eta_ddot;
  if (layout_.rigid_size() > 0) {
    const RigidMatrix mass = rigid_mass();
    const RigidVector rigid_a = rigid_part(z_ddot);
    RigidVector rigid = rigid_rhs_ - mass * rigid_a;
    rigid.noalias() -= rigid_elastic_mass_ * eta_ddot;
    scatter_rigid(rigid, out);
    out.tail(n_).noalias() -= rigid_elastic_mass_.transpose() * rigid_a;
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const BodyBlock& block = layout_.bodies[i];
    if (block.pinned) continue;
    out.segment<3>(block.minimal) = body_forces_[i] - body_inertia(static_cast<int>(i)).cwiseProduct(z_ddot.segment<3>(block.minimal));
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::minimal_wire_residual(double t, ConstRef z, ConstRef z_dot, Ref out) {
  out.setZero();
  if (m_.wires.empty()) return;
  set_minimal_state(t, z, z_dot);
  wire_boom_force_.setZero();
  Eigen::Vector3d hull = Eigen::Vector3d::Zero();
  for (Eigen::Vector3d& force : wire_body_forces_) force.setZero();
  add_wire_loads(false, wire_boom_force_, hull, wire_body_forces_);
  if (layout_.rigid_size() > 0) {
    RigidVector rigid = frame_jacobian().transpose() * wire_boom_force_.head<3>();
    if (hull_free() && !hull.isZero(0.0)) rigid.template head<3>() += hull;  // (a wire to the hull)
    if constexpr (Articulated) {
      if (has_pinned_bodies()) add_pinned_bodies(t, wire_body_forces_, rigid, false);  // (a wire to a pinned body)
    }
    scatter_rigid(rigid, out);
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!layout_.bodies[i].pinned) out.segment<3>(layout_.bodies[i].minimal) = wire_body_forces_[i];
  }
  out.tail(n_) = wire_boom_force_.tail(n_);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::full_residual(double t, ConstRef q, ConstRef v, ConstRef v_dot, Ref out) {
  full_forces(t, q, v, out);
  full_mass_times(q, v_dot, full_inertia_);
  out -= full_inertia_;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::full_wire_residual(double t, ConstRef q, ConstRef v, Ref out) {
  out.setZero();
  if (m_.wires.empty()) return;
  set_full_state(t, q, v);
  Eigen::Vector3d hull = Eigen::Vector3d::Zero();
  for (Eigen::Vector3d& force : wire_body_forces_) force.setZero();
  add_wire_loads(false, out.tail(3 + n_), hull, wire_body_forces_);
  if (hull_free()) out.segment<3>(layout_.hull) = hull;
  for (std::size_t i = 0; i < bodies_.size(); ++i) out.segment<3>(layout_.bodies[i].full) = wire_body_forces_[i];
}

// The shared steps of both Jacobians: difference the wires' share over their columns (added) and
// the whole residual over the dense leading columns (assigned). `residual(x, x_dot, out)` and
// `wire(x, x_dot, out)` evaluate at the given state; `x`, `x_dot` are the state (restored on return).
constexpr double dense_increment = 1e-7;  // × size: the whole residual (hull loads ~1e8 N)
constexpr double wire_increment = 1e-6;   // × size: the wire's loads alone

template <class Residual, class Wire>
void difference_columns(int size, int dense_columns, int elastic_offset, const std::vector<int>& tip_columns, bool wire_present,
                        const Eigen::VectorXd& scale, Eigen::VectorXd& x, Eigen::VectorXd& x_dot, Eigen::VectorXd& base,
                        Eigen::VectorXd& shifted, Residual residual, Wire wire, SecondOrderJacobian& out) {
  // Positions: a fraction of the coordinate's typical size, not of its value (the loads depend on
  // differences of positions ~100 m from the origin; an increment ∝ |x| would be 100× too coarse for
  // the 20 m wire). Velocities: of their value or typical size.
  const auto position_increment = [&scale](int j, double factor) { return factor * scale(j); };
  const auto rate_increment = [&scale](int j, double value, double factor) { return factor * std::max(std::abs(value), scale(j)); };
  const auto column = [&](BorderedBandMatrix& target, int col, double delta, bool assign) {
    for (int i = 0; i < size; ++i) {
      const double value = -(shifted(i) - base(i)) / delta;
      if (assign) {
        target.at(i, col) = value;
      } else if (value != 0.0 && target.in_structure(i, col)) {  // the wire moves only tip and border rows
        target.at(i, col) += value;
      }
    }
  };
  if (wire_present && !tip_columns.empty()) {
    wire(x, x_dot, base);
    for (const int j : tip_columns) {
      const int col = elastic_offset + j;
      const double saved = x(col), saved_rate = x_dot(col);
      const double dz = position_increment(col, wire_increment), dv = rate_increment(col, saved_rate, wire_increment);
      x(col) = saved + dz;
      wire(x, x_dot, shifted);
      x(col) = saved;
      column(out.stiffness, col, dz, false);
      x_dot(col) = saved_rate + dv;
      wire(x, x_dot, shifted);
      x_dot(col) = saved_rate;
      column(out.damping, col, dv, false);
    }
  }
  residual(x, x_dot, base);
  for (int col = 0; col < dense_columns; ++col) {
    const double saved = x(col), saved_rate = x_dot(col);
    const double dz = position_increment(col, dense_increment), dv = rate_increment(col, saved_rate, dense_increment);
    x(col) = saved + dz;
    residual(x, x_dot, shifted);
    x(col) = saved;
    column(out.stiffness, col, dz, true);
    x_dot(col) = saved_rate + dv;
    residual(x, x_dot, shifted);
    x_dot(col) = saved_rate;
    column(out.damping, col, dv, true);
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::minimal_jacobian(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, SecondOrderJacobian& out) {
  const int size = minimal_size(), e = layout_.elastic, r = layout_.rigid_size();
  out.set_zero();
  minimal_forces(t, z, z_dot, true);  // mounts the boom, its mass blocks, J and Jᵀ M_Rf
  // The rigid rows' and columns' places in z: the hull's, the pinned bodies', then the heel's.
  const std::array<int, max_rigid_block>& rigid_index = layout_.rigid_coordinates;
  Eigen::Vector3d frame_a = frame_known_acc_;
  if (r > 0) {
    const FrameJacobian& jr = frame_jacobian_;
    const RigidMatrix mass = rigid_mass();
    for (int i = 0; i < r; ++i) {
      for (int j = 0; j < r; ++j) out.mass.at(rigid_index[i], rigid_index[j]) = mass(i, j);
      for (int j = 0; j < n_; ++j) out.mass.at(rigid_index[i], e + j) = out.mass.at(e + j, rigid_index[i]) = rigid_elastic_mass_(i, j);
    }
    frame_a += jr * rigid_part(z_ddot);
  }
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const BodyBlock& block = layout_.bodies[k];
    if (block.pinned) continue;
    for (int i = 0; i < 3; ++i) out.mass.at(block.minimal + i, block.minimal + i) = body_inertia(static_cast<int>(k))(i);
  }
  if (n_ > 0) {
    FloatingFrameBody<Coords>::add_scaled(m_.boom.coords().mass_ff(), 1.0, false, out.mass, e);
    boom_a_.head<3>() = frame_a;
    boom_a_.tail(n_) = z_ddot.tail(n_);
    m_.boom.add_elastic_derivatives(boom_q_, boom_v_, boom_a_, Eigen::Vector2d(0.0, -m_.gravity), reference_stiffness_,
                                    reference_damping_, out.stiffness, out.damping, e, boom_work_);
    if (r > 0) {
      const RigidCoupling rigid_k = frame_jacobian_.transpose() * reference_stiffness_;
      const RigidCoupling rigid_d = frame_jacobian_.transpose() * reference_damping_;
      for (int i = 0; i < r; ++i) {
        for (int j = 0; j < n_; ++j) {
          out.stiffness.at(rigid_index[i], e + j) = rigid_k(i, j);
          out.damping.at(rigid_index[i], e + j) = rigid_d(i, j);
        }
      }
    }
  }
  Eigen::VectorXd& state = jacobian_x_;
  Eigen::VectorXd& rate = jacobian_x_dot_;
  state.head(size) = z;
  rate.head(size) = z_dot;
  difference_columns(
      size, e, e, shared_->wire_columns, !m_.wires.empty(), shared_->minimal_scale, state, rate, jacobian_base_, jacobian_shifted_,
      [&](const Eigen::VectorXd& s, const Eigen::VectorXd& s_dot, Eigen::VectorXd& res) {
        minimal_residual(t, s.head(size), s_dot.head(size), z_ddot, res.head(size));
      },
      [&](const Eigen::VectorXd& s, const Eigen::VectorXd& s_dot, Eigen::VectorXd& res) {
        minimal_wire_residual(t, s.head(size), s_dot.head(size), res.head(size));
      },
      out);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::full_jacobian(double t, ConstRef q, ConstRef v, ConstRef v_dot, SecondOrderJacobian& out) {
  const int size = full_size(), b = layout_.frame, e = layout_.frame + 3;
  out.set_zero();
  if (hull_free()) {
    const Eigen::Matrix3d hull_mass = hull_rigid_inertia();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) out.mass.at(layout_.hull + i, layout_.hull + j) = hull_mass(i, j);
    }
  }
  for (std::size_t k = 0; k < bodies_.size(); ++k) {
    const int at = layout_.bodies[k].full;
    for (int i = 0; i < 3; ++i) out.mass.at(at + i, at + i) = body_inertia(static_cast<int>(k))(i);
  }
  boom_q_ = q.tail(3 + n_);
  boom_v_ = v.tail(3 + n_);
  m_.boom.mass_blocks(boom_q_, boom_reference_mass_, boom_coupling_, boom_work_);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.mass.at(b + i, b + j) = boom_reference_mass_(i, j);
    for (int j = 0; j < n_; ++j) out.mass.at(b + i, e + j) = out.mass.at(e + j, b + i) = boom_coupling_(i, j);
  }
  if (n_ > 0) {
    FloatingFrameBody<Coords>::add_scaled(m_.boom.coords().mass_ff(), 1.0, false, out.mass, e);
    boom_a_ = v_dot.tail(3 + n_);
    m_.boom.add_elastic_derivatives(boom_q_, boom_v_, boom_a_, Eigen::Vector2d(0.0, -m_.gravity), reference_stiffness_,
                                    reference_damping_, out.stiffness, out.damping, e, boom_work_);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < n_; ++j) {
        out.stiffness.at(b + i, e + j) = reference_stiffness_(i, j);
        out.damping.at(b + i, e + j) = reference_damping_(i, j);
      }
    }
  }
  Eigen::VectorXd& state = jacobian_x_;
  Eigen::VectorXd& rate = jacobian_x_dot_;
  state.head(size) = q;
  rate.head(size) = v;
  difference_columns(
      size, e, e, shared_->wire_columns, !m_.wires.empty(), shared_->full_scale, state, rate, jacobian_base_, jacobian_shifted_,
      [&](const Eigen::VectorXd& s, const Eigen::VectorXd& s_dot, Eigen::VectorXd& r) {
        full_residual(t, s.head(size), s_dot.head(size), v_dot, r.head(size));
      },
      [&](const Eigen::VectorXd& s, const Eigen::VectorXd& s_dot, Eigen::VectorXd& r) {
        full_wire_residual(t, s.head(size), s_dot.head(size), r.head(size));
      },
      out);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
CraneOutputs CraneEquationsOf<Coords, Articulated>::minimal_outputs_with_accelerations(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot) {
  set_minimal_state(t, z, z_dot);
  record_hull_velocity(t, hull_v_);
  hull_force_.setZero();  // (the wires' share on the hull lands here; the hull's own loads are not needed)
  boom_and_wire_loads(false);  // and the mass blocks
  Eigen::Vector3d frame_a = frame_known_acceleration(t);
  if (layout_.rigid_size() > 0) frame_a += frame_jacobian() * rigid_part(z_ddot);
  // Joint reaction on the boom at B: M_B q̈_B − Q_B over the frame rows, with q̈ from the caller.
  joint_reaction_ = boom_reference_mass_ * frame_a - boom_force_.head<3>();
  if (n_ > 0) joint_reaction_.noalias() += boom_coupling_ * z_ddot.tail(n_);
  CraneOutputs out = common_outputs();
  out.joint_reaction = joint_reaction_;
  out.root_axial_force = root_axial_force(joint_reaction_, boom_q_(2));
  out.constraint_residual = 0.0;
  add_boom_stress(frame_a, z_ddot.tail(n_), out);
  return out;
}

}  // namespace ffrf::multibody::detail
