// Tests of the generalized symmetric eigen solvers (ARPACK shift-invert, Spectra, dense) against
// closed-form spectra (spring–mass chains, Euler–Bernoulli cantilever and free–free beam), against
// each other, against M-orthonormality, and for the errors they raise on bad requests.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fem/assembly.hpp"
#include "modal/arpack_shift_invert.hpp"
#include "modal/dense_eigen.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/spectra_shift_invert.hpp"

namespace {

using ffrf::modal::EigenPairs;
using ffrf::modal::EigenRequest;
using ffrf::modal::EigenSolverError;
using ffrf::modal::EigenSolverKind;
using ffrf::modal::SparseMatrix;
using ffrf::modal::solve_generalized;

constexpr EigenSolverKind kAllSolvers[] = {EigenSolverKind::arpack, EigenSolverKind::dense, EigenSolverKind::spectra};

SparseMatrix tridiagonal(int n, double diagonal, double off_diagonal) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, diagonal);
    if (i + 1 < n) {
      entries.emplace_back(i, i + 1, off_diagonal);
      entries.emplace_back(i + 1, i, off_diagonal);
    }
  }
  SparseMatrix matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

// A fixed–fixed chain of n masses joined by n + 1 springs k. Both the stiffness tridiag(−k, 2k, −k)
// and the mass tridiag(b, a, b) share the eigenvectors sin(i jπ/(n+1)), so
// ω_j² = k (2 − 2 cos θ_j) / (a + 2 b cos θ_j), θ_j = jπ/(n+1).
struct SpringMassChain {
  int n;
  double spring;
  double mass_diagonal;
  double mass_off_diagonal;  // 0 = lumped; (m/6)·(4, 1) = consistent mass of linear bars

  SparseMatrix stiffness() const { return tridiagonal(n, 2.0 * spring, -spring); }
  SparseMatrix mass() const { return tridiagonal(n, mass_diagonal, mass_off_diagonal); }
  double eigenvalue(int j) const {  // j = 1..n, ascending
    const double theta = j * std::numbers::pi / (n + 1);
    return spring * (2.0 - 2.0 * std::cos(theta)) / (mass_diagonal + 2.0 * mass_off_diagonal * std::cos(theta));
  }
};

constexpr SpringMassChain kLumpedChain{60, 1.0e4, 2.0, 0.0};
constexpr SpringMassChain kConsistentChain{60, 1.0e4, 2.0 * 4.0 / 6.0, 2.0 / 6.0};

double relative_difference(double value, double reference) { return std::abs(value - reference) / std::abs(reference); }

// The lumped chain: the lowest 6 of (2k/m)(1 − cos jπ/(n+1)), every solver, 1e-10 relative.
TEST(EigenSolvers, LumpedChainMatchesClosedForm) {
  const SparseMatrix stiffness = kLumpedChain.stiffness();
  const SparseMatrix mass = kLumpedChain.mass();
  for (const EigenSolverKind kind : kAllSolvers) {
    const EigenPairs pairs = solve_generalized(stiffness, mass, EigenRequest{.nev = 6}, kind);
    ASSERT_EQ(pairs.eigenvalues.size(), 6) << to_string(kind);
    for (int j = 1; j <= 6; ++j) {
      const double exact = 2.0 * kLumpedChain.spring / kLumpedChain.mass_diagonal *
                           (1.0 - std::cos(j * std::numbers::pi / (kLumpedChain.n + 1)));
      EXPECT_LT(relative_difference(pairs.eigenvalues[j - 1], exact), 1e-10) << to_string(kind) << " mode " << j;
    }
  }
}

// A consistent (non-diagonal) mass and a shift inside the spectrum: the 5 eigenvalues nearest σ.
TEST(EigenSolvers, ConsistentChainInteriorShiftReturnsNearestEigenvalues) {
  const SparseMatrix stiffness = kConsistentChain.stiffness();
  const SparseMatrix mass = kConsistentChain.mass();
  // σ between modes 20 and 21, nearer 20: the nearest five are modes 18..22.
  const double sigma = 0.6 * kConsistentChain.eigenvalue(20) + 0.4 * kConsistentChain.eigenvalue(21);
  for (const EigenSolverKind kind : kAllSolvers) {
    const EigenPairs pairs = solve_generalized(stiffness, mass, EigenRequest{.nev = 5, .sigma = sigma}, kind);
    ASSERT_EQ(pairs.eigenvalues.size(), 5) << to_string(kind);
    for (int i = 0; i < 5; ++i) {
      EXPECT_LT(relative_difference(pairs.eigenvalues[i], kConsistentChain.eigenvalue(18 + i)), 1e-10)
          << to_string(kind) << " mode " << 18 + i;
    }
  }
}

