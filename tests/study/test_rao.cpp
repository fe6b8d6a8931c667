// The frequency domain (study/rao.hpp, multibody/linearisation.hpp) against independent results:
// (a) the complex LU response and the natural modes of 1- and 2-DOF oscillators against their
// closed forms (Cramer's rule, the characteristic polynomial); (b) the hull's heave natural
// frequency of a crane whose heave decouples against √(C33 / (m + A33)) and its damping ratio against
// the scene's 5 % of critical; (d) the linearised mass matrix against the kinetic energy's
// polarization and the stiffness against central differences of the static residual (a path
// through the equations other than the Newton blocks).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "multibody/crane_equations.hpp"
#include "multibody/linearisation.hpp"
#include "study/rao.hpp"
#include "study/run_pipeline.hpp"
#include "study_test_support.hpp"

namespace ffrf {
namespace {

using cd = std::complex<double>;

TEST(FrequencyResponse, OneDegreeOfFreedomMatchesTheClosedForm) {
  const double m = 3.0, c = 0.7, k = 50.0;
  const Eigen::MatrixXd mass = Eigen::MatrixXd::Constant(1, 1, m), damping = Eigen::MatrixXd::Constant(1, 1, c),
                        stiffness = Eigen::MatrixXd::Constant(1, 1, k);
  Eigen::VectorXcd force(1);
  force(0) = cd(2.0, -1.0);
  for (const double omega : {0.5, 4.0, std::sqrt(k / m), 9.0}) {
    const cd expected = force(0) / (k - m * omega * omega + cd(0.0, c * omega));
    const cd x = study::frequency_response(mass, damping, stiffness, force, omega)(0);
    EXPECT_NEAR(std::abs(x - expected), 0.0, 1e-12 * std::abs(expected)) << omega;
  }
  multibody::LinearisedCrane linear;
  linear.equilibrium = Eigen::VectorXd::Zero(1);
  linear.mass = mass;
  linear.damping = damping;
  linear.stiffness = stiffness;
  const auto modes = study::natural_modes(linear);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_NEAR(modes[0].angular_frequency, std::sqrt(k / m), 1e-12);
  EXPECT_NEAR(modes[0].damping_ratio, c / (2.0 * std::sqrt(k * m)), 1e-12);
}

TEST(FrequencyResponse, TwoDegreesOfFreedomMatchCramersRuleAndTheCharacteristicPolynomial) {
  // Two masses in a chain: ground –k1– m1 –k2– m2, dashpots c1, c2 beside the springs.
  const double m1 = 2.0, m2 = 0.5, k1 = 100.0, k2 = 30.0, c1 = 0.4, c2 = 0.1;
  Eigen::MatrixXd mass(2, 2), damping(2, 2), stiffness(2, 2);
  mass << m1, 0.0, 0.0, m2;
  damping << c1 + c2, -c2, -c2, c2;
  stiffness << k1 + k2, -k2, -k2, k2;
  Eigen::VectorXcd force(2);
  force << cd(1.0, 0.0), cd(0.0, 0.5);
  for (const double omega : {1.0, 5.0, 7.7, 12.0}) {
    const cd d11 = k1 + k2 - m1 * omega * omega + cd(0.0, (c1 + c2) * omega);
    const cd d22 = k2 - m2 * omega * omega + cd(0.0, c2 * omega);
    const cd d12 = -k2 + cd(0.0, -c2 * omega);
    const cd det = d11 * d22 - d12 * d12;
    const cd x1 = (d22 * force(0) - d12 * force(1)) / det, x2 = (d11 * force(1) - d12 * force(0)) / det;
    const Eigen::VectorXcd x = study::frequency_response(mass, damping, stiffness, force, omega);
    EXPECT_NEAR(std::abs(x(0) - x1), 0.0, 1e-12 * std::abs(x1)) << omega;
    EXPECT_NEAR(std::abs(x(1) - x2), 0.0, 1e-12 * std::abs(x2)) << omega;
  }
  // Undamped: m1 m2 ω⁴ − (m1 k2 + m2 (k1 + k2)) ω² + k1 k2 = 0.
  multibody::LinearisedCrane linear;
  linear.equilibrium = Eigen::VectorXd::Zero(2);
  linear.mass = mass;
  linear.damping = Eigen::MatrixXd::Zero(2, 2);
  linear.stiffness = stiffness;
  const double b = m1 * k2 + m2 * (k1 + k2), disc = std::sqrt(b * b - 4.0 * m1 * m2 * k1 * k2);
  const auto modes = study::natural_modes(linear);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_NEAR(modes[0].angular_frequency, std::sqrt((b - disc) / (2.0 * m1 * m2)), 1e-10);
  EXPECT_NEAR(modes[1].angular_frequency, std::sqrt((b + disc) / (2.0 * m1 * m2)), 1e-10);
  EXPECT_NEAR(modes[0].damping_ratio, 0.0, 1e-12);
}

// The reference crane with its rigid boom upright over G1 (cargo hanging under the tip) and the
// hull's centre of flotation under G1, undamped in heave: heave decouples from surge and pitch (no
// first moment of the waterplane or of the masses about G1) and leaves two degrees of freedom, the
// hull with its boom and added mass on the waterplane spring C33 = ρ g L B, the cargo on the wire.
TEST(FrequencyResponse, HullHeaveNaturalFrequencyFollowsFromWaterplaneAndMasses) {
  scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  scene.wave.reset();
  scene.hull->g1_aft_of_mid_length = 0.0;
  scene.boom.mount->angle = std::numbers::pi / 2.0;
  scene.boom.mount->root_x = 0.0;
  scene.radiation.heave_damping = 0.0;
  scene.wire->damping_ratio = 0.0;
  study::PreparedRun prepared = study::prepare_run(scene, {scene::BoomKind::rigid, 1});
  const multibody::LinearisedCrane linear = multibody::linearise_crane(*prepared.equations, prepared.statics.z);
  const double rho = scene.environment.water_density, g = scene.environment.gravity;
  const double restoring = rho * g * scene.hull->length * scene.hull->width;  // C33 of the box's waterplane
  const double cargo = scene.cargo->mass, wire = scene.wire->stiffness;
  const double crane = scene.hull->mass + scene.boom.mesh.total_mass();
  const double added_mass = scene.radiation.heave_added_mass * (crane + cargo);  // A33 = 1.5 × displaced mass
  const double hull_mass = crane + added_mass;
  // m1 m2 ω⁴ − (m1 k2 + m2 (k1 + k2)) ω² + k1 k2 = 0, the lower root.
  const double b = hull_mass * wire + cargo * (restoring + wire);
  const double expected = std::sqrt((b - std::sqrt(b * b - 4.0 * hull_mass * cargo * restoring * wire)) / (2.0 * hull_mass * cargo));
  const study::NaturalMode* heave = nullptr;
  const auto modes = study::natural_modes(linear);
  for (const auto& mode : modes) {
    if (mode.dominant == "hull heave" && heave == nullptr) heave = &mode;
  }
  ASSERT_NE(heave, nullptr);
  EXPECT_NEAR(heave->angular_frequency / expected, 1.0, 1e-6);
  EXPECT_NEAR(heave->damping_ratio, 0.0, 1e-9);
  // The stiff wire makes it the one-body heave frequency √(C33 / (m + A33)) within 0.5 %.
  EXPECT_NEAR(heave->angular_frequency / std::sqrt(restoring / (hull_mass + cargo)), 1.0, 5e-3);
}

// M against the kinetic energy T = ½ żᵀ M ż (the outputs' own sum, added mass included) by
// polarization, K against central differences of the static residual Q_z at rest in calm water.
TEST(FrequencyResponse, LinearisedMassAndStiffnessMatchEnergyAndResidualDifferences) {
  scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  scene.wave.reset();
  study::PreparedRun prepared = study::prepare_run(scene, {scene::BoomKind::modal, 16, 2, true});
  multibody::CraneEquations& equations = *prepared.equations;
  const Eigen::VectorXd z0 = prepared.statics.z;
  const multibody::LinearisedCrane linear = multibody::linearise_crane(equations, z0);
  const int n = linear.size();
  const auto energy = [&](const Eigen::VectorXd& velocity) { return equations.minimal_outputs(0.0, z0, velocity).kinetic_energy; };
  Eigen::MatrixXd mass(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd ei = Eigen::VectorXd::Zero(n), ej = Eigen::VectorXd::Zero(n);
      ei(i) = 1e-3;
      ej(j) = 1e-3;
      mass(i, j) = (energy(ei + ej) - energy(ei) - energy(ej)) / 1e-6;
    }
  }
  EXPECT_LT((mass - linear.mass).norm(), 1e-6 * linear.mass.norm());
  const Eigen::VectorXd scale = equations.coordinate_scale();
  Eigen::MatrixXd stiffness(n, n);
  Eigen::VectorXd plus(n), minus(n), z = z0;
  for (int j = 0; j < n; ++j) {
    const double h = 1e-5 * scale(j);
    z(j) = z0(j) + h;
    equations.static_residual(z, plus);
    z(j) = z0(j) - h;
    equations.static_residual(z, minus);
    z(j) = z0(j);
    stiffness.col(j) = -(plus - minus) / (2.0 * h);
  }
  for (int j = 0; j < n; ++j) {
    EXPECT_LT((stiffness.col(j) - linear.stiffness.col(j)).norm(), 1e-5 * linear.stiffness.col(j).norm() + 1e-6) << j;
  }
}

// The provider of frequency-dependent hull terms: 0.3 × displaced mass more heave added mass from
// the provider gives the RAOs of the scene whose heave_added_mass is 0.3 higher (the same M), and a
// given hull excitation E gives (G + iωH)(−ω²M + iωC + K)⁻¹[E; 0] of the linearisation itself.
TEST(FrequencyResponse, HullHydrodynamicsProviderAddsToTheModelAndReplacesTheExcitation) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const double displaced = scene.hull->mass + scene.boom.mesh.total_mass() + scene.cargo->mass;
  study::RaoRequest request;
  request.models = {{scene::BoomKind::rigid, 1}};
  request.angular_frequencies = {0.45, 0.63, 0.9};
  request.hydrodynamics = [&](double) {
    study::HullFrequencyTerms terms;
    terms.added_mass(1, 1) = 0.3 * displaced;
    return terms;
  };
  const study::RaoResult provided = study::response_amplitude_operators(scene, request);
  scene::Scene heavier = scene;
  heavier.radiation.heave_added_mass += 0.3;
  // B33 = ζ · 2√((m + A33) C33) is a fraction of critical: keep it the same.
  heavier.radiation.heave_damping *= std::sqrt((1.0 + scene.radiation.heave_added_mass) / (1.0 + heavier.radiation.heave_added_mass));
  request.hydrodynamics = {};
  const study::RaoResult rebuilt = study::response_amplitude_operators(heavier, request);
  for (const auto output : {multibody::LinearOutput::hull_heave, multibody::LinearOutput::hull_pitch, multibody::LinearOutput::cargo_heave}) {
    for (std::size_t f = 0; f < 3; ++f) {
      const cd a = provided.models[0].response[static_cast<std::size_t>(output)][f];
      const cd b = rebuilt.models[0].response[static_cast<std::size_t>(output)][f];
      EXPECT_NEAR(std::abs(a - b), 0.0, 1e-6 * std::abs(b)) << multibody::to_string(output) << " " << f;
    }
  }
  // A given excitation replaces the derived one.
  const Eigen::Vector3cd given(cd(1e6, 2e5), cd(-3e7, 1e6), cd(4e8, -5e7));
  request.hydrodynamics = [&](double) {
    study::HullFrequencyTerms terms;
    terms.excitation = given;
    return terms;
  };
  const study::RaoResult replaced = study::response_amplitude_operators(scene, request);
  scene::Scene calm = scene;
  calm.wave.reset();
  study::PreparedRun prepared = study::prepare_run(calm, {scene::BoomKind::rigid, 1});
  const multibody::LinearisedCrane linear = multibody::linearise_crane(*prepared.equations, prepared.statics.z);
  const multibody::OutputMap map = multibody::linear_outputs(*prepared.equations, linear);
  Eigen::VectorXcd force = Eigen::VectorXcd::Zero(linear.size());
  force.head<3>() = given;
  for (std::size_t f = 0; f < 3; ++f) {
    const double omega = request.angular_frequencies[f];
    const Eigen::VectorXcd x = study::frequency_response(linear.mass, linear.damping, linear.stiffness, force, omega);
    const Eigen::VectorXcd y = map.position.cast<cd>() * x + cd(0.0, omega) * (map.velocity.cast<cd>() * x);
    for (int k = 0; k < multibody::linear_output_count; ++k) {
      EXPECT_NEAR(std::abs(replaced.models[0].response[static_cast<std::size_t>(k)][f] - y(k)), 0.0, 1e-9 * std::abs(y(k)) + 1e-12);
    }
  }
}

}  // namespace
}  // namespace ffrf
