// The power-series reference of the rotating clamped-free beam (fem/analytic_rotating_beam.hpp)
// against independent values: the closed-form clamped-free roots βL at λ = 0 (and the exact shift
// μ = μ₀ − λ without stiffening); the published first flapwise frequencies of the rotating
// cantilever (Wright, Smith, Thresher & Wang 1982, J. Appl. Mech. 49; Hodges & Rutkowski 1981,
// AIAA J. 19) with the in-plane ones following as ω̄_in² = ω̄_flap² − Ω̄²; and the Euler buckling
// load of the cantilever, p̄ = π²/4, where the first frequency of the compressed beam vanishes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fem/analytic_beam.hpp"
#include "fem/analytic_rotating_beam.hpp"

namespace {

using namespace ffrf::fem;

TEST(AnalyticRotatingBeam, NonRotatingSeriesGivesClampedFreeRoots) {
  const auto mu = rotating_beam_eigenvalues(RotatingBeamProblem{}, 3);
  const double published[] = {1.875104, 4.694091, 7.854757};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(std::pow(mu[i], 0.25), published[i], 1e-6) << "mode " << i + 1;
  // And to round-off against the bisection of 1 + cos βL cosh βL = 0 (fem/analytic_beam.hpp).
  const BeamMesh unit{1.0, 1, {1.0, 1.0, 1.0, 1.0}};
  const auto roots = analytic_bending_modes(unit, Boundary::clamped_free, 3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(std::pow(mu[i], 0.25) / roots[i].beta_l, 1.0, 1e-12) << "mode " << i + 1;
}

TEST(AnalyticRotatingBeam, WithoutStiffeningInPlaneEigenvaluesShiftByLambda) {
  const auto mu0 = rotating_beam_eigenvalues(RotatingBeamProblem{}, 3);
  for (double lambda : {1.0, 10.0, 20.0, 100.0}) {
    RotatingBeamProblem p;
    p.spin_parameter = lambda;
    p.hub_radius_ratio = 0.3;
    p.centrifugal_stiffening = false;
    const auto mu = rotating_beam_eigenvalues(p, 3);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mu[i], mu0[i] - lambda, 1e-10 * mu0[i]) << "lambda " << lambda << " mode " << i + 1;
  }
  // λ = 20 > μ₁ = 12.36: the first mode diverges (μ < 0).
  RotatingBeamProblem p;
  p.spin_parameter = 20.0;
  p.centrifugal_stiffening = false;
  EXPECT_LT(rotating_beam_eigenvalues(p, 1)[0], 0.0);
}

TEST(AnalyticRotatingBeam, FirstFlapwiseFrequencyMatchesPublishedTable) {
  const double spin[] = {0, 1, 2, 3, 4, 5, 6, 8, 10, 12};
  const double published[] = {3.5160, 3.6817, 4.1373, 4.7973, 5.5850, 6.4495, 7.3604, 9.2568, 11.2023, 13.1702};
  for (int i = 0; i < 10; ++i) {
    RotatingBeamProblem flap;
    flap.spin_parameter = spin[i] * spin[i];
    flap.in_plane = false;
    const double flapwise = std::sqrt(rotating_beam_eigenvalues(flap, 1)[0]);
    EXPECT_NEAR(flapwise, published[i], 0.6e-4) << "Omega = " << spin[i];
    RotatingBeamProblem in = flap;
    in.in_plane = true;
    const double in_plane_mu = rotating_beam_eigenvalues(in, 1)[0];
    EXPECT_NEAR(in_plane_mu, flapwise * flapwise - spin[i] * spin[i], 1e-9 * flapwise * flapwise) << "Omega = " << spin[i];
  }
  // Measured: all ten agree to ≤ 5.3e-5 (rounding of the 4th decimal; at Ω̄ = 1 the series gives
  // 3.681647, one unit below the table's last digit). Second and third modes at Ω̄ = 12 (same table).
  RotatingBeamProblem flap;
  flap.spin_parameter = 144.0;
  flap.in_plane = false;
  const auto mu = rotating_beam_eigenvalues(flap, 3);
  EXPECT_NEAR(std::sqrt(mu[1]), 37.6031, 1e-4);
  EXPECT_NEAR(std::sqrt(mu[2]), 79.6145, 1e-4);
}

TEST(AnalyticRotatingBeam, HubRadiusStiffensFurther) {
  // A hub ahead of the root adds the tension ρAΩ² r (L − x): every frequency rises with r.
  RotatingBeamProblem p;
  p.spin_parameter = 16.0;
  double previous = 0.0;
  for (double ratio : {0.0, 0.5, 1.0, 2.0}) {
    p.hub_radius_ratio = ratio;
    const double mu = rotating_beam_eigenvalues(p, 1)[0];
    EXPECT_GT(mu, previous) << "r/L = " << ratio;
    previous = mu;
  }
}

TEST(AnalyticRotatingBeam, CompressionLowersTheFirstFrequencyToZeroAtEulerLoad) {
  const double critical = std::numbers::pi * std::numbers::pi / 4.0;
  RotatingBeamProblem p;
  double previous = rotating_beam_eigenvalues(p, 1)[0];
  for (double ratio : {0.2, 0.5, 0.8, 0.95, 0.999}) {
    p.axial_force_parameter = -ratio * critical;
    const double mu = rotating_beam_eigenvalues(p, 1)[0];
    EXPECT_LT(mu, previous) << "P/Pcr = " << ratio;
    previous = mu;
  }
  EXPECT_LT(previous, 0.01 * 12.36);  // nearly zero just below buckling
  p.axial_force_parameter = -critical;
  EXPECT_THROW(rotating_beam_eigenvalues(p, 1), std::domain_error);
  // The tip determinant at μ = 0 vanishes at the Euler load (the buckling equation cos(√p̄) = 0).
  p.axial_force_parameter = -critical;
  const long double at = rotating_beam_tip_determinant(p, 0.0L);
  p.axial_force_parameter = -0.9 * critical;
  const long double off = rotating_beam_tip_determinant(p, 0.0L);
  EXPECT_LT(std::fabs(static_cast<double>(at)), 1e-12 * std::fabs(static_cast<double>(off)));
}

TEST(AnalyticRotatingBeam, RejectsInvalidParameters) {
  RotatingBeamProblem p;
  p.spin_parameter = -1.0;
  EXPECT_THROW(rotating_beam_eigenvalues(p, 1), std::invalid_argument);
  EXPECT_THROW(rotating_beam_eigenvalues(RotatingBeamProblem{}, 0), std::invalid_argument);
}

}  // namespace
