// FE frequencies of the spinning and the compressed cantilever (modal/rotating_beam_modes.hpp)
// against independent results: the exact shift ω² = ω₀² − Ω² without stiffening (including
// divergence above ω₁); the power series of fem/analytic_rotating_beam.hpp with stiffening; the
// published first flapwise frequencies (Wright et al. 1982) from K + Ω²K_c alone; the dense
// eigenvalues of the same matrices for an indefinite K_Ω; and the Euler load π²EI/(4L²) where the
// first frequency of the compressed cantilever vanishes, also from the buckling eigenproblem
// K φ = P (−K_g,1) φ solved densely.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>

#include "fem/analytic_rotating_beam.hpp"
#include "fem/axial_force.hpp"
#include "modal/rotating_beam_modes.hpp"
#include "linalg/dense_solvers.hpp"

namespace {

using namespace ffrf;

// The spin-up beam: L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m², ρA = 1.2 kg/m (ω₁ ≈ 3.80 rad/s).
const fem::BeamMesh beam{10.0, 32, {2.8e7, 1.0, 1.4e4 / 2.8e7, 1.2}};
const fem::BeamModel model = fem::make_beam_model(beam, fem::Boundary::clamped_free);
const double scale = fem::rotating_beam_frequency_scale(beam);  // √(EI/(ρA L⁴)) [rad/s]

std::vector<double> bending_omega2(const modal::RotatingBeamModes& r, int count) {
  std::vector<double> out;
  for (const auto& m : r.modes)
    if (m.kind == fem::ModeKind::bending && static_cast<int>(out.size()) < count) out.push_back(m.omega_squared);
  return out;
}

modal::RotatingBeamModes spin(double omega, bool stiffening, double hub_radius = 0.0, int count = 6) {
  modal::RotatingBeamState state;
  state.spin_rate = omega;
  state.centrifugal_stiffening = stiffening;
  state.hub_radius = hub_radius;
  return modal::rotating_beam_modes(model, state, count);
}

TEST(RotatingBeamModes, WithoutStiffeningOmegaSquaredDropsByExactlySpinSquared) {
  const auto omega0 = bending_omega2(spin(0.0, false), 4);
  ASSERT_EQ(omega0.size(), 4u);
  EXPECT_NEAR(std::sqrt(omega0[0]) / (1.875104069 * 1.875104069 * scale), 1.0, 1e-6);
  // Round-off of a bending eigenvalue is ε times the largest eigenvalue of (K, M) (the axial
  // stiffness EA/l dominates K), not ε ω²: the measured error (0.0045 ε λ_max) is held below 0.1 ε λ_max.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Eigen::MatrixXd(model.stiffness),
                                                                          Eigen::MatrixXd(model.mass));
  const double round_off = std::numeric_limits<double>::epsilon() * dense.eigenvalues().maxCoeff();
  double worst = 0.0;
  for (double omega : {0.5 * std::sqrt(omega0[0]), 3.0, 5.0, 30.0}) {  // 5 and 30 rad/s: above ω₁
    const auto r = spin(omega, false);
    const auto omega2 = bending_omega2(r, 4);
    ASSERT_EQ(omega2.size(), 4u);
    for (int i = 0; i < 4; ++i) {
      const double expected = omega0[static_cast<std::size_t>(i)] - omega * omega;
      const double error = std::abs(omega2[static_cast<std::size_t>(i)] - expected) / round_off;
      worst = std::max(worst, error);
      EXPECT_LT(error, 0.1) << "Omega " << omega << " mode " << i + 1;
    }
    if (omega > std::sqrt(omega0[0])) {
      EXPECT_FALSE(r.modes[0].stable());
      EXPECT_NEAR(r.modes[0].growth_rate(), std::sqrt(omega * omega - omega0[0]), 1e-9 * omega);
      EXPECT_EQ(r.modes[0].angular_frequency(), 0.0);
    }
  }
  std::printf("[ measured ] worst |w^2 - (w0^2 - W^2)| = %.3g eps lambda_max (eps lambda_max = %.2e rad^2/s^2)\n", worst,
              round_off);
}

TEST(RotatingBeamModes, WithStiffeningMatchesPowerSeries) {
  double worst = 0.0;
  for (double hub_ratio : {0.0, 0.5}) {
    for (double spin_bar : {1.0, 4.0, 10.0}) {
      const double omega = spin_bar * scale;
      const auto fe = bending_omega2(spin(omega, true, hub_ratio * beam.length), 3);
      const auto mu = fem::rotating_beam_eigenvalues(
          fem::rotating_beam_problem(beam, omega, hub_ratio * beam.length, 0.0, true), 3);
      for (int i = 0; i < 3; ++i) {
        const double reference = std::sqrt(mu[static_cast<std::size_t>(i)]) * scale;
        const double error = std::abs(std::sqrt(fe[static_cast<std::size_t>(i)]) - reference) / reference;
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-4) << "r/L " << hub_ratio << " Omega_bar " << spin_bar << " mode " << i + 1;
      }
    }
  }
  std::printf("[ measured ] worst relative error of w (N = 32, modes 1-3, Omega_bar = 1, 4, 10) = %.2e\n", worst);
}

