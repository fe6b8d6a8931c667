// Inertia shape integrals (inertia invariants) of the beam in the floating frame, in the space
// of the free nodal DOFs q_n: with ū0(x) = (x, 0) the undeformed position in the body frame,
// S(x) the 2×n shape matrix on the free DOFs and Ĩ = [[0,-1],[1,0]] the planar skew operator,
//   mass           m    = ∫ρ dx
//   first_moment   s0   = ∫ρ ū0 dx                      (2)
//   second_moment  J0   = ∫ρ ū0ᵀū0 dx
//   shape_integral S̄    = ∫ρ S dx                       (2×n)      paper eq. 19.d M_Rf
//   u0_dot_shape   d    = ∫ρ ū0ᵀ S dx                   (1×n)      enters M_θθ
//   u0_cross_shape c    = ∫ρ ū0ᵀ Ĩ S dx                 (1×n)      enters M_θf
//   mass_ff        M_ff = ∫ρ SᵀS dx                     (n×n)      paper eq. 19.d
//   skew_ff        S̃    = ∫ρ Sᵀ Ĩ S dx                  (n×n, skew) enters M_θf, Q_v
// Integrated exactly element by element (4-point Gauss–Legendre: the integrands are polynomials
// of degree ≤ 6). Derivation: docs/theory.md §2.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::fem {

struct NodalInvariants {
  double mass = 0.0;
  Eigen::Vector2d first_moment = Eigen::Vector2d::Zero();
  double second_moment = 0.0;
  Eigen::Matrix<double, 2, Eigen::Dynamic> shape_integral;
  Eigen::RowVectorXd u0_dot_shape;
  Eigen::RowVectorXd u0_cross_shape;
  Eigen::SparseMatrix<double> mass_ff;
  Eigen::SparseMatrix<double> skew_ff;
};

NodalInvariants nodal_invariants(const BeamMesh& mesh, const DofMap& dofs);

// One element's share of the invariants above, over its six DOFs (u1, v1, φ1, u2, v2, φ2): their sum
// over the elements, restricted to the free DOFs, is the beam's.
struct ElementInvariants {
  Eigen::Matrix<double, 2, 6> shape_integral;  // ∫ρ S_e
  Eigen::Matrix<double, 1, 6> u0_dot_shape;    // ∫ρ ū0ᵀ S_e
  Eigen::Matrix<double, 1, 6> u0_cross_shape;  // ∫ρ ū0ᵀ Ĩ S_e
  Eigen::Matrix<double, 6, 6> mass;            // ∫ρ S_eᵀ S_e
  Eigen::Matrix<double, 6, 6> skew;            // ∫ρ S_eᵀ Ĩ S_e
};
ElementInvariants element_invariants(const BeamMesh& mesh, int element);

}  // namespace ffrf::fem