// ΦᵀMΦ = I, ΦᵀKΦ = diag(ω²) and the sign convention, for every solver.
TEST(EigenSolvers, EigenvectorsAreMassOrthonormalWithFixedSign) {
  const SparseMatrix stiffness = kConsistentChain.stiffness();
  const SparseMatrix mass = kConsistentChain.mass();
  for (const EigenSolverKind kind : kAllSolvers) {
    const EigenPairs pairs = solve_generalized(stiffness, mass, EigenRequest{.nev = 8}, kind);
    const Eigen::MatrixXd& modes = pairs.eigenvectors;
    const Eigen::MatrixXd modal_mass = modes.transpose() * (mass * modes);
    const Eigen::MatrixXd modal_stiffness = modes.transpose() * (stiffness * modes);
    EXPECT_LT((modal_mass - Eigen::MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff(), 1e-10) << to_string(kind);
    const Eigen::MatrixXd expected_stiffness = pairs.eigenvalues.asDiagonal();
    EXPECT_LT((modal_stiffness - expected_stiffness).cwiseAbs().maxCoeff(), 1e-10 * pairs.eigenvalues.maxCoeff())
        << to_string(kind);
    for (Eigen::Index j = 0; j < modes.cols(); ++j) {
      // The first entry of largest magnitude (symmetric chain modes come in ± pairs of equal size).
      const double largest = modes.col(j).cwiseAbs().maxCoeff();
      Eigen::Index first_largest = 0;
      while (std::abs(modes(first_largest, j)) < (1.0 - 1e-6) * largest) ++first_largest;
      EXPECT_GT(modes(first_largest, j), 0.0) << to_string(kind) << " mode " << j;
    }
    for (Eigen::Index j = 1; j < pairs.eigenvalues.size(); ++j) {
      EXPECT_LT(pairs.eigenvalues[j - 1], pairs.eigenvalues[j]) << to_string(kind);
    }
  }
}

TEST(EigenSolvers, ArpackClassReportsStatsAndSuccess) {
  const SparseMatrix stiffness = kLumpedChain.stiffness();
  const SparseMatrix mass = kLumpedChain.mass();
  ffrf::modal::ArpackShiftInvert solver(stiffness, mass);
  EXPECT_EQ(solver.info(), ffrf::modal::ArpackInfo::not_computed);
  EXPECT_EQ(solver.compute(4, 0, 0.0), 4);
  EXPECT_EQ(solver.info(), ffrf::modal::ArpackInfo::successful) << solver.info_message();
  EXPECT_EQ(solver.stats().converged, 4);
  EXPECT_GE(solver.stats().iterations, 1);
  EXPECT_GE(solver.stats().operator_applications, 4);
  // Reproducible: a second compute gives bit-identical eigenvalues (fixed starting vector).
  const Eigen::VectorXd first = solver.eigenvalues();
  solver.compute(4, 0, 0.0);
  EXPECT_EQ((first - solver.eigenvalues()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(EigenSolvers, SolverNamesRoundTrip) {
  for (const EigenSolverKind kind : kAllSolvers) {
    EXPECT_EQ(ffrf::modal::parse_eigen_solver(to_string(kind)), kind);
  }
  EXPECT_FALSE(ffrf::modal::parse_eigen_solver("lanczos").has_value());
  EXPECT_EQ(ffrf::modal::eigen_solver_choices(), "arpack|dense|spectra");
}

// Expects solve_generalized to throw EigenSolverError whose message contains `needle`.
void expect_error_naming(const SparseMatrix& stiffness, const SparseMatrix& mass, const EigenRequest& request,
                         EigenSolverKind kind, const std::string& needle) {
  try {
    solve_generalized(stiffness, mass, request, kind);
    ADD_FAILURE() << to_string(kind) << ": no EigenSolverError, expected one naming '" << needle << "'";
  } catch (const EigenSolverError& error) {
    EXPECT_NE(std::string(error.what()).find(needle), std::string::npos)
        << to_string(kind) << ": message '" << error.what() << "' does not name '" << needle << "'";
  }
}

TEST(EigenSolvers, BadRequestsThrowNamingTheValue) {
  const SparseMatrix stiffness = tridiagonal(10, 2.0, -1.0);
  const SparseMatrix mass = tridiagonal(10, 1.0, 0.0);
  for (const EigenSolverKind kind : kAllSolvers) {
    expect_error_naming(stiffness, mass, EigenRequest{.nev = 0}, kind, "nev = 0");
    expect_error_naming(stiffness, mass, EigenRequest{.nev = 10}, kind, "nev = 10");
    expect_error_naming(stiffness, mass, EigenRequest{.nev = 12}, kind, "1..9");
    expect_error_naming(stiffness, mass, EigenRequest{.nev = 4, .ncv = 4}, kind, "ncv = 4");
    expect_error_naming(stiffness, mass, EigenRequest{.nev = 4, .ncv = 11}, kind, "ncv = 11");
    expect_error_naming(stiffness, mass, EigenRequest{.nev = 2, .tolerance = -1.0}, kind, "tolerance = -1");
    expect_error_naming(stiffness, tridiagonal(9, 1.0, 0.0), EigenRequest{.nev = 2}, kind, "10 x 10");
  }
}

// σ exactly at an eigenvalue of a diagonal problem: K − σM has an exact zero pivot.
TEST(EigenSolvers, SingularShiftThrowsNamingTheShift) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < 8; ++i) entries.emplace_back(i, i, static_cast<double>(i + 1));
  SparseMatrix stiffness(8, 8);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  SparseMatrix mass(8, 8);
  mass.setIdentity();
  for (const EigenSolverKind kind : {EigenSolverKind::arpack, EigenSolverKind::spectra}) {
    expect_error_naming(stiffness, mass, EigenRequest{.nev = 2, .sigma = 3.0}, kind, "singular at σ = 3");
  }
  ffrf::modal::ArpackShiftInvert solver(stiffness, mass);
  EXPECT_EQ(solver.compute(2, 0, 3.0), 0);
  EXPECT_EQ(solver.info(), ffrf::modal::ArpackInfo::numerical_issue);
  EXPECT_NE(solver.info_message().find("negative shift"), std::string::npos) << solver.info_message();
}

TEST(EigenSolvers, DenseRefusesLargeProblems) {
  const SparseMatrix stiffness = tridiagonal(6001, 2.0, -1.0);
  const SparseMatrix mass = tridiagonal(6001, 1.0, 0.0);
  expect_error_naming(stiffness, mass, EigenRequest{.nev = 2}, EigenSolverKind::dense, "use arpack");
}

// ---- the beam (fem): clamped-free and free-free Euler–Bernoulli ---------------------------------

constexpr ffrf::fem::BeamSection kSteelSection{2.1e11, 0.01, 8.333e-6, 78.5};

// ω = (βL)² √(EI/(ρA L⁴))
double bending_omega(double beta_l, const ffrf::fem::BeamMesh& mesh) {
  const auto& s = mesh.section;
  return beta_l * beta_l * std::sqrt(s.bending_rigidity() / (s.mass_per_length * std::pow(mesh.length, 4)));
}

TEST(EigenSolversBeam, SolversAgreeOnClampedFreeBeam) {
  const ffrf::fem::BeamMesh mesh{10.0, 40, kSteelSection};
  const auto beam = ffrf::fem::assemble_free(mesh, ffrf::fem::Boundary::clamped_free);
  const EigenRequest request{.nev = 6};
  const EigenPairs reference = solve_generalized(beam.stiffness, beam.mass, request, EigenSolverKind::dense);
  for (const EigenSolverKind kind : {EigenSolverKind::arpack, EigenSolverKind::spectra}) {
    const EigenPairs pairs = solve_generalized(beam.stiffness, beam.mass, request, kind);
    ASSERT_EQ(pairs.eigenvalues.size(), 6);
    for (int j = 0; j < 6; ++j) {
      EXPECT_LT(relative_difference(pairs.eigenvalues[j], reference.eigenvalues[j]), 1e-9)
          << to_string(kind) << " mode " << j;
      const auto mode = pairs.eigenvectors.col(j);
      const auto reference_mode = reference.eigenvectors.col(j);
      const double sign = mode.dot(beam.mass * reference_mode) >= 0.0 ? 1.0 : -1.0;
      EXPECT_LT((mode - sign * reference_mode).cwiseAbs().maxCoeff(), 1e-7 * reference_mode.cwiseAbs().maxCoeff())
          << to_string(kind) << " mode " << j;
    }
  }
}

TEST(EigenSolversBeam, ArpackFindsCantileverFundamentalWithTenThousandElements) {
  const ffrf::fem::BeamMesh mesh{10.0, 10000, kSteelSection};
  const auto beam = ffrf::fem::assemble_free(mesh, ffrf::fem::Boundary::clamped_free);
  ASSERT_EQ(beam.stiffness.rows(), 30000);
  const EigenPairs pairs = solve_generalized(beam.stiffness, beam.mass, EigenRequest{.nev = 6}, EigenSolverKind::arpack);
  ASSERT_EQ(pairs.eigenvalues.size(), 6);
  const double omega1 = std::sqrt(pairs.eigenvalues[0]);
  EXPECT_LT(relative_difference(omega1, bending_omega(1.875104069, mesh)), 1e-6) << "ω1 = " << omega1;
  EXPECT_EQ(pairs.stats.converged, 6);
}

TEST(EigenSolversBeam, FreeFreeBeamWithNegativeShiftHasThreeRigidModes) {
  const ffrf::fem::BeamMesh mesh{10.0, 40, kSteelSection};
  const auto beam = ffrf::fem::assemble_free(mesh, ffrf::fem::Boundary::free_free);
  const double first_elastic = std::pow(bending_omega(4.730040745, mesh), 2);
  const EigenRequest request{.nev = 4, .sigma = -1.0};
  for (const EigenSolverKind kind : kAllSolvers) {
    const EigenPairs pairs = solve_generalized(beam.stiffness, beam.mass, request, kind);
    ASSERT_EQ(pairs.eigenvalues.size(), 4);
    for (int j = 0; j < 3; ++j) {
      EXPECT_LT(std::abs(pairs.eigenvalues[j]), 1e-6 * first_elastic) << to_string(kind) << " rigid mode " << j;
    }
    EXPECT_LT(relative_difference(std::sqrt(pairs.eigenvalues[3]), std::sqrt(first_elastic)), 1e-6)
        << to_string(kind) << " ω = " << std::sqrt(pairs.eigenvalues[3]);
  }
}

}  // namespace
