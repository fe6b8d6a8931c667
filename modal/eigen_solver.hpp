// Generalized symmetric eigenproblem K φ = ω² M φ (K symmetric, M symmetric positive definite):
// the common request/result types and one entry point that dispatches to the ARPACK shift-invert
// solver (production), Spectra's shift-invert solver (cross-check) or a dense Eigen solver
// (reference for small problems). Eigen solvers see only matrices, never the beam.
// All solvers return the nev eigenvalues nearest the shift σ, ascending, with eigenvectors
// M-normalized (φᵀMφ = 1) and their sign fixed so that the entry of largest magnitude is > 0
// (of entries equal in magnitude to a relative 1e-6, the first one, so that ± pairs of equal
// size in symmetric modes give the same sign whichever solver ran).
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ffrf::modal {

using SparseMatrix = Eigen::SparseMatrix<double>;

enum class EigenSolverKind { arpack, dense, spectra };
std::string_view to_string(EigenSolverKind kind);
std::optional<EigenSolverKind> parse_eigen_solver(std::string_view text);
std::string eigen_solver_choices();  // "arpack|dense|spectra"

struct EigenRequest {
  int nev = 6;             // number of eigenpairs wanted, 1 <= nev < n
  int ncv = 0;             // Krylov subspace size; 0 = automatic: min(n, max(2 nev + 1, 20))
  double sigma = 0.0;      // shift [rad²/s²]; K − σM must be nonsingular
  double tolerance = 0.0;  // relative accuracy of the Ritz values; 0 = machine precision
  int max_iterations = 3000;
};

struct EigenStats {
  int iterations = 0;             // Arnoldi/Lanczos restarts (0 for dense)
  int operator_applications = 0;  // products with (K − σM)⁻¹M
  int converged = 0;              // converged Ritz values
};

struct EigenPairs {
  Eigen::VectorXd eigenvalues;   // ω² ascending [rad²/s²]
  Eigen::MatrixXd eigenvectors;  // n × nev, M-normalized columns
  EigenStats stats;
};

// Thrown when a request is invalid or a solver fails; what() says which, why, and what to try.
class EigenSolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

EigenPairs solve_generalized(const SparseMatrix& stiffness, const SparseMatrix& mass,
                             const EigenRequest& request, EigenSolverKind kind);

// Helpers shared by the solvers: checks nev/ncv against n (throws EigenSolverError),
// M-normalizes, fixes signs and sorts pairs ascending.
int resolve_ncv(const EigenRequest& request, Eigen::Index n);
void validate_request(const EigenRequest& request, Eigen::Index n);
// Checks that K and M are square, of the same size and non-empty (throws EigenSolverError).
void validate_matrices(const SparseMatrix& stiffness, const SparseMatrix& mass);
// The message shared by the shift-invert solvers when K − σM cannot be factored.
std::string singular_shift_message(double sigma);
void normalize_and_sort(const SparseMatrix& mass, Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors);

}  // namespace ffrf::modal
