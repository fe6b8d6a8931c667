// Spectra 1.0 shift-invert for the generalized symmetric problem: the operator (K − σM)⁻¹M
// (SymShiftInvert, sparse LU) and the M-product (SparseSymMatProd) handed to
// SymGEigsShiftSolver, which transforms the Ritz values back to λ = σ + 1/ν.
#include "modal/spectra_shift_invert.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace ffrf::modal {

namespace {

// Spectra's convergence test is |residual| < tol · max(ε^(2/3), |ν|): tol = 0 would never pass,
// so "machine precision" is taken as a small multiple of ε.
constexpr double kMachineTolerance = 1e-14;

}  // namespace

EigenPairs solve_spectra_shift_invert(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                      const EigenRequest& request) {
  using ShiftInvert = Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse>;
  using MassProduct = Spectra::SparseSymMatProd<double>;
  using Solver = Spectra::SymGEigsShiftSolver<ShiftInvert, MassProduct, Spectra::GEigsMode::ShiftInvert>;

  validate_matrices(stiffness, mass);
  const Eigen::Index n = stiffness.rows();
  validate_request(request, n);
  const int ncv = resolve_ncv(request, n);

  ShiftInvert shift_invert(stiffness, mass);
  MassProduct mass_product(mass);
  try {
    Solver solver(shift_invert, mass_product, request.nev, ncv, request.sigma);
    solver.init();
    const double tolerance = request.tolerance > 0.0 ? request.tolerance : kMachineTolerance;
    const Eigen::Index converged =
        solver.compute(Spectra::SortRule::LargestMagn, request.max_iterations, tolerance, Spectra::SortRule::SmallestAlge);
    if (solver.info() != Spectra::CompInfo::Successful) {
      std::ostringstream why;
      why << "Spectra did not converge: " << converged << " converged of nev = " << request.nev << " after "
          << solver.num_iterations() << " iterations; increase max_iterations or ncv (now " << ncv << ")";
      throw EigenSolverError(why.str());
    }
    EigenPairs pairs{solver.eigenvalues(), solver.eigenvectors(), {}};
    pairs.stats.iterations = static_cast<int>(solver.num_iterations());
    pairs.stats.operator_applications = static_cast<int>(solver.num_operations());
    pairs.stats.converged = static_cast<int>(converged);
    normalize_and_sort(mass, pairs.eigenvalues, pairs.eigenvectors);
    return pairs;
  } catch (const std::invalid_argument&) {
    // SymShiftInvert::set_shift throws when the sparse LU of K − σM fails.
    throw EigenSolverError("Spectra: " + singular_shift_message(request.sigma));
  }
}

}  // namespace ffrf::modal
