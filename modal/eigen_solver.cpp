// Generalized symmetric eigenproblem K φ = ω² M φ: names of the solvers, checks of a request
// against the problem size, the common post-processing (M-normalization, sign, ascending order)
// and the dispatch to ARPACK shift-invert, Spectra shift-invert or the dense reference.
#include "modal/eigen_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "modal/arpack_shift_invert.hpp"
#include "modal/dense_eigen.hpp"
#include "modal/spectra_shift_invert.hpp"

namespace ffrf::modal {

namespace {

constexpr std::array<std::pair<EigenSolverKind, std::string_view>, 3> kSolverNames{{
    {EigenSolverKind::arpack, "arpack"},
    {EigenSolverKind::dense, "dense"},
    {EigenSolverKind::spectra, "spectra"},
}};

// Index of the entry that fixes the sign: the first entry whose magnitude is within a relative
// 1e-6 of the largest. Taking the first of near-equal entries (symmetric modes have pairs of
// equal magnitude) makes the sign the same whichever solver produced the vector.
Eigen::Index sign_reference_entry(const Eigen::Ref<const Eigen::VectorXd>& vector) {
  const double largest = vector.cwiseAbs().maxCoeff();
  const double threshold = (1.0 - 1e-6) * largest;
  for (Eigen::Index i = 0; i < vector.size(); ++i) {
    if (std::abs(vector[i]) >= threshold) return i;
  }
  return 0;
}

}  // namespace

std::string_view to_string(EigenSolverKind kind) {
  for (const auto& [k, name] : kSolverNames) {
    if (k == kind) return name;
  }
  return "unknown";
}

std::optional<EigenSolverKind> parse_eigen_solver(std::string_view text) {
  for (const auto& [kind, name] : kSolverNames) {
    if (name == text) return kind;
  }
  return std::nullopt;
}

std::string eigen_solver_choices() {
  std::string choices;
  for (const auto& [kind, name] : kSolverNames) {
    if (!choices.empty()) choices += '|';
    choices += name;
  }
  return choices;
}

int resolve_ncv(const EigenRequest& request, Eigen::Index n) {
  if (request.ncv != 0) return request.ncv;
  const Eigen::Index automatic = std::min<Eigen::Index>(n, std::max(2 * request.nev + 1, 20));
  return static_cast<int>(automatic);
}

void validate_request(const EigenRequest& request, Eigen::Index n) {
  std::ostringstream why;
  if (n < 2) {
    why << "the eigenproblem has n = " << n
        << " degrees of freedom; at least 2 are needed (refine the mesh or free more DOFs)";
  } else if (request.nev < 1 || request.nev > n - 1) {
    why << "nev = " << request.nev << " is outside the valid range 1.." << n - 1
        << " for n = " << n << " degrees of freedom; ask for fewer modes or refine the mesh";
  } else if (const int ncv = resolve_ncv(request, n); ncv <= request.nev || ncv > n) {
    why << "ncv = " << ncv << " must satisfy nev < ncv <= n, i.e. lie in " << request.nev + 1 << ".." << n
        << "; use ncv = 0 for the automatic choice min(n, max(2 nev + 1, 20))";
  } else if (!std::isfinite(request.sigma)) {
    why << "shift sigma = " << request.sigma << " is not finite; give a finite shift in rad²/s²";
  } else if (!(request.tolerance >= 0.0) || !std::isfinite(request.tolerance)) {
    why << "tolerance = " << request.tolerance
        << " must be a finite number >= 0 (0 = machine precision)";
  } else if (request.max_iterations < 1) {
    why << "max_iterations = " << request.max_iterations << " must be >= 1; try the default 3000";
  } else {
    return;
  }
  throw EigenSolverError(why.str());
}

void validate_matrices(const SparseMatrix& stiffness, const SparseMatrix& mass) {
  std::ostringstream why;
  if (stiffness.rows() != stiffness.cols()) {
    why << "stiffness matrix K is " << stiffness.rows() << " x " << stiffness.cols()
        << "; it must be square";
  } else if (mass.rows() != mass.cols()) {
    why << "mass matrix M is " << mass.rows() << " x " << mass.cols() << "; it must be square";
  } else if (stiffness.rows() != mass.rows()) {
    why << "K is " << stiffness.rows() << " x " << stiffness.cols() << " but M is " << mass.rows()
        << " x " << mass.cols() << "; both must be assembled on the same free DOFs";
  } else if (stiffness.rows() == 0) {
    why << "K and M are empty (0 x 0); assemble a mesh with free DOFs first";
  } else {
    return;
  }
  throw EigenSolverError(why.str());
}

std::string singular_shift_message(double sigma) {
  std::ostringstream why;
  why << "K − σM is singular at σ = " << sigma
      << ": choose a shift that is not an eigenvalue (a negative shift for free–free beams); on a very "
         "fine mesh a small |σ| is rounded away next to K's large entries, so try a larger |σ| or fewer elements";
  return why.str();
}

void normalize_and_sort(const SparseMatrix& mass, Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& eigenvectors) {
  const Eigen::Index count = eigenvalues.size();
  if (eigenvectors.cols() != count || eigenvectors.rows() != mass.rows()) {
    std::ostringstream why;
    why << "eigenvector matrix is " << eigenvectors.rows() << " x " << eigenvectors.cols() << " but "
        << mass.rows() << " x " << count << " was expected (n x number of eigenvalues)";
    throw EigenSolverError(why.str());
  }
  Eigen::VectorXd mass_times_vector(mass.rows());
  for (Eigen::Index j = 0; j < count; ++j) {
    auto vector = eigenvectors.col(j);
    mass_times_vector.noalias() = mass * vector;
    const double modal_mass = vector.dot(mass_times_vector);
    if (!(modal_mass > 0.0) || !std::isfinite(modal_mass)) {
      std::ostringstream why;
      why << "eigenvector " << j << " has modal mass φᵀMφ = " << modal_mass
          << "; M must be positive definite on the free DOFs";
      throw EigenSolverError(why.str());
    }
    vector /= std::sqrt(modal_mass);
    if (vector[sign_reference_entry(vector)] < 0.0) vector = -vector;
  }

  std::vector<Eigen::Index> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return eigenvalues[a] < eigenvalues[b]; });
  Eigen::VectorXd sorted_values(count);
  Eigen::MatrixXd sorted_vectors(eigenvectors.rows(), count);
  for (Eigen::Index j = 0; j < count; ++j) {
    const Eigen::Index from = order[static_cast<std::size_t>(j)];
    sorted_values[j] = eigenvalues[from];
    sorted_vectors.col(j) = eigenvectors.col(from);
  }
  eigenvalues = std::move(sorted_values);
  eigenvectors = std::move(sorted_vectors);
}

namespace {

EigenPairs solve_with_arpack(const SparseMatrix& stiffness, const SparseMatrix& mass, const EigenRequest& request) {
  ArpackShiftInvert solver(stiffness, mass);
  solver.compute(request.nev, resolve_ncv(request, stiffness.rows()), request.sigma, request.tolerance,
                 request.max_iterations);
  if (solver.info() != ArpackInfo::successful) throw EigenSolverError("ARPACK: " + solver.info_message());
  return EigenPairs{solver.eigenvalues(), solver.eigenvectors(), solver.stats()};
}

}  // namespace

EigenPairs solve_generalized(const SparseMatrix& stiffness, const SparseMatrix& mass,
                             const EigenRequest& request, EigenSolverKind kind) {
  validate_matrices(stiffness, mass);
  validate_request(request, stiffness.rows());
  switch (kind) {
    case EigenSolverKind::arpack:
      return solve_with_arpack(stiffness, mass, request);
    case EigenSolverKind::dense:
      return solve_dense(stiffness, mass, request);
    case EigenSolverKind::spectra:
      return solve_spectra_shift_invert(stiffness, mass, request);
  }
  throw EigenSolverError("unknown eigen solver kind; choose one of " + eigen_solver_choices());
}

}  // namespace ffrf::modal
