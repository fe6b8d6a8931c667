// Geometric stiffening of the floating-frame boom (multibody/floating_frame_body.hpp: −(K + K_σ + θ̇²K_c)η)
// end to end, against closed-form beam theory:
//  * static prestress: a light boom on a held hub at φ = 45° carrying a heavy cargo at its tip. The
//    wire hangs vertically from the tip at equilibrium, so in the (fixed) boom frame the tip carries
//    the constant axial compression P = W sin φ and transverse load Q = W cos φ. Without stiffening
//    the tip deflects Q L³/(3EI) (+ q L⁴/(8EI) from the boom's own weight q = ρA g cos φ); second-order
//    beam-column theory (EI v'''' + P v'' = 0, clamped–free, tip shear Q) gives
//    δ = (Q/(P k))(tan kL − kL), k = √(P/EI), which is what K + K_σ reproduces with the reference axial
//    force N = −P of the undeformed boom. The load components in the boom frame do not depend on the
//    deflection because the wire stays vertical, so the only differences left are the mesh (N = 32),
//    the boom's own weight (ρA g L / W ≈ 3e-4, its transverse and axial parts) and round-off: 1e-3.
//    Measured: 1.3e-11 (linear), 1.8e-4 (nodal and modal k = 4 + static, beam-column).
//  * centrifugal: a beam spun at a constant Ωs above its first bending frequency ω1: the linear model
//    without stiffening softens by Ωs² M, so the first mode grows like exp(σ t), σ = √(Ωs² − ω1²)
//    (the Coriolis coupling to the much stiffer axial modes shifts it slightly); with the centrifugal
//    stiffness θ̇² K_c it stays bounded.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "crane_test_support.hpp"
#include "fem/analytic_beam.hpp"

