// Sparse assembly of frame-element matrices: element e couples nodes e and e + 1, i.e. full DOFs
// 3e .. 3e + 5, so the assembled matrices are banded with half-bandwidth 5.
#include "fem/assembly.hpp"

#include <vector>

#include "fem/beam_element.hpp"

namespace ffrf::fem {
namespace {

template <class ElementFn>
SparseMatrix assemble(const BeamMesh& mesh, ElementFn element_matrix) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(element_dofs * element_dofs * mesh.element_count));
  for (int e = 0; e < mesh.element_count; ++e) {
    const ElementMatrix local = element_matrix(e);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        if (local(i, j) != 0.0) entries.emplace_back(node_dofs * e + i, node_dofs * e + j, local(i, j));
      }
    }
  }
  SparseMatrix global(mesh.full_dof_count(), mesh.full_dof_count());
  global.setFromTriplets(entries.begin(), entries.end());
  return global;
}

}  // namespace

SparseMatrix assemble_mass(const BeamMesh& mesh) {
  const ElementMatrix local = element_mass(mesh.section, mesh.element_length());
  return assemble(mesh, [&](int) { return local; });
}

SparseMatrix assemble_stiffness(const BeamMesh& mesh) {
  const ElementMatrix local = element_stiffness(mesh.section, mesh.element_length());
  return assemble(mesh, [&](int) { return local; });
}

SparseMatrix assemble_geometric_stiffness(const BeamMesh& mesh, double axial_force) {
  const ElementMatrix local = element_geometric_stiffness(axial_force, mesh.element_length());
  return assemble(mesh, [&](int) { return local; });
}

SparseMatrix assemble_geometric_stiffness(const BeamMesh& mesh, const Eigen::VectorXd& element_axial_force) {
  const double l = mesh.element_length();
  return assemble(mesh, [&](int e) { return element_geometric_stiffness(element_axial_force(e), l); });
}

FreeMatrices assemble_free(const BeamMesh& mesh, Boundary boundary) {
  FreeMatrices out;
  out.dofs = make_dof_map(mesh, boundary);
  out.mass = restrict_to_free(assemble_mass(mesh), out.dofs);
  out.stiffness = restrict_to_free(assemble_stiffness(mesh), out.dofs);
  return out;
}

}  // namespace ffrf::fem
