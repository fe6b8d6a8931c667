// ARPACK (arpack-ng dsaupd/dseupd) in shift-invert mode 3 for K φ = λ M φ, B = M:
// OP = (K − σM)⁻¹ M, whose largest-magnitude eigenvalues ν = 1/(λ − σ) are the λ nearest σ.
// K − σM is factored once per compute() by a sparse LDLᵀ. The reverse-communication loop is in
// run_lanczos(); the operator products it asks for are the small functions beside it.
// ARPACK is not re-entrant: dsaupd/dseupd keep state between calls in Fortran SAVE variables (and
// its timing and debug COMMON blocks), so two threads inside it at once corrupt each other. Every
// call of compute() therefore runs its Lanczos loop and dseupd under one process-wide lock
// (arpack_lock() below): callers — a parallel sweep's workers — need not know.
#include "modal/arpack_shift_invert.hpp"

#include <arpack/arpack.hpp>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <sstream>
#include <vector>

namespace ffrf::modal {

namespace {

using ConstVectorMap = Eigen::Map<const Eigen::VectorXd>;
using VectorMap = Eigen::Map<Eigen::VectorXd>;

// ARPACK's iparam/ipntr entries, 0-based.
constexpr int kShiftStrategy = 0;      // iparam(1): 1 = exact shifts
constexpr int kMaxIterations = 2;      // iparam(3): in max iterations, out iterations taken
constexpr int kBlockSize = 3;          // iparam(4): must be 1
constexpr int kConverged = 4;          // iparam(5): converged Ritz values
constexpr int kMode = 6;               // iparam(7): 3 = shift-invert
constexpr int kOperatorProducts = 8;   // iparam(9): products with OP
constexpr int kInput = 0;              // ipntr(1): x in workd
constexpr int kOutput = 1;             // ipntr(2): y in workd
constexpr int kMassTimesInput = 2;     // ipntr(3): M x in workd (ido = 1)

// (K − σM)⁻¹: the factorization and the scratch vector M x, allocated once.
class ShiftInvertOperator {
 public:
  ShiftInvertOperator(const SparseMatrix& stiffness, const SparseMatrix& mass, double sigma)
      : mass_(mass), mass_times_x_(mass.rows()) {
    const SparseMatrix shifted = stiffness - sigma * mass;
    factor_.compute(shifted);
    // Eigen reports an exact zero pivot; a tiny pivot from round-off is harmless for shift-invert
    // (the error lies along the wanted eigenvector), so only zero or non-finite pivots fail.
    factored_ = factor_.info() == Eigen::Success && factor_.vectorD().allFinite() &&
                (factor_.vectorD().array() != 0.0).all();
  }

  bool factored() const { return factored_; }

  // y = (K − σM)⁻¹ M x  (ido = −1: the starting phase)
  void apply_to_unmassed(const double* x, double* y) {
    mass_times_x_.noalias() = mass_ * ConstVectorMap(x, mass_.rows());
    VectorMap(y, mass_.rows()) = factor_.solve(mass_times_x_);
  }

  // y = (K − σM)⁻¹ b with b = M x supplied by ARPACK  (ido = 1)
  void apply_to_massed(const double* mass_times_x, double* y) {
    VectorMap(y, mass_.rows()) = factor_.solve(ConstVectorMap(mass_times_x, mass_.rows()));
  }