TEST(RotatingBeamModes, FlapwiseStiffeningMatchesPublishedFirstFrequency) {
  // Out of plane there is no −Ω²M: K + Ω²K_c alone (Wright et al. 1982, r = 0).
  const auto kc = fem::assemble_geometric_stiffness(beam, model.dofs, fem::centrifugal_axial_force(beam, 0.0));
  const double spin_bar[] = {2.0, 6.0, 12.0};
  const double published[] = {4.1373, 7.3604, 13.1702};
  for (int i = 0; i < 3; ++i) {
    const double omega = spin_bar[i] * scale;
    const modal::SparseMatrix k = model.stiffness + omega * omega * kc;
    modal::EigenRequest request;
    request.nev = 1;
    const auto pairs = modal::solve_generalized(k, model.mass, request, modal::EigenSolverKind::arpack);
    EXPECT_NEAR(std::sqrt(pairs.eigenvalues(0)) / scale, published[i], 1e-4) << "Omega_bar " << spin_bar[i];
  }
}

TEST(RotatingBeamModes, IndefiniteStiffnessFindsTheSameLowestModesAsDense) {
  const double omega = 25.0;  // above ω₁ = 3.80 and ω₂ = 23.8 rad/s without stiffening: two negative ω²
  modal::RotatingBeamState state;
  state.spin_rate = omega;
  state.centrifugal_stiffening = false;
  const auto r = modal::rotating_beam_modes(model, state, 5);
  EXPECT_LT(r.shift, r.pairs.eigenvalues(0));
  const Eigen::MatrixXd k(modal::rotating_stiffness(model, state));
  const Eigen::MatrixXd m(model.mass);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(k, m);
  for (int j = 0; j < 5; ++j) {
    EXPECT_NEAR(r.pairs.eigenvalues(j), dense.eigenvalues()(j), 1e-9 * omega * omega) << "mode " << j + 1;
  }
  EXPECT_LT(r.pairs.eigenvalues(1), 0.0);
  EXPECT_GT(r.pairs.eigenvalues(2), 0.0);
}

double first_omega2(double axial_force) {
  modal::RotatingBeamState state;
  state.axial_force = axial_force;
  return modal::rotating_beam_modes(model, state, 2).pairs.eigenvalues(0);
}

TEST(RotatingBeamModes, CompressedCantileverLosesItsFirstFrequencyAtEulerLoad) {
  const double critical = std::numbers::pi * std::numbers::pi * beam.section.bending_rigidity() / (4.0 * beam.length * beam.length);
  double previous = first_omega2(0.0);
  for (double ratio : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    const double omega2 = first_omega2(-ratio * critical);
    EXPECT_LT(omega2, previous) << "P/Pcr " << ratio;
    EXPECT_GT(omega2, 0.0) << "P/Pcr " << ratio;
    previous = omega2;
  }
  // Bisection on ω₁²(P) = 0.
  double lo = 0.5 * critical, hi = 1.5 * critical;  // compression magnitudes
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (first_omega2(-mid) > 0.0 ? lo : hi) = mid;
  }
  const double bisected = 0.5 * (lo + hi);
  EXPECT_NEAR(bisected / critical, 1.0, 1e-3);
  EXPECT_LT(first_omega2(-1.1 * critical), 0.0);  // buckled: negative ω² found and reported
  // Second method: K φ = P_cr K_g,1 φ ⇔ K_g,1 φ = (1/P_cr) K φ, K positive definite.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> buckling(Eigen::MatrixXd(model.unit_geometric_stiffness),
                                                                             Eigen::MatrixXd(model.stiffness));
  const double from_eigenproblem = 1.0 / buckling.eigenvalues().maxCoeff();
  EXPECT_NEAR(from_eigenproblem / critical, 1.0, 1e-3);
  EXPECT_NEAR(bisected / from_eigenproblem, 1.0, 1e-9);
  std::printf("[ measured ] P_cr bisection / (pi^2 EI / 4L^2) - 1 = %.2e, buckling eigenproblem: %.2e\n",
              bisected / critical - 1.0, from_eigenproblem / critical - 1.0);
}

TEST(RotatingBeamModes, RejectsInvalidStates) {
  modal::RotatingBeamState state;
  state.spin_rate = -1.0;
  EXPECT_THROW(modal::rotating_beam_modes(model, state, 2), std::invalid_argument);
  state.spin_rate = 1.0;
  const auto free_free = fem::make_beam_model(beam, fem::Boundary::free_free);
  EXPECT_THROW(modal::rotating_beam_modes(free_free, state, 2), std::invalid_argument);
}

}  // namespace
