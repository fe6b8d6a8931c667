// Dense reference solver for K φ = ω² M φ: Eigen's GeneralizedSelfAdjointEigenSolver on the
// densified K and M (Cholesky of M, then a symmetric tridiagonal QR), all n eigenpairs, of which
// the nev nearest the shift σ are returned ascending and M-normalized. O(n²) memory and O(n³)
// time: refused above dense_eigen_size_limit DOFs.
#pragma once

#include <Eigen/Core>

#include "modal/eigen_solver.hpp"

namespace ffrf::modal {

inline constexpr Eigen::Index dense_eigen_size_limit = 6000;

// Throws EigenSolverError for an invalid request, n > dense_eigen_size_limit or an M that is not
// positive definite.
EigenPairs solve_dense(const SparseMatrix& stiffness, const SparseMatrix& mass, const EigenRequest& request);

}  // namespace ffrf::modal
