// Sparse assembly of the element matrices of fem/beam_element.hpp over a BeamMesh, in full DOFs
// (3 per node) or directly on the free DOFs of a boundary condition.
#pragma once

#include <Eigen/SparseCore>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::fem {

using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, symmetric stored in full

SparseMatrix assemble_mass(const BeamMesh& mesh);
SparseMatrix assemble_stiffness(const BeamMesh& mesh);
// Geometric stiffness for a uniform axial force (tension > 0, compression < 0) [N].
SparseMatrix assemble_geometric_stiffness(const BeamMesh& mesh, double axial_force);
// Geometric stiffness for one axial force per element (size N).
SparseMatrix assemble_geometric_stiffness(const BeamMesh& mesh, const Eigen::VectorXd& element_axial_force);

// The same matrices restricted to the free DOFs of a boundary condition.
struct FreeMatrices {
  DofMap dofs;
  SparseMatrix mass;
  SparseMatrix stiffness;
};
FreeMatrices assemble_free(const BeamMesh& mesh, Boundary boundary);

}  // namespace ffrf::fem
