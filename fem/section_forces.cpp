// Section forces and fibre stresses from element deformations (see header).
#include "fem/section_forces.hpp"

#include <cmath>

namespace ffrf::fem {

void section_forces_full(const BeamMesh& mesh, const Eigen::VectorXd& full, SectionForces& out) {
  const int nodes = mesh.node_count();
  out.position.resize(nodes);
  out.axial_force.setZero(nodes);
  out.bending_moment.setZero(nodes);
  const double l = mesh.element_length();
  const double axial = mesh.section.axial_rigidity(), bending = mesh.section.bending_rigidity();
  for (int node = 0; node < nodes; ++node) out.position(node) = mesh.node_position(node);
  for (int e = 0; e < mesh.element_count; ++e) {
    const auto q = full.segment<element_dofs>(node_dofs * e);
    const double force = axial * (q(3) - q(0)) / l;
    // κ at ξ = 0 and ξ = 1.
    const double start = (-6.0 * q(1) - 4.0 * l * q(2) + 6.0 * q(4) - 2.0 * l * q(5)) / (l * l);
    const double end = (6.0 * q(1) + 2.0 * l * q(2) - 6.0 * q(4) + 4.0 * l * q(5)) / (l * l);
    // Each interior node gets half of each neighbour's end value; the two ends their own.
    const double start_weight = e == 0 ? 1.0 : 0.5, end_weight = e == mesh.element_count - 1 ? 1.0 : 0.5;
    out.axial_force(e) += start_weight * force;
    out.axial_force(e + 1) += end_weight * force;
    out.bending_moment(e) += start_weight * bending * start;
    out.bending_moment(e + 1) += end_weight * bending * end;
  }
  // The element's force is its mean over the element (the value at its middle when N is linear): at
  // the two ends, extrapolate from the two nearest elements instead of taking half an element's lag.
  const int n = mesh.element_count;
  if (n >= 2) {
    const auto element_force = [&](int e) { return axial * (full(node_dofs * (e + 1)) - full(node_dofs * e)) / l; };
    out.axial_force(0) = 1.5 * element_force(0) - 0.5 * element_force(1);
    out.axial_force(n) = 1.5 * element_force(n - 1) - 0.5 * element_force(n - 2);
  }
}

void section_forces_from_end_forces(const BeamMesh& mesh, const std::vector<ElementForces>& end_forces, SectionForces& out) {
  const int nodes = mesh.node_count(), n = mesh.element_count;
  out.position.resize(nodes);
  out.axial_force.setZero(nodes);
  out.bending_moment.setZero(nodes);
  for (int node = 0; node < nodes; ++node) out.position(node) = mesh.node_position(node);
  for (int e = 0; e < n; ++e) {
    const ElementForces& r = end_forces[static_cast<std::size_t>(e)];
    const double start_weight = e == 0 ? 1.0 : 0.5, end_weight = e == n - 1 ? 1.0 : 0.5;
    out.axial_force(e) -= start_weight * r(0);
    out.bending_moment(e) -= start_weight * r(2);
    out.axial_force(e + 1) += end_weight * r(3);
    out.bending_moment(e + 1) += end_weight * r(5);
  }
}

SectionForces section_forces(const BeamMesh& mesh, const DofMap& dofs, const Eigen::VectorXd& free_displacements) {
  SectionForces out;
  section_forces_full(mesh, extend_to_full(free_displacements, dofs), out);
  return out;
}

FibreStress fibre_stress(const BeamSection& section, double fibre_distance, double axial_force, double bending_moment) {
  const double membrane = axial_force / section.area;
  const double bending = bending_moment * fibre_distance / section.second_moment;
  return {membrane - bending, membrane + bending};
}

double two_flange_fibre_distance(const BeamSection& section) { return std::sqrt(section.second_moment / section.area); }

}  // namespace ffrf::fem
