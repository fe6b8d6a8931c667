// The measured largest stable step of fixed-step ARKODE ERK (solve/explicit_stability.hpp)
// against independent theory: the Runge–Kutta stability polynomial's Taylor coefficients, the
// analytic axial frequency of a one-element bar, the linearized crane's Jacobian eigenvalues
// (solve::explicit_stable_step: linear algebra, no time stepping) and the boom's own modes
// with their stiffness-proportional damping (cases/stability_theory.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "study/stability_theory.hpp"
#include "solve/explicit_stability.hpp"
#include "../scene/crane_test_support.hpp"

namespace ffrf {
namespace explicit_stability_test {

using scene::BoomKind;

scene::Scene calm_reference_scene() {
  scene::Scene scene = test::reference_scene();
  scene.wave.reset();  // the limit is a property of the linearization about the static equilibrium
  return scene;
}

struct Measured {
  std::unique_ptr<multibody::CraneEquations> equations;
  Eigen::VectorXd z0;
  double jacobian_limit;
  solve::StableStepMeasurement measurement;
};

Measured measure(const scene::Scene& scene, const scene::BoomChoice& choice) {
  Measured m{scene::build_crane_equations(scene, choice), {}, 0.0, {}};
  m.z0 = multibody::solve_static_equilibrium(*m.equations, m.equations->initial_guess()).z;
  m.jacobian_limit = solve::explicit_stable_step(*m.equations, m.z0);
  // Start the bracket away from the theory so the search has to find the limit itself.
  m.measurement = solve::measure_stable_step(*m.equations, m.z0, 0.37 * m.jacobian_limit);
  std::printf("%-24s measured h ∈ [%.5g, %.5g] s (%d trials, %ld RHS, window %ld steps), Jacobian bound %.5g s\n",
              choice.label().c_str(), m.measurement.stable_step, m.measurement.unstable_step, m.measurement.trials,
              m.measurement.rhs_evaluations, m.measurement.window_steps, m.jacobian_limit);
  return m;
}

TEST(ExplicitStability, StabilityPolynomialIsTheFourthOrderTaylorSeriesOfExp) {
  // Coefficients c_k of R(w) = Σ c_k w^k by a discrete Fourier transform on the unit circle.
  constexpr int points = 16;
  std::vector<double> c(points);
  for (int k = 0; k < points; ++k) {
    std::complex<double> sum = 0.0;
    for (int j = 0; j < points; ++j) {
      const std::complex<double> w = std::polar(1.0, 2.0 * std::numbers::pi * j / points);
      sum += solve::explicit_stability_function(w) * std::conj(std::pow(w, k));
    }
    c[static_cast<std::size_t>(k)] = (sum / static_cast<double>(points)).real();
  }
  const double factorial[] = {1.0, 1.0, 2.0, 6.0, 24.0};
  for (int k = 0; k <= 4; ++k) EXPECT_NEAR(c[static_cast<std::size_t>(k)], 1.0 / factorial[k], 1e-13) << "order 4: k = " << k;
  for (int k = 5; k < points; ++k) EXPECT_NEAR(c[static_cast<std::size_t>(k)], 0.0, 1e-13) << "k = " << k;
  // Then |R(iy)|² − 1 = y⁶ (y² − 8) / 576: the imaginary-axis boundary is β_I = 2√2 (classical RK4's).
  const double beta_i = 2.0 * std::numbers::sqrt2;
  EXPECT_NEAR(solve::explicit_imaginary_axis_boundary(), beta_i, 1e-6) << "integrate_explicit's table";
  EXPECT_NEAR(solve::explicit_ray_boundary({0.0, 1.0}), beta_i, 1e-6) << "the measurement's table";
  EXPECT_NEAR(std::abs(solve::explicit_stability_function({0.0, beta_i})), 1.0, 1e-12);
}

TEST(ExplicitStability, HighestFrequencyOfTheOneElementBoomIsTheAxialBar) {
  const scene::Scene scene = calm_reference_scene();
  const fem::BeamMesh& mesh = scene.boom.mesh;
  // One clamped–free element: axial K = EA/L, consistent M = ρAL/3 → ω = √(3 EA / ρA) / L.
  const double axial = std::sqrt(3.0 * mesh.section.youngs_modulus * mesh.section.area / mesh.section.mass_per_length) / mesh.length;
  EXPECT_NEAR(study::highest_boom_frequency(scene, {BoomKind::nodal, 1, 0, false}), axial, 1e-9 * axial);
  EXPECT_EQ(study::highest_boom_frequency(scene, {BoomKind::rigid, 1, 0, false}), 0.0);
  // Without damping the boom bound is β_I / ω_max, whatever the modes below it.
  const Eigen::VectorXd omega = study::boom_angular_frequencies(scene, {BoomKind::nodal, 4, 0, false});
  EXPECT_NEAR(study::damped_boom_step_limit(omega, 0.0), study::undamped_boom_step_limit(omega.maxCoeff()),
              1e-9 * study::undamped_boom_step_limit(omega.maxCoeff()));
}

TEST(ExplicitStability, MeasuredLimitAgreesWithTheLinearizedCraneForCoarseMeshes) {
  // The assertion uses the coupled system's Jacobian bound: it sees every mode (boom, wire–cargo,
  // hull) and the boom's damping, so it is the bound for N = 1 (wire, axial bar and cargo compete)
  // as well as for N = 2, 4 (the boom's overdamped top mode). Where the boom limits, its own damped
  // bound must agree too; the undamped β_I/ω_max is far off there (damping moves the top modes to
  // λ ≈ −βω² on the real axis).
  const scene::Scene scene = calm_reference_scene();
  for (const int elements : {1, 2, 4}) {
    const scene::BoomChoice choice{BoomKind::nodal, elements, 0, false};
    const Measured m = measure(scene, choice);
    ASSERT_TRUE(m.measurement.converged);
    EXPECT_LE(m.measurement.relative_width(), 0.02);
    EXPECT_NEAR(m.measurement.stable_step / m.jacobian_limit, 1.0, 0.2) << choice.label();
    const Eigen::VectorXd omega = study::boom_angular_frequencies(scene, choice);
    const double boom = study::damped_boom_step_limit(omega, scene::boom_stiffness_damping(scene));
    const double undamped = study::undamped_boom_step_limit(omega.maxCoeff());
    std::printf("   boom bounds: damped %.5g s, undamped β_I/ω_max %.5g s (ω_max %.5g rad/s)\n", boom, undamped, omega.maxCoeff());
    if (elements >= 2) {
      EXPECT_NEAR(m.measurement.stable_step / boom, 1.0, 0.2) << choice.label();
    }
    if (elements == 4) {
      EXPECT_LT(m.measurement.stable_step, 0.2 * undamped) << "the damped top mode limits, not β_I/ω_max";
    }
  }
}

TEST(ExplicitStability, BeyondTheLimitIsReportedUnstableAndBelowItCompletes) {
  const scene::Scene scene = calm_reference_scene();
  const Measured m = measure(scene, {BoomKind::nodal, 4, 0, false});
  ASSERT_TRUE(m.measurement.converged);
  const solve::StableStepSearch search;
  const Eigen::VectorXd start = m.z0 + solve::stability_seed(*m.equations, search.seed_size);
  multibody::RunSettings settings;
  settings.kind = solve::Integrator::arkode;
  settings.output_interval = 0.01;
  settings.duration = 1.0;  // ≥ 3 000 steps at these sizes: longer than the measurement window
  settings.fixed_step = 1.3 * m.measurement.stable_step;
  try {
    const auto run = multibody::simulate(*m.equations, start, settings);
    ADD_FAILURE() << "1.3 × the measured limit returned " << run.samples.size() << " samples";
  } catch (const solve::SolverFailure& failure) {
    std::printf("1.3 ×: %s\n", failure.what());
    EXPECT_EQ(failure.cause().rfind("unstable:", 0), 0U) << failure.cause();
    EXPECT_NE(failure.cause().find("stability limit"), std::string::npos) << "names the limit: " << failure.cause();
    EXPECT_NE(failure.remedy().find("reduce the fixed step"), std::string::npos) << failure.remedy();
    EXPECT_EQ(failure.remedy().find("--"), std::string::npos) << "neutral words, no option names: " << failure.remedy();
  }
  settings.fixed_step = 0.7 * m.measurement.stable_step;
  const auto run = multibody::simulate(*m.equations, start, settings);
  ASSERT_EQ(run.samples.size(), 101U);
  for (const auto& o : run.samples) {
    ASSERT_TRUE(std::isfinite(o.kinetic_energy) && std::isfinite(o.tip_deflection.norm()) && std::isfinite(o.wire_tension));
  }
}

TEST(ExplicitStability, ModalBoomTakesStepsLargerByTheSquaredFrequencyRatio) {
  const scene::Scene scene = calm_reference_scene();
  const scene::BoomChoice modal{BoomKind::modal, 16, 2, true}, nodal{BoomKind::nodal, 16, 0, false};
  const Measured m_modal = measure(scene, modal), m_nodal = measure(scene, nodal);
  ASSERT_TRUE(m_modal.measurement.converged && m_nodal.measurement.converged);
  const double step_ratio = m_modal.measurement.stable_step / m_nodal.measurement.stable_step;
  const double frequency_ratio = study::highest_boom_frequency(scene, nodal) / study::highest_boom_frequency(scene, modal);
  std::printf("h(modal k=2+static) / h(nodal N=16) = %.4g; ω_max ratio %.4g, squared %.4g\n", step_ratio,
              frequency_ratio, frequency_ratio * frequency_ratio);
  EXPECT_GE(step_ratio, 0.8 * frequency_ratio) << "at least the undamped ratio β_I/ω";
  // Both top modes are overdamped (ζ = βω/2 ≫ 1): λ ≈ −βω², so h ∝ 1/ω².
  EXPECT_NEAR(step_ratio / (frequency_ratio * frequency_ratio), 1.0, 0.2);
}

TEST(ExplicitStability, EveryModelOfTheDefaultListAgreesWithTheLinearizedCrane) {
  // Nodal N = 1 … 64 and modal k = 1 … 12 with static modes (≈ 2 s on one core): the coupled
  // bound holds to 10 % everywhere (rigid: +6 %, the wire–cargo bounce against the hull's pitch);
  // every elastic model is limited by the boom, whose damped bound also agrees to 10 %.
  const scene::Scene scene = calm_reference_scene();
  std::vector<scene::BoomChoice> models{{BoomKind::rigid, 1, 0, false}};
  for (int n = 1; n <= 64; n *= 2) models.push_back({BoomKind::nodal, n, 0, false});
  for (int k = 1; k <= 12; ++k) models.push_back({BoomKind::modal, 16, k, true});
  for (const scene::BoomChoice& choice : models) {
    const Measured m = measure(scene, choice);
    ASSERT_TRUE(m.measurement.converged) << choice.label();
    EXPECT_NEAR(m.measurement.stable_step / m.jacobian_limit, 1.0, 0.1) << choice.label();
    if (choice.kind == BoomKind::rigid) continue;
    const double boom =
        study::damped_boom_step_limit(study::boom_angular_frequencies(scene, choice), scene::boom_stiffness_damping(scene));
    EXPECT_NEAR(m.measurement.stable_step / boom, 1.0, 0.1) << choice.label();
  }
}

}  // namespace explicit_stability_test
}  // namespace ffrf
