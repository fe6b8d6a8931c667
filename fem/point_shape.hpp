// Shape rows of a material point of the beam and nodal load vectors.
// The elastic displacement of the point at axial coordinate x is ū_f(x) = S(x) q_n and its small
// rotation is φ(x) = ∂v/∂x = R(x) q_n (paper eq. 4 on the element that holds x). By virtual work
// (paper eq. 13), a body-frame force F at x has the nodal load S(x)ᵀF and a moment M has R(x)ᵀM.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::fem {

struct PointShape {
  Eigen::SparseMatrix<double, Eigen::RowMajor> displacement;  // 2×n: rows (u, v)
  Eigen::SparseMatrix<double, Eigen::RowMajor> rotation;      // 1×n
};

// x in [0, L]; throws std::out_of_range otherwise.
PointShape point_shape(const BeamMesh& mesh, const DofMap& dofs, double x);

// Nodal load vector (free DOFs) of a body-frame force (axial, transverse) [N] and a moment [N m]
// applied at x.
Eigen::VectorXd point_load(const BeamMesh& mesh, const DofMap& dofs, double x,
                           const Eigen::Vector2d& force, double moment);

// Nodal load vector (free DOFs) of a uniform distributed load (axial, transverse) [N/m].
Eigen::VectorXd distributed_load(const BeamMesh& mesh, const DofMap& dofs, const Eigen::Vector2d& load_per_length);

}  // namespace ffrf::fem
