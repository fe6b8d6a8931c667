// The beam in nodal space, built once per scene: mesh, boundary condition, free-DOF map, the
// assembled free mass, stiffness and unit geometric stiffness (K_g for a 1 N axial tension), and
// the inertia shape integrals. Constant data shared by the nodal and modal elastic coordinates.
#pragma once

#include <Eigen/SparseCore>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"
#include "fem/shape_integrals.hpp"

namespace ffrf::fem {

struct BeamModel {
  BeamMesh mesh;
  Boundary boundary;
  DofMap dofs;
  Eigen::SparseMatrix<double> mass;                      // = invariants.mass_ff
  Eigen::SparseMatrix<double> stiffness;
  Eigen::SparseMatrix<double> unit_geometric_stiffness;  // K_g(P = 1 N tension)
  NodalInvariants invariants;
};

// Validates the mesh (throws std::invalid_argument) and assembles everything.
BeamModel make_beam_model(const BeamMesh& mesh, Boundary boundary);

}  // namespace ffrf::fem
