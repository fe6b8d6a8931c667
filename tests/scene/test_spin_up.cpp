// The driven hub and the spin-up benchmark (Simo & Vu-Quoc 1986; cases/spin_up_beam.toml):
//  * the prescribed rotation's pose, rate and acceleration are derivatives of one another
//    (central differences) and continuous at the end of the spin-up;
//  * the driving constraint's reaction on a rigid beam equals rigid-body dynamics by hand:
//    moment J_B θ̈ + m r (L/2) θ̈ with J_B = ρA L³/3, force m a_G with a_G = θ̈ Ĩ c − θ̇² c, c the
//    centroid, for the root on the axis and on a 2 m arm —
//    in minimal coordinates (CVODE) and through the multipliers of the time-dependent clamp (IDA);
//  * the linear floating-frame beam without stiffening diverges once Ω(t) passes its first bending
//    frequency ω1 (analytic clamped–free value), the detector names it with a growth rate no larger
//    than the instantaneous √(Ω² − ω1²); with centrifugal stiffening it stays bounded, and nodal
//    (N = 10) and modal (k = 4 + static) agree within 2 % over 0–30 s (the acceptance criterion for the spin-up case);
//  * the full-coordinate formulations with C_t and γ = −C_tt (IDA index-2, index-1 + projection)
//    reproduce the minimal-coordinate run: a second method for the driving-constraint terms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"
#include "multibody/crane_run.hpp"
#include "multibody/crane_statics.hpp"
#include "fem/analytic_beam.hpp"

