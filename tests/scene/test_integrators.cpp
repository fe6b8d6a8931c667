// The fixed-step and explicit integrators against independent references:
//  * generalized-α converges at second order in h (cargo heave vs CVODE at rtol 1e-10);
//  * generalized-α with ρ∞ = 1 on a conservative system: bounded, O(h²) energy error;
//  * generalized-α keeps the index-3 constraint at Newton-tolerance level;
//  * ARKODE adaptive ERK agrees with CVODE on the rigid-boom crane;
//  * ARKODE fixed-step ERK beyond the stability limit is reported "unstable" (never NaN) and
//    runs below it.
#include <gtest/gtest.h>

#include <cstdio>

#include "crane_test_support.hpp"

namespace integrators_test {

using namespace ffrf;
using test::column;
using O = multibody::CraneOutputs;

multibody::RunSettings settings(solve::Integrator kind, double duration, double tolerance) {
  multibody::RunSettings s;
  s.kind = kind;
  s.relative_tolerance = s.absolute_tolerance = tolerance;
  s.duration = duration;
  s.output_interval = 0.05;
  return s;
}

// max |a − b| over the samples with t ∈ [from, to].
double max_difference(const multibody::RunResult& a, const multibody::RunResult& b, double from, double to) {
  double error = 0.0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    if (a.time[i] >= from - 1e-9 && a.time[i] <= to + 1e-9) error = std::max(error, std::abs(a.samples[i].cargo.y() - b.samples[i].cargo.y()));
  }
  return error;
}

// The reference scene, nodal N = 2, at static equilibrium.
struct Reference {
  scene::Scene scene = test::reference_scene();
  std::unique_ptr<multibody::CraneEquations> equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 2, 0, false});
  Eigen::VectorXd z0 = multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z;
};

TEST(Integrators, GeneralizedAlphaConvergesAtSecondOrder) {
  Reference ref;
  const auto cvode = multibody::simulate(*ref.equations, ref.z0, settings(solve::Integrator::cvode, 30.0, 1e-10));
  double errors[3];
  const double steps[3] = {0.025, 0.0125, 0.00625};
  double residual = 0.0;
  for (int i = 0; i < 3; ++i) {
    auto s = settings(solve::Integrator::generalized_alpha, 30.0, 1e-9);
    s.fixed_step = steps[i];
    const auto run = multibody::simulate(*ref.equations, ref.z0, s);
    EXPECT_DOUBLE_EQ(run.stats.step, steps[i]);
    errors[i] = max_difference(run, cvode, 20.0, 30.0);
    for (const auto& o : run.samples) residual = std::max(residual, o.constraint_residual);
    std::printf("generalized-α h = %.4f s: max cargo heave error (20–30 s) %.3e m; steps %ld, residuals %ld, matrices %ld, "
                "Newton %ld, %.3f s\n", steps[i], errors[i], run.stats.steps, run.stats.function_evaluations,
                run.stats.jacobian_evaluations, run.stats.newton_iterations, run.stats.wall_seconds);
  }
  const double order1 = std::log2(errors[0] / errors[1]), order2 = std::log2(errors[1] / errors[2]);
  std::printf("observed orders %.3f, %.3f; max constraint residual %.3e m\n", order1, order2, residual);
  EXPECT_NEAR(order1, 2.0, 0.3);
  EXPECT_NEAR(order2, 2.0, 0.3);
  EXPECT_LT(residual, 1e-8) << "constraint residual [m]";
}

TEST(Integrators, GeneralizedAlphaKeepsTheConstraintAndTheReaction) {
  Reference ref;
  auto s = settings(solve::Integrator::generalized_alpha, 30.0, 1e-6);
  s.absolute_tolerance = 1e-8;  // the default tolerances
  s.fixed_step = 0.01;
  const auto run = multibody::simulate(*ref.equations, ref.z0, s);
  const auto cvode = multibody::simulate(*ref.equations, ref.z0, settings(solve::Integrator::cvode, 30.0, 1e-10));
  double residual = 0.0, reaction = 0.0, reaction_scale = 0.0;
  for (std::size_t i = 0; i < run.samples.size(); ++i) {
    residual = std::max(residual, run.samples[i].constraint_residual);
    reaction = std::max(reaction, (run.samples[i].joint_reaction.head<2>() - cvode.samples[i].joint_reaction.head<2>()).norm());
    reaction_scale = std::max(reaction_scale, cvode.samples[i].joint_reaction.head<2>().norm());
  }
  std::printf("generalized-α h = 0.01 s, rtol 1e-6: max constraint residual %.3e m; joint force vs CVODE %.3e N of %.3e N "
              "(%.2e relative); Newton %.2f iterations per step, %ld matrices\n", residual, reaction, reaction_scale,
              reaction / reaction_scale, static_cast<double>(run.stats.newton_iterations) / static_cast<double>(run.stats.steps),
              run.stats.jacobian_evaluations);
  EXPECT_LT(residual, 1e-8) << "constraint residual [m]";
  EXPECT_LT(reaction / reaction_scale, 1e-3) << "the multiplier is the joint reaction";
}

