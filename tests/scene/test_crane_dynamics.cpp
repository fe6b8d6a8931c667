// Coupled-crane dynamics against independent references:
//  * energy: hull on springs only (no water, waves, damping), total energy conserved over 100 s;
//  * heave free decay of the hull alone: T = 2π √((m + A33) / (ρ g L B)) (box: linear restoring);
//  * a cargo hanging from a rigid boom on a fixed hull: the rigid body on a string is a double
//    pendulum (string ℓ, hook-to-G distance h, inertia I): linearized
//    m[[ℓ², ℓh], [ℓh, h² + I/m]] ẍ + m g [[ℓ, 0], [0, h]] x = 0, lower root derived in the test;
//  * IDA (Lagrange multipliers) and CVODE (minimal coordinates) agree; the constraint holds;
//  * a very stiff boom (E × 10⁶) reproduces the rigid boom.
#include <gtest/gtest.h>

#include <cstdio>

#include "crane_test_support.hpp"

namespace crane_dynamics_test {

using namespace ffrf;
using test::column;

multibody::RunSettings tight(double duration, solve::Integrator kind = solve::Integrator::cvode) {
  multibody::RunSettings s;
  s.kind = kind;
  s.relative_tolerance = 1e-9;
  s.absolute_tolerance = 1e-9;
  s.duration = duration;
  s.output_interval = 0.02;
  return s;
}

TEST(CraneDynamics, EnergyIsConservedWithoutWaterAndDamping) {
  test::ConservativeCrane crane = test::conservative_crane();
  auto& equations = crane.equations;
  const Eigen::VectorXd& z = crane.start;
  const multibody::RunResult run = multibody::simulate(*equations, z, tight(100.0));
  EXPECT_TRUE(run.wire_events.empty());
  const auto energy = column(run, [](const multibody::CraneOutputs& o) {
    return o.kinetic_energy + o.gravity_energy + o.strain_energy + o.wire_energy + o.spring_energy;
  });
  const auto kinetic = column(run, [](const multibody::CraneOutputs& o) { return o.kinetic_energy; });
  const double kinetic_max = *std::max_element(kinetic.begin(), kinetic.end());
  double drift = 0.0;
  for (double e : energy) drift = std::max(drift, std::abs(e - energy.front()));
  EXPECT_GT(kinetic_max, 1e6) << "the test must actually move";
  EXPECT_LT(drift / kinetic_max, 1e-6) << "energy drift " << drift << " J against max kinetic energy " << kinetic_max << " J";
  std::printf("energy drift %.3g J, max kinetic %.3g J, relative %.3g, steps %ld\n", drift, kinetic_max, drift / kinetic_max, run.stats.steps);
}

TEST(CraneDynamics, HeavePeriodOfTheHullAloneMatchesHydrostatics) {
  scene::Scene scene = test::reference_scene();
  scene.wave.reset();
  scene.hull->g1_aft_of_mid_length = 0.0;        // G1 above the centre of flotation: heave uncoupled
  scene.boom.mesh.section.mass_per_length = 1.0;  // negligible boom and cargo: "the hull alone"
  scene.cargo->mass = 1.0;
  scene.wire->stiffness = 1.0e3;
  scene.radiation.surge_damping = scene.radiation.heave_damping = scene.radiation.pitch_damping = 0.0;
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::rigid, 1, 0, false});
  Eigen::VectorXd z = multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z;
  z(1) += 0.2;  // heave release: the hull, and the tiny cargo with it (the wire keeps its stretch)
  z(4) += 0.2;
  multibody::RunSettings settings = tight(60.0);
  settings.output_interval = 0.01;
  const multibody::RunResult run = multibody::simulate(*equations, z, settings);
  const double period = test::mean_period(run.time, column(run, [](const multibody::CraneOutputs& o) { return o.hull.y(); }));
  const auto& hull = *scene.hull;
  const double mass = hull.mass + scene.boom.mesh.total_mass() + scene.cargo->mass;
  const double added = scene.radiation.heave_added_mass * mass;
  const double rho_g_area = scene.environment.water_density * scene.environment.gravity * hull.length * hull.width;
  const double expected = 2.0 * std::numbers::pi * std::sqrt((mass + added) / rho_g_area);
  std::printf("heave period %.5f s, hydrostatic theory %.5f s, ratio %.6f\n", period, expected, period / expected);
  EXPECT_NEAR(period / expected, 1.0, 0.01);
  EXPECT_NEAR(period / expected, 1.0, 1e-3) << "box sides are vertical: restoring is exactly linear";
}

