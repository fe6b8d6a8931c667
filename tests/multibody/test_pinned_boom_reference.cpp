// Self-checks of the pinned-boom reference (pinned_boom_reference.hpp): its exact solutions against
// the classical limits, its finite elements against its exact solutions, and the oblique wire
// against bounds that hold whatever the wire's direction.
#include "pinned_boom_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace ffrf::test::pinned_boom_reference_checks {

constexpr double pi = std::numbers::pi;

// The reference crane's boom (defaults of PinnedBoom): L = 120 m, EI = 2.1e11 × 11.4,
// EA = 2.1e11 × 1.27, ρA = 10 000 kg/m, k = 2e8 N/m, wire ⊥ boom at the tip.
PinnedBoom crane_boom() { return PinnedBoom{}; }

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

// λ = βL of a bending frequency.
double lambda_of(const PinnedBoom& b, double omega) {
  return b.length * std::sqrt(omega / std::sqrt(b.EI / b.mass_per_length));
}

TEST(PinnedBoomReference, StiffWireGivesPinnedPinnedFrequencies) {
  PinnedBoom b = crane_boom();
  b.wire_stiffness = 1e16;
  const Eigen::VectorXd omega = natural_frequencies_analytic(b, 4);
  double worst = 0.0;
  for (int n = 1; n <= 4; ++n) {
    const double exact = std::pow(n * pi / b.length, 2) * std::sqrt(b.EI / b.mass_per_length);
    worst = std::max(worst, relative(omega(n - 1), exact));
  }
  std::printf("[ measured ] k = 1e16: worst relative deviation from pinned-pinned %.3e\n", worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(PinnedBoomReference, NoWireGivesPinnedFreeRoots) {
  PinnedBoom b = crane_boom();
  b.wire_stiffness = 0.0;
  const Eigen::VectorXd omega = natural_frequencies_analytic(b, 4);
  EXPECT_EQ(omega(0), 0.0);  // the rigid rotation about the pin
  const double first = lambda_of(b, omega(1));
  std::printf("[ measured ] k = 0: first nonzero beta L = %.15f (|error| %.3e)\n", first,
              std::abs(first - 3.9266023120479));
  EXPECT_LT(relative(first, 3.9266023120479), 1e-9);
  for (int i = 1; i < 4; ++i) {  // tan λ = tanh λ, and λ near (4i + 1)π/4
    const double lambda = lambda_of(b, omega(i));
    EXPECT_NEAR(std::tan(lambda), std::tanh(lambda), 1e-9) << i;
    EXPECT_NEAR(lambda, (4 * i + 1) * pi / 4, 1e-3) << i;
  }
}

// The mode of an exact root satisfies the boundary conditions it was derived from: w = A sin βx +
// C sinh βx with w''(L) = 0 chosen, then EI w'''(L) = k w(L) must hold (checks the determinant).
TEST(PinnedBoomReference, ExactModeSatisfiesSpringCondition) {
  const PinnedBoom b = crane_boom();
  const Eigen::VectorXd omega = natural_frequencies_analytic(b, 3);
  for (int i = 0; i < 3; ++i) {
    const double beta = lambda_of(b, omega(i)) / b.length, l = beta * b.length;
    const double A = std::sinh(l), C = std::sin(l);  // −A sin λ + C sinh λ = 0
    const double w = A * std::sin(l) + C * std::sinh(l);
    const double shear = b.EI * std::pow(beta, 3) * (-A * std::cos(l) + C * std::cosh(l));
    EXPECT_LT(std::abs(shear - b.wire_stiffness * w), 1e-9 * std::abs(b.wire_stiffness * w)) << i;
  }
}

TEST(PinnedBoomReference, FiniteElementsConvergeToExactFrequencies) {
  const PinnedBoom b = crane_boom();
  const Eigen::VectorXd exact = natural_frequencies_analytic(b, 3);
  const Eigen::VectorXd fe64 = bending_frequencies_fe(b, 64, 3);
  for (int i = 0; i < 3; ++i) {
    std::printf("[ measured ] bending mode %d: exact %.10f rad/s, N = 64 relative error %.3e\n",
                i + 1, exact(i), relative(fe64(i), exact(i)));
    EXPECT_LT(relative(fe64(i), exact(i)), 1e-6) << i;
  }
  // Fourth order: the error falls ~16-fold per halving of the element length.
  double error[3];
  const int n[3] = {8, 16, 32};
  for (int j = 0; j < 3; ++j) error[j] = relative(bending_frequencies_fe(b, n[j], 1)(0), exact(0));
  for (int j = 0; j < 2; ++j) {
    const double order = std::log2(error[j] / error[j + 1]);
    std::printf("[ measured ] mode 1 error N = %d: %.3e, N = %d: %.3e, order %.3f\n", n[j],
                error[j], n[j + 1], error[j + 1], order);
    EXPECT_GT(error[j + 1], 0.0);
    EXPECT_NEAR(order, 4.0, 0.3) << n[j];
  }
  // Consistent mass: the finite-element frequencies lie above the exact ones.
  EXPECT_GT(fe64(0), exact(0));
}

TEST(PinnedBoomReference, AxialModesDecoupleAndConverge) {
  PinnedBoom b = crane_boom();
  b.wire_tension = 1e6;  // along the boom (d ⊥ boom): an axial spring T/ℓ at the tip
  b.wire_length = 20.0;
  const PinnedBoomModes modes = natural_modes_fe(b, 64);
  for (Eigen::Index j = 0; j < 10; ++j) {
    EXPECT_TRUE(modes.axial_fraction(j) < 1e-12 || modes.axial_fraction(j) > 1.0 - 1e-12) << j;
  }
  const Eigen::VectorXd all = natural_frequencies_fe(b, 64, 5);
  const Eigen::VectorXd exact = in_plane_frequencies_analytic(b, 5);
  for (int i = 0; i < 5; ++i) {
    std::printf("[ measured ] in-plane mode %d: exact %.6f, N = 64 relative error %.3e\n", i + 1,
                exact(i), relative(all(i), exact(i)));
    EXPECT_LT(relative(all(i), exact(i)), 1e-4) << i;  // linear bar elements: second order
  }
}

TEST(PinnedBoomReference, UniformAxialForceScalesPinnedPinnedFrequencies) {
  PinnedBoom b = crane_boom();
  b.wire_stiffness = 1e14;  // nearly a pin at the tip
  const double euler = pi * pi * b.EI / (b.length * b.length);
  for (const double share : {0.5, -0.5}) {  // tension and compression of half the Euler load
    b.axial_force_uniform = share * euler;
    const double omega = bending_frequencies_fe(b, 64, 1)(0);
    const double beta = pi / b.length;
    const double P = b.axial_force_uniform;
    const double exact = std::sqrt((std::pow(beta, 4) * b.EI + beta * beta * P) /
                                   b.mass_per_length);
    std::printf("[ measured ] P = %+.1f P_Euler: relative error %.3e\n", share,
                relative(omega, exact));
    EXPECT_LT(relative(omega, exact), 1e-5);
  }
}

TEST(PinnedBoomReference, StaticDeflectionMatchesBeamTheory) {
  const PinnedBoom b = crane_boom();
  const Eigen::Vector2d gravity(0.0, -9.81);
  const double q = b.mass_per_length * gravity.y();
  const int N = 16;
  const PinnedBoomStatic fe = static_deflection_fe(b, N, gravity, Eigen::Vector2d::Zero());
  const double tip = static_deflection_analytic(b, q, b.length);
  const double mid = static_deflection_analytic(b, q, 0.5 * b.length);
  const double heel = tip / b.length + q * std::pow(b.length, 3) / (24.0 * b.EI);  // w'(0)
  std::printf("[ measured ] w(L) = %.12f m (FE rel. error %.3e), w(L/2) = %.12f m (%.3e), "
              "heel rotation rel. error %.3e, wire force %.6e N (%.3e)\n",
              tip, relative(fe.tip_displacement.y(), tip), mid,
              relative(fe.nodal(3 * N / 2 + 1), mid), relative(fe.heel_rotation, heel),
              fe.wire_force, relative(fe.wire_force, -q * b.length / 2.0));
  EXPECT_LT(relative(fe.tip_displacement.y(), tip), 1e-9);
  EXPECT_LT(relative(fe.nodal(3 * N / 2 + 1), mid), 1e-9);
  EXPECT_LT(relative(fe.heel_rotation, heel), 1e-9);
  EXPECT_LT(relative(fe.wire_force, -q * b.length / 2.0), 1e-9);  // stretched by qL/2
  EXPECT_LT(std::abs(fe.tip_displacement.x()), 1e-15);

  // A tip force: transverse, a rigid rotation F/k; axial, the bar's FL/EA.
  const PinnedBoomStatic point = static_deflection_fe(b, N, Eigen::Vector2d::Zero(), {3e6, -1e6});
  EXPECT_LT(relative(point.tip_displacement.y(), -1e6 / b.wire_stiffness), 1e-9);
  EXPECT_LT(relative(point.tip_displacement.x(), 3e6 * b.length / b.EA), 1e-9);
  EXPECT_LT(relative(point.heel_rotation, -1e6 / b.wire_stiffness / b.length), 1e-9);

  PinnedBoom slack = b;  // no wire: the boom swings freely
  slack.wire_stiffness = 0.0;
  EXPECT_THROW(static_deflection_fe(slack, N, gravity, Eigen::Vector2d::Zero()),
               std::invalid_argument);
}

TEST(PinnedBoomReference, ObliqueWireLiesBetweenBounds) {
  const int N = 32, count = 6;
  PinnedBoom oblique = crane_boom();
  oblique.wire_direction_local = {-std::cos(pi / 6), std::sin(pi / 6)};  // 30° to the boom
  PinnedBoom no_wire = oblique;
  no_wire.wire_stiffness = 0.0;
  const Eigen::VectorXd w_obl = natural_frequencies_fe(oblique, N, count);
  const Eigen::VectorXd w_free = natural_frequencies_fe(no_wire, N, count);
  const Eigen::VectorXd w_transverse = natural_frequencies_fe(crane_boom(), N, count);
  // Upper bound: the stiffness k I (the tip held alike in every direction) ≥ k d dᵀ.
  PinnedBoomFe upper = assemble_pinned_boom(oblique, N);
  upper.K.block<2, 2>(3 * N - 2, 3 * N - 2) += oblique.wire_stiffness *
      (Eigen::Matrix2d::Identity() - oblique.wire_direction_local *
                                         oblique.wire_direction_local.transpose());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> held(upper.K, upper.M);
  for (int i = 0; i < count; ++i) {
    const double w_held = std::sqrt(held.eigenvalues()(i));
    std::printf("[ measured ] mode %d: k = 0 %.6f, oblique %.6f, transverse %.6f, held %.6f\n",
                i + 1, w_free(i), w_obl(i), w_transverse(i), w_held);
    EXPECT_LE(w_free(i), w_obl(i) * (1 + 1e-12)) << i;
    EXPECT_LE(w_obl(i), w_held * (1 + 1e-12)) << i;
  }
  // The first (bending) mode: a weaker transverse hold than the transverse wire's.
  EXPECT_LT(w_obl(0), w_transverse(0));

  // Symmetry, Rayleigh quotients and M-orthonormality of the modes.
  const PinnedBoomFe fe = assemble_pinned_boom(oblique, N);
  const auto asymmetry = [](const Eigen::MatrixXd& A) {
    return (A - A.transpose()).cwiseAbs().maxCoeff() / A.cwiseAbs().maxCoeff();
  };
  const double asym_K = asymmetry(fe.K), asym_M = asymmetry(fe.M);
  EXPECT_LT(asym_K, 1e-15);  // round-off of the quadrature's products only
  EXPECT_LT(asym_M, 1e-15);
  const PinnedBoomModes modes = natural_modes_fe(oblique, N);
  const Eigen::MatrixXd X = modes.shapes.bottomRows(fe.K.rows()).leftCols(count);
  const Eigen::MatrixXd gram = X.transpose() * fe.M * X;
  double worst_rayleigh = 0.0;
  for (int i = 0; i < count; ++i) {
    const double rayleigh = X.col(i).dot(fe.K * X.col(i)) / X.col(i).dot(fe.M * X.col(i));
    worst_rayleigh = std::max(worst_rayleigh, relative(std::sqrt(rayleigh), w_obl(i)));
  }
  const double orthonormality =
      (gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff();
  std::printf("[ measured ] asymmetry K %.1e, M %.1e; M-orthonormality %.1e; Rayleigh %.1e\n",
              asym_K, asym_M, orthonormality, worst_rayleigh);
  EXPECT_LT(orthonormality, 1e-10);
  EXPECT_LT(worst_rayleigh, 1e-8);  // the eigensolver's round-off, ε |K|/|M| relative to ω²
  // A trial vector's Rayleigh quotient bounds ω₁² from above: the rigid rotation about the pin.
  Eigen::VectorXd rigid = Eigen::VectorXd::Zero(fe.K.rows() + 2);
  for (int node = 0; node <= N; ++node) {
    rigid(3 * node + 1) = node * oblique.length / N;
    rigid(3 * node + 2) = 1.0;
  }
  const Eigen::VectorXd r = rigid.tail(fe.K.rows());
  const double by_hand = oblique.wire_stiffness * 0.25 * oblique.length * oblique.length /
                         (oblique.mass_per_length * std::pow(oblique.length, 3) / 3.0);
  EXPECT_LT(relative(r.dot(fe.K * r) / r.dot(fe.M * r), by_hand), 1e-12);
  EXPECT_LT(w_obl(0) * w_obl(0), by_hand);
}

}  // namespace ffrf::test::pinned_boom_reference_checks