 private:
  const SparseMatrix& mass_;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> factor_;
  Eigen::VectorXd mass_times_x_;
  bool factored_ = false;
};

// y = M x  (ido = 2: the B-inner products)
void apply_mass(const SparseMatrix& mass, const double* x, double* y) {
  VectorMap(y, mass.rows()).noalias() = mass * ConstVectorMap(x, mass.rows());
}

// A fixed, non-symmetric starting vector in [0.5, 1.5): reproducible runs. Not all ones, which is
// symmetric and so M-orthogonal to every antisymmetric mode of a symmetric structure.
void fill_starting_vector(std::vector<double>& resid) {
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  for (double& value : resid) {
    state += 0x9E3779B97F4A7C15ULL;  // splitmix64
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    value = 0.5 + static_cast<double>(z >> 11) * 0x1.0p-53;
  }
}

// The work arrays of dsaupd/dseupd for one problem size, allocated once per compute().
struct LanczosWorkspace {
  LanczosWorkspace(int n_, int nev_, int ncv_)
      : n(n_), nev(nev_), ncv(ncv_), resid(static_cast<std::size_t>(n_)),
        basis(static_cast<std::size_t>(n_) * static_cast<std::size_t>(ncv_)),
        workd(3 * static_cast<std::size_t>(n_)),
        lworkl(ncv_ * (ncv_ + 8)), workl(static_cast<std::size_t>(lworkl)) {}
  int n, nev, ncv;
  std::vector<double> resid, basis, workd;
  int lworkl;
  std::vector<double> workl;
  int iparam[11] = {};
  int ipntr[11] = {};
};

std::string saupd_message(int info, const LanczosWorkspace& work, int max_iterations) {
  std::ostringstream why;
  switch (info) {
    case 1:
      why << "maximum number of iterations reached (" << max_iterations << "): "
          << work.iparam[kConverged] << " converged of nev = " << work.nev
          << "; increase max_iterations or ncv (now " << work.ncv << ")";
      break;
    case 3:
      why << "no shifts could be applied during an implicit restart; increase ncv (now " << work.ncv
          << ") relative to nev = " << work.nev;
      break;
    case -3:
      why << "ncv = " << work.ncv << " must satisfy nev < ncv <= n (nev = " << work.nev
          << ", n = " << work.n << ")";
      break;
    case -8:
      why << "the LAPACK tridiagonal eigen solver (dsteqr) failed inside dsaupd; try another ncv";
      break;
    case -9:
      why << "the starting vector is zero";
      break;
    case -9999:
      why << "could not build a Lanczos factorization (size " << work.iparam[kConverged]
          << " reached); check that M is positive definite and that σ is not an eigenvalue";
      break;
    default:
      why << "dsaupd returned info = " << info << " (invalid argument; see the dsaupd documentation)";
  }
  return why.str();
}

std::string seupd_message(int info) {
  std::ostringstream why;
  switch (info) {
    case -8:
    case -9:
      why << "the LAPACK eigen solver failed while dseupd formed the Ritz vectors (info = " << info << ")";
      break;
    case -14:
      why << "dseupd: dsaupd found no eigenvalue to sufficient accuracy; loosen the tolerance or increase ncv";
      break;
    case -17:
      why << "dseupd counted a different number of converged Ritz values than dsaupd (internal error)";
      break;
    default:
      why << "dseupd returned info = " << info << " (see the dseupd documentation)";
  }
  return why.str();
}

ArpackInfo classify(int saupd_info) {
  if (saupd_info == 0) return ArpackInfo::successful;
  if (saupd_info == 1 || saupd_info == 3) return ArpackInfo::not_converging;
  return ArpackInfo::numerical_issue;
}

// The one lock around ARPACK's SAVE state (see the file comment).
std::mutex& arpack_lock() {
  static std::mutex lock;
  return lock;
}

// The reverse-communication loop of dsaupd: answers every request with the operator products
// above until ARPACK reports convergence (ido = 99). Returns dsaupd's info.
int run_lanczos(LanczosWorkspace& work, ShiftInvertOperator& shift_invert, const SparseMatrix& mass,
                double tolerance) {
  int ido = 0;
  int info = 1;  // use the starting vector in resid
  for (;;) {
    arpack::saupd(ido, arpack::bmat::generalized, work.n, arpack::which::largest_magnitude, work.nev,
                  tolerance, work.resid.data(), work.ncv, work.basis.data(), work.n, work.iparam,
                  work.ipntr, work.workd.data(), work.workl.data(), work.lworkl, info);
    const double* x = work.workd.data() + work.ipntr[kInput] - 1;
    double* y = work.workd.data() + work.ipntr[kOutput] - 1;
    switch (ido) {
      case -1:
        shift_invert.apply_to_unmassed(x, y);
        break;
      case 1:
        shift_invert.apply_to_massed(work.workd.data() + work.ipntr[kMassTimesInput] - 1, y);
        break;
      case 2:
        apply_mass(mass, x, y);
        break;
      default:  // 99 = done (or an error in info)
        return info;
    }
  }
}

}  // namespace

ArpackShiftInvert::ArpackShiftInvert(const SparseMatrix& stiffness, const SparseMatrix& mass)
    : stiffness_(stiffness), mass_(mass) {
  validate_matrices(stiffness_, mass_);
}

int ArpackShiftInvert::compute(int nev, int ncv, double sigma, double tolerance, int max_iterations) {
  const EigenRequest request{nev, ncv, sigma, tolerance, max_iterations};
  const Eigen::Index n = stiffness_.rows();
  validate_request(request, n);
  if (n > std::numeric_limits<int>::max() / 3) {
    throw EigenSolverError("n = " + std::to_string(n) + " is too large for 32-bit ARPACK indices");
  }
  eigenvalues_.resize(0);
  eigenvectors_.resize(0, 0);
  stats_ = EigenStats{};

  ShiftInvertOperator shift_invert(stiffness_, mass_, sigma);
  if (!shift_invert.factored()) {
    info_ = ArpackInfo::numerical_issue;
    message_ = singular_shift_message(sigma);
    return 0;
  }

  LanczosWorkspace work(static_cast<int>(n), nev, resolve_ncv(request, n));
  fill_starting_vector(work.resid);
  work.iparam[kShiftStrategy] = 1;
  work.iparam[kMaxIterations] = max_iterations;
  work.iparam[kBlockSize] = 1;
  work.iparam[kMode] = 3;

  // From the first dsaupd call to dseupd, ARPACK's SAVE variables belong to this problem.
  const std::lock_guard<std::mutex> arpack_state(arpack_lock());
  const int saupd_info = run_lanczos(work, shift_invert, mass_, tolerance);
  stats_.iterations = work.iparam[kMaxIterations];
  stats_.operator_applications = work.iparam[kOperatorProducts];
  stats_.converged = work.iparam[kConverged];
  info_ = classify(saupd_info);
  if (info_ != ArpackInfo::successful) {
    message_ = saupd_message(saupd_info, work, max_iterations);
    return saupd_info == 1 ? stats_.converged : 0;
  }

  // Mode 3: dseupd returns λ = σ + 1/ν directly, and M-orthonormal Ritz vectors.
  std::vector<int> select(static_cast<std::size_t>(work.ncv));
  eigenvalues_.resize(nev);
  eigenvectors_.resize(n, nev);
  int seupd_info = 0;
  arpack::seupd(1, arpack::howmny::ritz_vectors, select.data(), eigenvalues_.data(), eigenvectors_.data(),
                work.n, sigma, arpack::bmat::generalized, work.n, arpack::which::largest_magnitude, nev,
                tolerance, work.resid.data(), work.ncv, work.basis.data(), work.n, work.iparam, work.ipntr,
                work.workd.data(), work.workl.data(), work.lworkl, seupd_info);
  if (seupd_info != 0) {
    info_ = ArpackInfo::numerical_issue;
    message_ = seupd_message(seupd_info);
    eigenvalues_.resize(0);
    eigenvectors_.resize(0, 0);
    return 0;
  }
  normalize_and_sort(mass_, eigenvalues_, eigenvectors_);
  message_ = "converged: " + std::to_string(stats_.converged) + " of nev = " + std::to_string(nev) + " in " +
             std::to_string(stats_.iterations) + " iterations";
  return stats_.converged;
}

}  // namespace ffrf::modal
