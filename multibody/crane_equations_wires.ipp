// Crane equations, the connectors' part: the wires between body points (multibody/crane_parameters.hpp:
// WireConnector). Each end's motion comes from its body — a rigid body's point (multibody/rigid_body.hpp)
// or the boom's material point with its shape rows (multibody/floating_frame_body.hpp) — and the
// rope's tension (multibody/wire_rope.hpp) pulls the two ends towards each other, each force mapped
// to its body's generalized force by virtual work. Every wire's stretch is an event function.
#pragma once

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Articulated>
typename CraneEquationsOf<Coords, Articulated>::EndMotion CraneEquationsOf<Coords, Articulated>::end_motion(const BodyAttachment& end) const {
  EndMotion motion;
  switch (end.body) {
    case Body::boom: motion.boom = m_.boom.point_motion(boom_q_, boom_v_, end.point); break;
    case Body::hull: motion.rigid = rigid_point_motion(hull_q_, hull_v_, end.point.undeformed); break;
    case Body::rigid:
      motion.rigid = rigid_point_motion(bodies_[end.index].pose, bodies_[end.index].velocity, end.point.undeformed);
      break;
  }
  return motion;
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::add_end_force(const BodyAttachment& end, const EndMotion& motion, const Eigen::Vector2d& force,
                                             Ref boom, Eigen::Vector3d& hull, std::vector<Eigen::Vector3d>& bodies) const {
  switch (end.body) {
    case Body::boom: m_.boom.add_point_force(motion.boom, end.point, force, boom); break;
    case Body::hull: add_rigid_point_force(motion.rigid, force, hull); break;
    case Body::rigid: add_rigid_point_force(motion.rigid, force, bodies[end.index]); break;
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::add_wire_loads(bool bilateral, Ref boom, Eigen::Vector3d& hull,
                                                           std::vector<Eigen::Vector3d>& bodies) {
  for (std::size_t i = 0; i < m_.wires.size(); ++i) {
    const WireConnector& wire = m_.wires[i];
    const EndMotion from = end_motion(wire.from), to = end_motion(wire.to);
    wires_[i] = wire_state(wire.rope, from.position(wire.from.body), from.velocity(wire.from.body), to.position(wire.to.body),
                           to.velocity(wire.to.body), bilateral);
    const Eigen::Vector2d pull = wires_[i].tension * wires_[i].direction;  // on `from`, towards `to`
    add_end_force(wire.from, from, pull, boom, hull, bodies);
    add_end_force(wire.to, to, -pull, boom, hull, bodies);
  }
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::wire_stretches_minimal(double t, ConstRef z, Ref stretch) {
  set_minimal_state(t, z, z, false);
  wire_stretches(stretch);
}

template <fem::ElasticCoordinates Coords, bool Articulated>
void CraneEquationsOf<Coords, Articulated>::wire_stretches(Ref stretch) const {
  for (std::size_t i = 0; i < m_.wires.size(); ++i) {
    const WireConnector& wire = m_.wires[i];
    const EndMotion from = end_motion(wire.from), to = end_motion(wire.to);
    stretch(static_cast<Eigen::Index>(i)) = (to.position(wire.to.body) - from.position(wire.from.body)).norm() - wire.rope.unstretched_length;
  }
}

}  // namespace ffrf::multibody::detail