namespace ffrf {
namespace spin_up_test {

scene::Scene spin_scene() { return scene::load_scene(FFRF_SOURCE_DIR "/cases/spin_up_beam.toml"); }

multibody::RunSettings spin_settings(const scene::Scene& scene, solve::Integrator kind, double duration) {
  multibody::RunSettings settings;
  settings.kind = kind;
  settings.relative_tolerance = 1e-7;
  settings.absolute_tolerance = 1e-7;
  settings.duration = duration;
  settings.output_interval = scene.simulation.output_interval;
  settings.max_order = 2;  // the undamped beam: A-stable BDF (docs/stability.md)
  settings.monitor.boom_length = scene.boom.mesh.length;
  settings.monitor.deflection_limit = scene.simulation.deflection_limit;
  return settings;
}

multibody::RunResult run(const scene::Scene& scene, const scene::BoomChoice& choice, const multibody::RunSettings& settings) {
  auto equations = scene::build_crane_equations(scene, choice);
  const Eigen::VectorXd z0 = multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z;
  return multibody::simulate(*equations, z0, settings);
}

// Ω(t) of the spin-up profile (the scene's Ts).
double spin_rate(const scene::Scene& scene, double t) {
  const double ts = scene.hub->spin_up_time, omega = scene.hub->spin_rate;
  return t >= ts ? omega : omega / ts * (t - ts / (2.0 * std::numbers::pi) * std::sin(2.0 * std::numbers::pi * t / ts));
}

TEST(PrescribedMotion, RateAndAccelerationAreDerivativesOfThePose) {
  multibody::PrescribedMotion motion;
  motion.pose0 = Eigen::Vector3d(1.0, 2.0, 0.3);
  motion.profile = multibody::RotationProfile::spin_up;
  motion.spin_rate = 4.0;
  motion.spin_up_time = 15.0;
  const double h = 1e-5;
  for (double t : {0.0, 0.7, 5.0, 7.5, 14.2, 15.0 + 2 * h, 22.0}) {
    const double rate_fd = (motion.pose(t + h)(2) - motion.pose(t - h)(2)) / (2 * h);
    const double acc_fd = (motion.velocity(t + h)(2) - motion.velocity(t - h)(2)) / (2 * h);
    EXPECT_NEAR(motion.velocity(t)(2), rate_fd, 1e-8) << t;
    EXPECT_NEAR(motion.acceleration(t)(2), acc_fd, 1e-7) << t;
    EXPECT_EQ(motion.pose(t).head<2>(), motion.pose0.head<2>());
  }
  // Continuous at Ts: θ(Ts) = Ωs Ts / 2, θ̇(Ts) = Ωs, θ̈(Ts) = 0.
  EXPECT_NEAR(motion.pose(15.0)(2) - 0.3, 4.0 * 15.0 / 2.0, 1e-12);
  EXPECT_NEAR(motion.velocity(15.0 - 1e-12)(2), 4.0, 1e-9);
  EXPECT_NEAR(motion.acceleration(15.0 - 1e-9)(2), 0.0, 1e-9);
}

TEST(DrivenHub, RigidBeamReactionIsRigidBodyDynamicsInMinimalAndFullCoordinates) {
  // Root on the axis (r = 0) and on an arm (r = 2 m: the root itself accelerates, θ̈ Ĩ A b − θ̇² A b,
  // and the time-dependent clamp's C_t, C_tt carry the arm). Centroid c = (r + L/2) e_θ:
  // force m (θ̈ Ĩ c − θ̇² c); moment about the root B: J_B θ̈ + m r (L/2) θ̈ with J_B = m L²/3.
  for (const double arm : {0.0, 2.0}) {
    scene::Scene scene = spin_scene();
    scene.hub->radius = arm;
    scene.boom.mount->root_x = arm;
    const double mass = scene.boom.mesh.total_mass(), length = scene.boom.mesh.length;
    const double root_inertia = mass * length * length / 3.0;  // ρA L³/3
    const multibody::PrescribedMotion motion{Eigen::Vector3d::Zero(), multibody::RotationProfile::spin_up, 4.0, 15.0};
    // Minimal coordinates: no degrees of freedom remain, the reaction follows from the kinematics
    // (round-off). IDA integrates the frame against the time-dependent clamp (rtol 1e-7 on an angle
    // that reaches 50 rad): its residual |C| = |ΔR| + L|Δθ| stays below 1e-5 m (Δθ ~ 2e-7 rad) and the
    // reaction, λ recomputed from the state at each output, follows within 1e-4. Projection puts every
    // output state on C(q, t) = 0.
    for (const auto& [kind, relative, drift] : {std::tuple{solve::Integrator::cvode, 1e-10, 1e-12},
                                                std::tuple{solve::Integrator::ida, 1e-4, 1e-5},
                                                std::tuple{solve::Integrator::projection, 1e-4, 1e-8}}) {
      const multibody::RunResult result = run(scene, {scene::BoomKind::rigid}, spin_settings(scene, kind, 20.0));
      const double force_scale = mass * (arm + 0.5 * length) * 16.0;  // m |c| Ωs²
      const double moment_scale = (root_inertia + mass * arm * 0.5 * length) * 8.0 / 15.0;  // θ̈_max = 2Ωs/Ts
      for (std::size_t k = 0; k < result.time.size(); k += 37) {
        const double t = result.time[k];
        const double theta = motion.pose(t)(2), rate = motion.velocity(t)(2), acc = motion.acceleration(t)(2);
        const Eigen::Vector2d centroid = (arm + 0.5 * length) * Eigen::Vector2d(std::cos(theta), std::sin(theta));
        const Eigen::Vector2d force = mass * (acc * Eigen::Vector2d(-centroid.y(), centroid.x()) - rate * rate * centroid);
        const double moment = (root_inertia + mass * arm * 0.5 * length) * acc;
        const multibody::CraneOutputs& o = result.samples[k];
        SCOPED_TRACE(std::string(to_string(kind)) + ", r = " + std::to_string(arm) + " m, t = " + std::to_string(t));
        EXPECT_NEAR(o.joint_reaction.z(), moment, relative * moment_scale);
        EXPECT_NEAR((o.joint_reaction.head<2>() - force).norm(), 0.0, relative * force_scale);
        EXPECT_NEAR(o.hull.z(), theta, 1e-12);  // the hub follows θ(t)
        EXPECT_LT(o.constraint_residual, drift);
      }
    }
  }
}

TEST(SpinUp, UnstiffenedLinearBeamDivergesOnceTheSpinPassesTheFirstBendingFrequency) {
  scene::Scene scene = spin_scene();
  const double omega1 = fem::analytic_bending_modes(scene.boom.mesh, fem::Boundary::clamped_free, 1)[0].angular_frequency;
  EXPECT_NEAR(omega1, 3.80, 0.005);  // (β1 L)² √(EI / (μ L⁴)) = 1.8751² · √(1.4e4 / (1.2 · 10⁴)) = 3.797 rad/s
  scene::BoomChoice choice{scene::BoomKind::nodal, 10};
  choice.stiffening = scene::Stiffening::none;
  const multibody::RunSettings settings = spin_settings(scene, solve::Integrator::cvode, 30.0);
  try {
    run(scene, choice, settings);
    FAIL() << "the unstiffened spin-up did not diverge";
  } catch (const solve::SolverFailure& failure) {
    EXPECT_EQ(failure.kind(), solve::FailureKind::divergence) << failure.what();
    const double omega_at_detection = spin_rate(scene, failure.time());
    EXPECT_GT(omega_at_detection, omega1) << "detected at t = " << failure.time();
    // The growth rate is positive and no faster than the instantaneous rate √(Ω² − ω1²) of the
    // softened mode (Ω(t) rises through the window, so the fitted rate is below it).
    EXPECT_GT(failure.value(), 0.05);
    EXPECT_LE(failure.value(), std::sqrt(omega_at_detection * omega_at_detection - omega1 * omega1) * 1.05);
    ASSERT_NE(multibody::partial_run(failure), nullptr);
    const multibody::RunResult& partial = *multibody::partial_run(failure);
    ASSERT_FALSE(partial.samples.empty());
    for (const auto& sample : partial.samples) ASSERT_TRUE(sample.tip_deflection.allFinite());
    EXPECT_GT(partial.samples.back().tip_deflection.norm(), scene.simulation.deflection_limit * scene.boom.mesh.length);
  }
}

TEST(SpinUp, CentrifugalStiffeningKeepsTheTipBoundedAndNodalAgreesWithModal) {
  const scene::Scene scene = spin_scene();  // boom.stiffening = centrifugal
  const multibody::RunSettings settings = spin_settings(scene, solve::Integrator::cvode, 30.0);
  const multibody::RunResult nodal = run(scene, {scene::BoomKind::nodal, 10}, settings);
  const multibody::RunResult modal = run(scene, {scene::BoomKind::modal, 10, 4, true}, settings);
  ASSERT_EQ(nodal.time.size(), modal.time.size());
  double largest = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < nodal.time.size(); ++k) {
    largest = std::max(largest, std::abs(nodal.samples[k].tip_deflection.y()));
    difference = std::max(difference, std::abs(nodal.samples[k].tip_deflection.y() - modal.samples[k].tip_deflection.y()));
  }
  EXPECT_LT(largest, 0.1 * scene.boom.mesh.length) << "bounded: well inside the linear model's range";
  EXPECT_GT(largest, 0.05) << "the spin-up does bend the beam (lagging tip)";
  EXPECT_LT(difference / largest, 0.02) << "nodal N=10 vs modal k=4+static, max |Δδ| / max |δ|";
  // After the spin-up the tip oscillates about the undeflected position (no tangential load at
  // constant Ω): the mean over the last 15 s is small against the peak.
  double mean = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < nodal.time.size(); ++k) {
    if (nodal.time[k] >= 15.0) {
      mean += nodal.samples[k].tip_deflection.y();
      ++count;
    }
  }
  EXPECT_LT(std::abs(mean / count), 0.1 * largest);
}