TEST(CraneDynamics, CargoOnRigidBoomSwingsAsARigidBodyOnAString) {
  scene::Scene scene = test::reference_scene();
  scene.wave.reset();
  scene.wire->damping_ratio = 0.0;
  auto equations = test::build_with(scene, {scene::BoomKind::rigid, 1, 0, false},
                                    [](multibody::HullModel& hull, multibody::WireModel&) { hull.fixed = true; });
  const auto& cargo = *scene.cargo;
  const double g = scene.environment.gravity, m = cargo.mass, h = cargo.hook_y, inertia = cargo.pitch_inertia();
  const double length = scene.wire->unstretched_length + m * g / scene.wire->stiffness;  // string at rest
  // Lower root of det(K − ω² M) = 0 for M = [[ℓ², ℓh], [ℓh, h² + I/m]], K = g [[ℓ, 0], [0, h]].
  const double a = length * length * (h * h + inertia / m) - length * length * h * h;
  const double b = -g * (length * (h * h + inertia / m) + h * length * length);
  const double c = g * g * length * h;
  const double omega2 = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
  const double ratio = (g - omega2 * length) / (omega2 * h);  // ψ/φ of the lower mode
  // Start in that mode: φ = 0.01 rad; the tip A is where the guess hangs the hook from.
  Eigen::VectorXd z = equations->initial_guess();
  const Eigen::Vector2d tip = z.head<2>() + Eigen::Vector2d(0.0, h + length);
  const double phi = 0.01, psi = ratio * phi;
  const Eigen::Vector2d hook = tip + length * Eigen::Vector2d(std::sin(phi), -std::cos(phi));
  z.head<2>() = hook + h * Eigen::Vector2d(std::sin(psi), -std::cos(psi));
  z(2) = psi;
  multibody::RunSettings settings = tight(80.0);
  settings.output_interval = 0.01;
  const multibody::RunResult run = multibody::simulate(*equations, z, settings);
  const double period = test::mean_period(run.time, column(run, [](const multibody::CraneOutputs& o) { return o.cargo.x(); }));
  std::printf("pendulum period %.5f s, double-pendulum theory %.5f s\n", period, 2 * std::numbers::pi / std::sqrt(omega2));
  EXPECT_NEAR(period / (2 * std::numbers::pi / std::sqrt(omega2)), 1.0, 5e-3);
  EXPECT_NEAR(period / (2 * std::numbers::pi / std::sqrt(omega2)), 1.0, 1e-3) << "small amplitude: linear theory";
}

TEST(CraneDynamics, LagrangeMultipliersAndMinimalCoordinatesAgree) {
  const scene::Scene scene = test::reference_scene();
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 4, 0, false});
  const Eigen::VectorXd z0 = multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z;
  multibody::RunSettings settings = tight(40.0);
  settings.output_interval = 0.05;
  const multibody::RunResult minimal = multibody::simulate(*equations, z0, settings);
  settings.kind = solve::Integrator::ida;
  const multibody::RunResult lagrange = multibody::simulate(*equations, z0, settings);
  double heave = 0.0, residual = 0.0;
  for (std::size_t i = 0; i < minimal.samples.size(); ++i) {
    heave = std::max(heave, std::abs(minimal.samples[i].cargo.y() - lagrange.samples[i].cargo.y()));
    residual = std::max(residual, lagrange.samples[i].constraint_residual);
  }
  std::printf("IDA vs CVODE: max cargo heave difference %.3g m, max constraint residual %.3g m\n", heave, residual);
  EXPECT_LT(heave, 1e-5) << "cargo heave [m]";
  EXPECT_LT(residual, 1e-8) << "constraint residual [m]";
  // The joint reactions agree too (λ against M q̈ − Q).
  const auto& a = minimal.samples.back().joint_reaction;
  const auto& b = lagrange.samples.back().joint_reaction;
  EXPECT_LT((a - b).norm(), 1e-4 * b.norm());
}

TEST(CraneDynamics, VeryStiffBoomReproducesTheRigidBoom) {
  scene::Scene scene = test::reference_scene();
  scene.boom.mesh.section.youngs_modulus *= 1e6;
  auto stiff = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 2, 0, false});
  auto rigid = scene::build_crane_equations(scene, {scene::BoomKind::rigid, 1, 0, false});
  multibody::RunSettings settings = tight(30.0);  // ramp (20 s) plus one full wave period
  settings.relative_tolerance = settings.absolute_tolerance = 1e-8;
  const auto a = multibody::simulate(*stiff, multibody::solve_static_equilibrium(*stiff, stiff->initial_guess()).z, settings);
  const auto b = multibody::simulate(*rigid, multibody::solve_static_equilibrium(*rigid, rigid->initial_guess()).z, settings);
  using O = multibody::CraneOutputs;
  EXPECT_LT(test::relative_history_error(column(a, [](const O& o) { return o.hull.y(); }), column(b, [](const O& o) { return o.hull.y(); })), 1e-4);
  EXPECT_LT(test::relative_history_error(column(a, [](const O& o) { return o.hull.z(); }), column(b, [](const O& o) { return o.hull.z(); })), 1e-4);
  EXPECT_LT(test::relative_history_error(column(a, [](const O& o) { return o.cargo.y(); }), column(b, [](const O& o) { return o.cargo.y(); })), 1e-4);
  EXPECT_LT(test::relative_history_error(column(a, [](const O& o) { return o.cargo.z(); }), column(b, [](const O& o) { return o.cargo.z(); })), 1e-4);
}

}  // namespace crane_dynamics_test