TEST(Integrators, GeneralizedAlphaWithoutDissipationKeepsTheEnergy) {
  test::ConservativeCrane crane = test::conservative_crane();
  auto& equations = crane.equations;
  const Eigen::VectorXd& z = crane.start;
  double drift[2], first_half[2], second_half[2];
  const double steps[2] = {0.01, 0.005};
  for (int i = 0; i < 2; ++i) {
    auto s = settings(solve::Integrator::generalized_alpha, 40.0, 1e-9);
    s.fixed_step = steps[i];
    s.spectral_radius = 1.0;
    const auto run = multibody::simulate(*equations, z, s);
    EXPECT_TRUE(run.wire_events.empty());
    const auto energy = column(run, [](const O& o) { return o.kinetic_energy + o.gravity_energy + o.strain_energy + o.wire_energy + o.spring_energy; });
    const auto kinetic = column(run, [](const O& o) { return o.kinetic_energy; });
    const double kinetic_max = *std::max_element(kinetic.begin(), kinetic.end());
    first_half[i] = second_half[i] = 0.0;
    for (std::size_t k = 0; k < energy.size(); ++k) {
      double& half = run.time[k] <= 20.0 ? first_half[i] : second_half[i];
      half = std::max(half, std::abs(energy[k] - energy.front()) / kinetic_max);
    }
    drift[i] = std::max(first_half[i], second_half[i]);
    std::printf("ρ∞ = 1, h = %.3f s: max |ΔE| / max E_kin = %.3e (0–20 s %.3e, 20–40 s %.3e), max E_kin %.3g J\n", steps[i],
                drift[i], first_half[i], second_half[i], kinetic_max);
  }
  EXPECT_LT(drift[0], 1e-3);
  EXPECT_NEAR(std::log2(drift[0] / drift[1]), 2.0, 0.3) << "energy error is O(h²)";
  EXPECT_LT(second_half[1], 2.0 * first_half[1]) << "bounded: no growth over time";
}

TEST(Integrators, ArkodeAdaptiveAgreesWithCvodeOnTheRigidBoom) {
  const scene::Scene scene = test::reference_scene();
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::rigid, 1, 0, false});
  const Eigen::VectorXd z0 = multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z;
  const auto cvode = multibody::simulate(*equations, z0, settings(solve::Integrator::cvode, 30.0, 1e-10));
  const auto arkode = multibody::simulate(*equations, z0, settings(solve::Integrator::arkode, 30.0, 1e-8));
  const double error = max_difference(arkode, cvode, 0.0, 30.0);
  std::printf("ARKODE ERK adaptive (rtol 1e-8) vs CVODE: max cargo heave difference %.3e m; steps %ld, RHS %ld, "
              "error-test failures %ld, %.3f s\n", error, arkode.stats.steps, arkode.stats.function_evaluations,
              arkode.stats.error_test_failures, arkode.stats.wall_seconds);
  EXPECT_LT(error, 1e-5);
  EXPECT_EQ(arkode.stats.jacobian_evaluations, 0);
  EXPECT_EQ(arkode.stats.newton_iterations, 0);
}

TEST(Integrators, ArkodeBeyondTheStabilityLimitIsReportedUnstable) {
  const scene::Scene scene = test::reference_scene();
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 8, 0, false});
  const Eigen::VectorXd z0 = multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z;
  const double limit = solve::explicit_stable_step(*equations, z0);
  std::printf("nodal N = 8: linearized ERK stability limit %.4e s (imaginary-axis boundary %.4f)\n", limit,
              solve::explicit_imaginary_axis_boundary());
  {  // the same boom without structural damping: only the imaginary-axis boundary matters
    scene::Scene undamped_scene = scene;
    undamped_scene.boom.damping_ratio = 0.0;
    auto undamped = scene::build_crane_equations(undamped_scene, {scene::BoomKind::nodal, 8, 0, false});
    const double undamped_limit =
        solve::explicit_stable_step(*undamped, multibody::solve_static_equilibrium(*undamped, undamped->initial_guess()).z);
    std::printf("without structural damping: limit %.4e s (ω_max ≈ %.4g rad/s)\n", undamped_limit,
                solve::explicit_imaginary_axis_boundary() / undamped_limit);
    EXPECT_GT(undamped_limit, 10.0 * limit) << "stiffness-proportional damping puts the top modes on the real axis at ≈ −βω²";
  }
  auto s = settings(solve::Integrator::arkode, 2.0, 1e-8);
  s.fixed_step = 100.0 * limit;
  try {
    multibody::simulate(*equations, z0, s);
    ADD_FAILURE() << "h = 100 × the limit must fail";
  } catch (const solve::SolverFailure& failure) {
    std::printf("%s\n", failure.what());
    EXPECT_NE(failure.cause().find("unstable"), std::string::npos) << failure.what();
    EXPECT_EQ(failure.solver(), "ARKODE ERK");
  }
  s.fixed_step = 1.1 * limit;
  s.duration = 0.1;
  EXPECT_THROW(multibody::simulate(*equations, z0, s), solve::SolverFailure) << "10 % beyond the limit";
  s.fixed_step = 0.9 * limit;
  const auto run = multibody::simulate(*equations, z0, s);
  for (const auto& o : run.samples) ASSERT_TRUE(std::isfinite(o.cargo.y()) && std::isfinite(o.kinetic_energy));
  std::printf("h = 0.9 × limit: %ld steps, max cargo heave change %.3e m\n", run.stats.steps,
              std::abs(run.samples.back().cargo.y() - run.samples.front().cargo.y()));
}

}  // namespace integrators_test
