// The modes analyses of `ffrf modes` called directly (moved from the CLI tests): the cantilever's
// bending frequencies against Euler–Bernoulli (βL)²/(2πL²)·√(EI/ρA) computed here; the free–free
// beam's three rigid modes; the spinning beam against the exact ω² = ω₀² − Ω² without stiffening and
// the published first flapwise frequency of the rotating cantilever (Wright et al. 1982,
// ω̄_in² = ω̄_flap² − Ω̄²); the Campbell diagram at its grid points; the axial force lowering ω1 with
// the Euler load π²EI/(4L²).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fem/beam_model.hpp"
#include "study/campbell.hpp"
#include "study/modes.hpp"
#include "study_test_support.hpp"

namespace {

using namespace ffrf;

// f = (βL)² / (2π L²) · √(EI / ρA) for the cantilever of cases/cantilever.toml.
double cantilever_frequency(double beta_l) {
  const double length = 10.0, youngs_modulus = 2.1e11, area = 0.01, second_moment = 8.333e-6, density = 7850.0;
  return beta_l * beta_l / (2.0 * std::numbers::pi * length * length) *
         std::sqrt(youngs_modulus * second_moment / (density * area));
}
double hertz(double omega) { return omega / (2.0 * std::numbers::pi); }

TEST(Modes, CantileverBendingFrequenciesMatchEulerBernoulli) {
  fem::BeamMesh mesh = test::scene_file("cantilever.toml").boom.mesh;
  mesh.element_count = 64;
  const study::ModesResult r = study::solve_modes(mesh, fem::Boundary::clamped_free, modal::EigenSolverKind::arpack, 6);
  EXPECT_EQ(r.dofs.free_count(), 192);
  const double beta_l[] = {1.875104069, 4.694091133, 7.854757438, 10.995540735};
  ASSERT_GE(r.modes.size(), 4u);
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_EQ(r.modes[j].kind, fem::ModeKind::bending);
    EXPECT_EQ(r.modes[j].order, static_cast<int>(j + 1));
    EXPECT_NEAR(hertz(r.modes[j].angular_frequency) / cantilever_frequency(beta_l[j]), 1.0, 1e-6) << "f" << j + 1;
  }
  for (std::size_t j = 1; j < r.modes.size(); ++j) EXPECT_LT(r.modes[j - 1].angular_frequency, r.modes[j].angular_frequency);
}

TEST(Modes, FreeFreeFindsThreeRigidModesWithANegativeShift) {
  fem::BeamMesh mesh = test::scene_file("cantilever.toml").boom.mesh;
  mesh.element_count = 64;
  const study::ModesResult r = study::solve_modes(mesh, fem::Boundary::free_free, modal::EigenSolverKind::arpack, 9);
  EXPECT_LT(r.shift, 0.0);
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_GE(r.modes.size(), 4u);
  for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(r.modes[j].kind, fem::ModeKind::rigid);
  EXPECT_EQ(r.modes[3].kind, fem::ModeKind::bending);
  EXPECT_NEAR(hertz(r.modes[3].angular_frequency) / cantilever_frequency(4.730040745), 1.0, 1e-6);
}

// The spin-up beam of the CLI test (L = 10 m, EI = 1.4e4 N m², ρA = 1.2 kg/m), N = 32, clamped-free.
const fem::BeamMesh kSpinBeam{10.0, 32, {2.8e7, 1.0, 5.0e-4, 1.2}};
const double kScale = std::sqrt(1.4e4 / (1.2 * std::pow(10.0, 4)));  // ω = ω̄ · scale [rad/s]
constexpr double kBeta1 = 1.875104069;