namespace geometric_stiffening_test {

using namespace ffrf;

constexpr double kLength = 10.0, kE = 2.1e11, kI = 1.0e-4, kRhoA = 1.0;

// The Euler load π²EI/(4L²) times `fraction` carried as tip compression at 45°: W = fraction P_cr / sin φ.
scene::Scene prestressed_boom(double fraction) {
  const double euler = std::numbers::pi * std::numbers::pi * kE * kI / (4.0 * kLength * kLength);
  const double weight = fraction * euler / std::sin(std::numbers::pi / 4.0);
  return test::hub_crane_scene({kE, 1.0e-2, kI, kRhoA, 32, weight / 9.81, 1.0e9});
}

double static_tip_deflection(const scene::Scene& scene, scene::BoomChoice choice) {
  auto equations = scene::build_crane_equations(scene, choice);
  return multibody::solve_static_equilibrium(*equations, equations->initial_guess()).outputs.tip_deflection.y();
}

TEST(GeometricStiffening, StaticPrestressGivesTheBeamColumnDeflection) {
  const double fraction = 0.5;
  const scene::Scene scene = prestressed_boom(fraction);
  const double g = scene.environment.gravity, phi = std::numbers::pi / 4.0, EI = kE * kI, L = kLength;
  const double W = scene.cargo->mass * g, P = W * std::sin(phi), Q = W * std::cos(phi);
  const double q = kRhoA * g * std::cos(phi);
  const double linear = Q * L * L * L / (3.0 * EI) + q * L * L * L * L / (8.0 * EI);
  const double k = std::sqrt(P / EI);
  const double beam_column = Q / (P * k) * (std::tan(k * L) - k * L);

  using scene::BoomKind;
  using scene::Stiffening;
  const double nodal_none = -static_tip_deflection(scene, {BoomKind::nodal, 32, 0, false, modal::EigenSolverKind::arpack, Stiffening::none});
  const double nodal_static =
      -static_tip_deflection(scene, {BoomKind::nodal, 32, 0, false, modal::EigenSolverKind::arpack, Stiffening::static_load});
  const double modal_static =
      -static_tip_deflection(scene, {BoomKind::modal, 32, 4, true, modal::EigenSolverKind::arpack, Stiffening::static_load});
  EXPECT_NEAR(nodal_none / linear, 1.0, 1e-3);
  EXPECT_NEAR(nodal_static / beam_column, 1.0, 1e-3);
  EXPECT_NEAR(modal_static / beam_column, 1.0, 1e-3);
  EXPECT_GT(beam_column / linear, 1.5) << "the test must load the boom enough for the prestress to matter";
  std::printf("P/P_cr %.2f: linear %.6g m (nodal %.6g), beam-column %.6g m (nodal %.6g, modal 4+static %.6g); "
              "errors %.2e %.2e %.2e\n",
              fraction, linear, nodal_none, beam_column, nodal_static, modal_static, nodal_none / linear - 1.0,
              nodal_static / beam_column - 1.0, modal_static / beam_column - 1.0);
}

// The Simo–Vu-Quoc beam (cases/spin_up_beam.toml) at a constant spin Ωs, no gravity, N = 4.
scene::Scene constant_spin(double spin_rate, scene::Stiffening stiffening) {
  scene::Scene scene = test::constant_spin_beam(spin_rate, stiffening, 4);
  scene.simulation.deflection_limit = 0.2;
  return scene;
}

multibody::RunSettings spin_settings(const scene::Scene& scene) {
  multibody::RunSettings settings;
  settings.duration = 10.0;
  settings.output_interval = 0.02;
  settings.max_order = 2;  // undamped boom: A-stable BDF orders only (docs/stability.md)
  settings.monitor.boom_length = scene.boom.mesh.length;
  return settings;
}

TEST(GeometricStiffening, CentrifugalStiffeningPreventsTheSpinDivergence) {
  const double spin = 6.0;
  const scene::Scene soft = constant_spin(spin, scene::Stiffening::none);
  const double omega1 = fem::analytic_bending_modes(soft.boom.mesh, fem::Boundary::clamped_free, 1).front().angular_frequency;
  ASSERT_GT(spin, omega1);
  const double sigma = std::sqrt(spin * spin - omega1 * omega1);
  double measured = 0.0;
  {
    auto equations = scene::build_crane_equations(soft, {scene::BoomKind::nodal, 4, 0, false});
    // Seed the bending mode with a 1 µm transverse tip deflection (free DOFs (u, v, φ) per node: the
    // tip's v is the second last), so the divergence does not rest on round-off and Coriolis coupling.
    Eigen::VectorXd start = equations->initial_guess();
    start(start.size() - 2) = 1e-6;
    try {
      multibody::simulate(*equations, start, spin_settings(soft));
      FAIL() << "without stiffening the beam spun above ω1 must diverge";
    } catch (const solve::SolverFailure& failure) {
      ASSERT_EQ(failure.kind(), solve::FailureKind::divergence) << failure.what();
      measured = failure.value();
      EXPECT_NEAR(measured / sigma, 1.0, 0.1) << failure.what();
    }
  }
  const scene::Scene stiff = constant_spin(spin, scene::Stiffening::centrifugal);
  auto equations = scene::build_crane_equations(stiff, {scene::BoomKind::nodal, 4, 0, false});
  const multibody::RunSettings settings = spin_settings(stiff);
  const multibody::RunResult run = multibody::simulate(*equations, equations->initial_guess(), settings);
  ASSERT_NEAR(run.time.back(), settings.duration, 1e-9);
  double largest = 0.0;
  for (const multibody::CraneOutputs& sample : run.samples) largest = std::max(largest, std::abs(sample.tip_deflection.y()));
  EXPECT_LT(largest, 0.01 * settings.monitor.deflection_limit * stiff.boom.mesh.length);
  std::printf("Ωs %.1f rad/s, ω1 %.4f rad/s: σ theory %.4f 1/s, measured %.4f 1/s (%.2f %%); stiffened max |v_tip| %.3g m\n",
              spin, omega1, sigma, measured, 100.0 * (measured / sigma - 1.0), largest);
}

}  // namespace geometric_stiffening_test
