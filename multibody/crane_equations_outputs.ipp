// Crane equations, the outputs of a state in minimal coordinates and what every set of coordinates
// shares (multibody/crane_equations.hpp: CraneOutputs): the bodies' poses, the wires' tensions by their
// role, the energies (kinetic, gravity, strain, wires, springs) for the conservation checks.
#pragma once

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Articulated>
CraneOutputs CraneEquationsOf<Coords, Articulated>::minimal_outputs(double t, ConstRef z, ConstRef z_dot) {
  if (hull_free()) record_hull_velocity(t, z_dot.segment<3>(layout_.hull));
  Eigen::VectorXd z_ddot(z.size());
  minimal_accelerations(t, z, z_dot, z_ddot);
  CraneOutputs out = common_outputs();
  out.joint_reaction = joint_reaction_;
  out.root_axial_force = root_axial_force(joint_reaction_, boom_q_(2));
  out.constraint_residual = 0.0;
  add_boom_stress(frame_acceleration_, z_ddot.tail(n_), out);
  return out;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
CraneOutputs CraneEquationsOf<Coords, Articulated>::common_outputs() {
  CraneOutputs out;
  out.hull = hull_q_;
  if (m_.cargo >= 0) out.cargo = bodies_[m_.cargo].pose;
  if (m_.a_frame >= 0) out.a_frame_rotation = bodies_[m_.a_frame].pose(2) - hull_q_(2) - m_.bodies[m_.a_frame].angle;
  out.tip_deflection = m_.boom_tip.shape * boom_q_.tail(n_);
  if (m_.hoist_wire >= 0) {
    out.wire_tension = wires_[m_.hoist_wire].tension;
    out.wire_length = wires_[m_.hoist_wire].length;
  }
  const double g = m_.gravity;
  double kinetic = 0.5 * hull_v_.dot(hull_rigid_inertia() * hull_v_) * (hull_free() ? 1.0 : 0.0);
  double gravity = hull_free() ? m_.hull.mass * g * hull_q_(1) : 0.0;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const Eigen::Vector3d& v = bodies_[i].velocity;
    kinetic += 0.5 * v.dot(body_inertia(static_cast<int>(i)).cwiseProduct(v));
    gravity += m_.bodies[i].mass * g * bodies_[i].pose(1);
  }
  out.kinetic_energy = kinetic + m_.boom.kinetic_energy(boom_v_, boom_reference_mass_, boom_coupling_, boom_work_);
  out.gravity_energy = gravity + m_.boom.gravity_potential(boom_q_, Eigen::Vector2d(0.0, -g));
  out.strain_energy = m_.boom.strain_energy(boom_q_, boom_work_);
  for (std::size_t i = 0; i < m_.wires.size(); ++i) {
    out.wire_energy += wire_energy(m_.wires[i].rope, wires_[i].length);
    switch (m_.wires[i].role) {
      case WireRole::hoist: break;
      case WireRole::luffing:
        out.luffing_tension += wires_[i].tension;
        out.luffing_line_pull = std::max(out.luffing_line_pull, wires_[i].tension / m_.wires[i].parts);
        break;
      case WireRole::backstay: out.backstay_tension += wires_[i].tension; break;
    }
  }
  if (hull_free()) {
    const Eigen::Vector3d d = hull_q_ - m_.hull.support_pose;
    out.spring_energy = 0.5 * m_.hull.mooring_stiffness * hull_q_(0) * hull_q_(0) +
                        0.5 * d.dot(m_.hull.support_stiffness.cwiseProduct(d));
  }
  return out;
}

}  // namespace ffrf::multibody::detail