TEST(SpinModes, SpinMatchesTheExactShiftAndThePublishedRotatingCantilever) {
  const fem::BeamModel model = fem::make_beam_model(kSpinBeam, fem::Boundary::clamped_free);
  const double spin = 4.0 * kScale;  // Ω̄ = 4 > β₁² = 3.516: without stiffening mode 1 diverges
  const study::SpinModesResult r = study::solve_spin_modes(model, spin, 0.0, 0.0, 6, modal::EigenSolverKind::arpack);
  const study::SpinModeRow& mode1 = r.rows[0];
  EXPECT_EQ(mode1.kind, fem::ModeKind::bending);
  EXPECT_GT(mode1.stiffened_omega2, 0.0);
  const double published_in_plane = std::sqrt(5.5850 * 5.5850 - 16.0) * kScale;  // ω̄_flap(4) = 5.5850
  EXPECT_NEAR(std::sqrt(mode1.stiffened_omega2) / published_in_plane, 1.0, 1e-4);
  ASSERT_TRUE(mode1.reference_omega2);
  EXPECT_NEAR(std::sqrt(*mode1.reference_omega2) / published_in_plane, 1.0, 1e-4);
  EXPECT_NEAR(std::sqrt(mode1.stiffened_omega2 / *mode1.reference_omega2), 1.0, 1e-6) << "FE against the power series";
  // Without stiffening: ω² = ω₀² − Ω² < 0, growth rate √(Ω² − ω₀²).
  const double omega0 = kBeta1 * kBeta1 * kScale;
  ASSERT_TRUE(mode1.plain_omega2);
  EXPECT_LT(*mode1.plain_omega2, 0.0);
  EXPECT_NEAR(std::sqrt(-*mode1.plain_omega2) / std::sqrt(spin * spin - omega0 * omega0), 1.0, 1e-5);
  const double omega02 = std::pow(4.694091133, 2) * kScale;
  EXPECT_NEAR(std::sqrt(*r.rows[1].plain_omega2) / std::sqrt(omega02 * omega02 - spin * spin), 1.0, 1e-6);
}

TEST(SpinModes, CampbellDiagramMatchesThePublishedRotatingCantilever) {
  const fem::BeamModel model = fem::make_beam_model(kSpinBeam, fem::Boundary::clamped_free);
  const study::CampbellResult r =
      study::campbell_diagram(model, {0.0, 4.0 * kScale, 5}, 0.0, 0.0, 3, modal::EigenSolverKind::arpack, {});
  ASSERT_EQ(r.points.size(), 5u);
  const double published[] = {3.5160, 4.1373, 5.5850};  // ω̄_flap at Ω̄ = 0, 2, 4
  for (std::size_t k = 0; k < 3; ++k) {
    const study::CampbellPoint& p = r.points[2 * k];
    const double spin_bar = 2.0 * static_cast<double>(k);
    EXPECT_NEAR(p.spin_rate / kScale, spin_bar, 1e-9);
    const double expected = std::sqrt(published[k] * published[k] - spin_bar * spin_bar) * kScale;
    EXPECT_NEAR(std::sqrt(p.stiffened_omega2[0]) / expected, 1.0, 1e-4) << "Omega_bar " << spin_bar;
    ASSERT_TRUE(p.reference_omega2[0]);
    EXPECT_NEAR(std::sqrt(*p.reference_omega2[0]) / expected, 1.0, 1e-4) << "Omega_bar " << spin_bar;
  }
  const double omega0 = kBeta1 * kBeta1 * kScale, spin = 4.0 * kScale;
  EXPECT_NEAR(std::sqrt(-r.points[4].plain_omega2[0]) / std::sqrt(spin * spin - omega0 * omega0), 1.0, 1e-5);
}

TEST(SpinModes, AxialForceLowersTheFrequencyAndReportsBuckling) {
  const fem::BeamModel model = fem::make_beam_model(kSpinBeam, fem::Boundary::clamped_free);
  const double critical = std::numbers::pi * std::numbers::pi * 1.4e4 / (4.0 * 10.0 * 10.0);
  const study::SpinModesResult half =
      study::solve_spin_modes(model, 0.0, 0.0, -0.5 * critical, 6, modal::EigenSolverKind::arpack);
  ASSERT_TRUE(half.buckling_load);
  EXPECT_NEAR(*half.buckling_load / critical, 1.0, 1e-12);
  EXPECT_TRUE(half.warnings.empty());
  const study::SpinModeRow& mode1 = half.rows[0];
  EXPECT_LT(mode1.stiffened_omega2, *mode1.plain_omega2);
  EXPECT_NEAR(std::sqrt(*mode1.plain_omega2) / (kBeta1 * kBeta1 * kScale), 1.0, 1e-6);
  ASSERT_TRUE(mode1.reference_omega2);
  EXPECT_NEAR(std::sqrt(mode1.stiffened_omega2 / *mode1.reference_omega2), 1.0, 1e-6) << "FE against the power series";
  const study::SpinModesResult buckled =
      study::solve_spin_modes(model, 0.0, 0.0, -1.2 * critical, 6, modal::EigenSolverKind::arpack);
  EXPECT_LT(buckled.rows[0].stiffened_omega2, 0.0) << "past the Euler load the first mode diverges";
  EXPECT_FALSE(buckled.warnings.empty());
}

}  // namespace