TEST(SpinUp, FullCoordinateFormulationsReproduceTheMinimalRunOfTheDrivenBase) {
  for (const double arm : {0.0, 1.5}) {  // root on the axis, and on an arm (the clamp's C_t, C_tt carry it)
  SCOPED_TRACE("r = " + std::to_string(arm) + " m");
  scene::Scene scene = spin_scene();
  scene.hub->radius = arm;
  scene.boom.mount->root_x = arm;
  const scene::BoomChoice choice{scene::BoomKind::modal, 10, 4, true};
  const multibody::RunResult minimal = run(scene, choice, spin_settings(scene, solve::Integrator::cvode, 20.0));
  double largest = 0.0;
  for (const auto& sample : minimal.samples) largest = std::max(largest, std::abs(sample.tip_deflection.y()));
  for (solve::Integrator kind : {solve::Integrator::ida, solve::Integrator::projection}) {
    const multibody::RunResult full = run(scene, choice, spin_settings(scene, kind, 20.0));
    ASSERT_EQ(full.time.size(), minimal.time.size());
    double difference = 0.0, drift = 0.0;
    for (std::size_t k = 0; k < full.time.size(); ++k) {
      difference = std::max(difference, std::abs(full.samples[k].tip_deflection.y() - minimal.samples[k].tip_deflection.y()));
      drift = std::max(drift, full.samples[k].constraint_residual);
    }
    EXPECT_LT(difference / largest, 1e-3) << to_string(kind);
    EXPECT_LT(drift, 1e-6) << to_string(kind) << ": the rotating clamp is held";
  }
  }
}

}  // namespace spin_up_test
}  // namespace ffrf
