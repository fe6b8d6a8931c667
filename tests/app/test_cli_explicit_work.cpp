// Adaptive explicit Runge–Kutta on the reference crane's stiff 16-element boom stops before its
// first step as too much work, naming the explicit step limit, the steps it needs and cvode; the
// steps it names against an estimate made here from what the run does not use: the boom's highest
// clamped–free eigenfrequency (its finite-element K and M, a dense generalized eigensolve), the
// stiffness-proportional damping of the scene (β = 2ζ/ω1, ω1 from Euler–Bernoulli theory) that puts
// that mode's fast root λ = −(βω² + √(β²ω⁴ − 4ω²))/2 on the negative real axis, and the interval of
// absolute stability of the method's Butcher table (ARKODE's Zonneveld 4(3)) along that axis.
#include <cstdio>  // FILE, which arkode_butcher.h uses without including it

#include <arkode/arkode_butcher_erk.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <regex>
#include <string>

#include "linalg/dense_solvers.hpp"
#include "cli_harness.hpp"
#include "fem/beam_model.hpp"
#include "scene/scene_loader.hpp"

namespace {

using namespace ffrf::test;

// |R(z)| of the explicit table for real z: stages k_i = z (1 + Σ_j<i a_ij k_j), R = 1 + Σ b_i k_i.
double amplification(ARKodeButcherTable table, double z) {
  std::vector<double> k(static_cast<std::size_t>(table->stages));
  double r = 1.0;
  for (int i = 0; i < table->stages; ++i) {
    double stage = 1.0;
    for (int j = 0; j < i; ++j) stage += table->A[i][j] * k[static_cast<std::size_t>(j)];
    k[static_cast<std::size_t>(i)] = z * stage;
    r += table->b[i] * k[static_cast<std::size_t>(i)];
  }
  return std::abs(r);
}

// The length of the method's stability interval on the negative real axis.
double real_axis_interval() {
  ARKodeButcherTable table = ARKodeButcherTable_LoadERK(ARKODE_ZONNEVELD_5_3_4);
  double stable = 0.0, unstable = 0.0;
  for (double z = -0.01; z > -20.0; z -= 0.01) {
    if (amplification(table, z) > 1.0) {
      unstable = z;
      break;
    }
    stable = z;
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (stable + unstable);
    (amplification(table, mid) > 1.0 ? unstable : stable) = mid;
  }
  ARKodeButcherTable_Free(table);
  return -stable;
}

TEST(CliExplicitWork, AdaptiveExplicitRkOnAStiffBoomStopsBeforeItsFirstStep) {
  TempDir dir;
  const std::string scene_path = source_file("cases/paper_floating_crane.toml");
  const RunResult r = run_ffrf("run " + scene_path + " --integrator arkode --step 0 --duration 5", dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;  // a solver failure (docs/user-guide.md)
  EXPECT_NE(r.err.find("(too much work)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the explicit step limit ~"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("use cvode"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at t = 0.000000 s"), std::string::npos) << "no step taken: " << r.err;
  std::smatch found;
  ASSERT_TRUE(std::regex_search(r.err, found, std::regex("needs ~([0-9.e+]+) steps"))) << r.err;
  const double steps = std::stod(found[1]);

  // The independent estimate.
  const ffrf::scene::Scene scene = ffrf::scene::load_scene(scene_path);
  const ffrf::fem::BeamModel beam = ffrf::fem::make_beam_model(scene.boom.mesh, ffrf::fem::Boundary::clamped_free);
  const Eigen::MatrixXd stiffness(beam.stiffness), mass(beam.mass);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(stiffness, mass, Eigen::EigenvaluesOnly);
  const double omega_max = std::sqrt(modes.eigenvalues().maxCoeff());
  const auto& section = scene.boom.mesh.section;
  const double length = scene.boom.mesh.length;
  const double omega_1 = std::pow(1.8751040687, 2) * std::sqrt(section.bending_rigidity() / (section.mass_per_length * std::pow(length, 4)));
  const double beta = 2.0 * scene.boom.damping_ratio / omega_1;
  ASSERT_GT(beta * omega_max, 2.0) << "the highest mode is overdamped: its fast root is real";
  const double fast = 0.5 * (beta * omega_max * omega_max +
                             std::sqrt(std::pow(beta * omega_max * omega_max, 2) - 4.0 * omega_max * omega_max));
  const double step_limit = real_axis_interval() / fast;
  const double estimate = 5.0 / step_limit;
  std::printf("ω_max %.4g rad/s, fast root %.4g 1/s, real-axis interval %.4f: limit %.3g s, %.3g steps; ffrf: %.3g\n",
              omega_max, fast, real_axis_interval(), step_limit, estimate, steps);
  EXPECT_GT(steps, 0.5 * estimate) << "estimate " << estimate << " steps (limit " << step_limit << " s)";
  EXPECT_LT(steps, 2.0 * estimate) << "estimate " << estimate << " steps (limit " << step_limit << " s)";
}

}  // namespace
