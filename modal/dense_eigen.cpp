// Dense reference solver: densify K and M, solve the full generalized symmetric problem with
// Eigen::GeneralizedSelfAdjointEigenSolver, keep the nev eigenvalues nearest σ (the same pairs a
// shift-invert Krylov solver returns), refine each by its Rayleigh quotient, ascending and
// M-normalized.
#include "modal/dense_eigen.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>
#include "linalg/dense_solvers.hpp"

namespace ffrf::modal {

namespace {

// φᵀKφ / φᵀMφ with the sparse matrices. The dense QR's eigenvalues carry an absolute error
// ~ ε·λ_max, i.e. a relative error ~ ε·λ_max/λ₁ (1e-8 for a 40-element beam) on the low modes;
// the Rayleigh quotient of the computed vector is accurate to the square of the vector's error.
double rayleigh_quotient(const SparseMatrix& stiffness, const SparseMatrix& mass,
                         const Eigen::Ref<const Eigen::VectorXd>& vector) {
  return vector.dot(stiffness * vector) / vector.dot(mass * vector);
}

}  // namespace

EigenPairs solve_dense(const SparseMatrix& stiffness, const SparseMatrix& mass, const EigenRequest& request) {
  validate_matrices(stiffness, mass);
  const Eigen::Index n = stiffness.rows();
  validate_request(request, n);
  if (n > dense_eigen_size_limit) {
    std::ostringstream why;
    why << "n = " << n << " DOFs is above the dense limit of " << dense_eigen_size_limit
        << ": the dense solver needs n² memory and n³ time; use arpack";
    throw EigenSolverError(why.str());
  }

  const Eigen::MatrixXd dense_stiffness(stiffness);
  const Eigen::MatrixXd dense_mass(mass);
  if (Eigen::LLT<Eigen::MatrixXd> mass_cholesky(dense_mass); mass_cholesky.info() != Eigen::Success) {
    throw EigenSolverError("dense solver: the mass matrix M is not positive definite (Cholesky failed); "
                           "check the density and the boundary condition");
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense_stiffness, dense_mass,
                                                                         Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (solver.info() != Eigen::Success) {
    throw EigenSolverError("dense solver: the symmetric QR iteration did not converge");
  }

  // The nev eigenvalues nearest σ.
  const Eigen::VectorXd& all_values = solver.eigenvalues();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  const auto distance = [&](Eigen::Index i) { return std::abs(all_values[i] - request.sigma); };
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return distance(a) < distance(b); });

  EigenPairs pairs;
  pairs.eigenvalues.resize(request.nev);
  pairs.eigenvectors.resize(n, request.nev);
  for (Eigen::Index j = 0; j < request.nev; ++j) {
    const Eigen::Index from = order[static_cast<std::size_t>(j)];
    pairs.eigenvectors.col(j) = solver.eigenvectors().col(from);
    pairs.eigenvalues[j] = rayleigh_quotient(stiffness, mass, pairs.eigenvectors.col(j));
  }
  normalize_and_sort(mass, pairs.eigenvalues, pairs.eigenvectors);
  pairs.stats.converged = request.nev;
  return pairs;
}

}  // namespace ffrf::modal
