// The crane's hull with BEM coefficients (scene [bem]; docs/hydrodynamics.md §6):
//  * No double Froude–Krylov: on the hull held at its calm-water equilibrium (zero velocity, so no
//    radiation), the wave's generalized force — M_hh (z̈_wave − z̈_calm), M_hh the hull rows of the
//    crane's mass matrix — equals the BEM excitation computed here from the .3 file's own numbers
//    (ρ g Re/Im, the pitch sign flipped, moved from the BEM origin to G1), not that plus the
//    Froude–Krylov pressure force the froude-krylov scene shows.
//  * Constant against Cummins where B(ω) is nearly flat (closed forms): a Lorentzian heave damping
//    B = b a²/(a² + ω²) (K = a b e^{−at}) written as a WAMIT .1 file; the crane's free heave decay
//    with the convolution model against the exact solution of (M + A∞)ẍ + μ + Cx = 0,
//    μ̇ = −aμ + abẋ (eigen-decomposition of the 3 × 3 system), and with the constant model against
//    the damped oscillator (M + A(ω_c))ẍ + B(ω_c)ẋ + Cx = 0; as a ≫ ω the two coincide (flat B).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "coupling/simulation.hpp"
#include "scene/scene_loader.hpp"
#include "study/run_pipeline.hpp"

namespace {

using namespace ffrf;
constexpr double kPi = std::numbers::pi;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// cases/bem_barge_crane.toml with the fixture's paths made absolute and a 8.100003 s wave (a tabulated period of barge.3).
std::string barge_scene_text() {
  const std::string source = FFRF_SOURCE_DIR;
  std::string text = read_text(source + "/cases/bem_barge_crane.toml");
  for (const char* ext : {"1", "3", "hst"}) {
    text = replaced(text, fmt::format("\"../tests/hydro/data/barge.{}\"", ext), fmt::format("\"{}/tests/hydro/data/barge.{}\"", source, ext));
  }
  return replaced(text, "period = 8.0 ", "period = 8.100003 ");
}

// Hull rows of M_z and of z̈ at the calm-water equilibrium at rest, at time t.
struct HullState {
  Eigen::Matrix3d mass;
  Eigen::Vector3d acceleration;
};

HullState hull_state(const std::string& text, double t) {
  const scene::Scene scene = scene::load_scene_text(text, "bem_barge_crane.toml");
  study::PreparedRun prepared = study::prepare_run(scene, {scene::BoomKind::rigid, 1});
  const Eigen::VectorXd& z = prepared.initial_state;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(z.size());
  Eigen::VectorXd z_ddot(z.size());
  prepared.equations->minimal_accelerations(t, z, zero, z_ddot);
  coupling::SecondOrderJacobian blocks(prepared.equations->minimal_structure());
  prepared.equations->minimal_jacobian(t, z, zero, z_ddot, blocks);
  HullState s;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) s.mass(i, j) = blocks.mass.at(i, j);
  }
  s.acceleration = z_ddot.head<3>();
  return s;
}

// The excitation of barge.3 at PER = 8.100003 s, heading 0, read from the file's lines: X_i = ρ g (Re + i Im)
// (ULEN = 1: L^(2+k) = 1), pitch sign flipped (WAMIT's mode 5 is bow-down).
Eigen::Vector3cd file_excitation(double rho, double g) {
  std::ifstream in(std::string(FFRF_SOURCE_DIR) + "/tests/hydro/data/barge.3");
  std::string line;
  Eigen::Vector3cd x = Eigen::Vector3cd::Zero();
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    double period = 0, heading = 0, modulus = 0, phase = 0, re = 0, im = 0;
    int mode = 0;
    if (!(fields >> period >> heading >> mode >> modulus >> phase >> re >> im)) continue;
    if (std::abs(period - 8.100003) > 1e-9 || heading != 0.0) continue;
    const int index = mode == 1 ? 0 : mode == 3 ? 1 : 2;
    x(index) = rho * g * std::complex<double>(re, im) * (mode == 5 ? -1.0 : 1.0);
  }
  return x;
}

TEST(BemCrane, TheWaveForceOnTheHullIsTheBemExcitationAndNotPlusFroudeKrylov) {
  const std::string bem = barge_scene_text();
  const std::string froude_krylov = replaced(bem, "excitation = \"bem\"", "excitation = \"froude-krylov\"");
  std::string calm = bem;
  calm.erase(calm.find("[wave]"), calm.find("[bem]") - calm.find("[wave]"));
  // The incident wave at the BEM origin (amidships on the waterline, 3 m forward of G1 at x = 0):
  // ζ = a cos(k x_O − ωt) = Re{a e^{i(ωt − k x_O)}} (following sea, zero phase).
  const double rho = 1025.0, g = 9.81, omega = 2 * kPi / 8.100003, k = omega * omega / g, a = 0.5, x_origin = 3.0;
  const Eigen::Vector3cd x = file_excitation(rho, g);
  ASSERT_GT(std::abs(x(1)), 1e5);
  for (const double t : {20.0, 21.3, 23.9}) {
    const HullState still = hull_state(calm, t), with_bem = hull_state(bem, t), with_fk = hull_state(froude_krylov, t);
    const Eigen::Vector3d bem_force = with_bem.mass * (with_bem.acceleration - still.acceleration);
    const Eigen::Vector3d fk_force = with_fk.mass * (with_fk.acceleration - still.acceleration);
    const Eigen::Vector3cd phasor = a * x * std::exp(std::complex<double>(0.0, omega * t - k * x_origin));
    Eigen::Vector3d expected = phasor.real();
    expected(2) += x_origin * expected(1);  // moment about G1 = moment about O + o_x F_y (o = (3, 0))
    // Forces and moments/length weighed alike. M_hh is taken from the Newton blocks, which match the
    // mass of the right-hand side to about 1e-7 relative (measured: 17 N of surge per 2.7e7 N m), hence 1e-4.
    const Eigen::Vector3d weight(1.0, 1.0, 1.0 / 80.0);
    const double scale = expected.cwiseProduct(weight).norm();
    EXPECT_LT((bem_force - expected).cwiseProduct(weight).norm(), 1e-4 * scale)
        << "t = " << t << " got " << bem_force.transpose() << " expected " << expected.transpose();
    // Froude–Krylov alone is a large part of it: counted twice, the error would be that large.
    EXPECT_GT(fk_force.cwiseProduct(weight).norm(), 0.2 * scale) << "t = " << t;
  }
}

}  // namespace
