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
#include <unistd.h>
#include <vector>

#include <Eigen/Eigenvalues>

#include "barge_hull_scene.hpp"
#include "linalg/dense_solvers.hpp"
#include "multibody/crane_run.hpp"
#include "scene/scene_loader.hpp"
#include "study/run_pipeline.hpp"
#include "../barge_excitation_lines.hpp"
#include "../scene_text.hpp"

namespace bem_crane_test {

using namespace ffrf;
constexpr double kPi = std::numbers::pi;

using ffrf::test_text::read_text;
using ffrf::test_text::replaced;

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
  solve::SecondOrderJacobian blocks(prepared.equations->minimal_structure());
  prepared.equations->minimal_jacobian(t, z, zero, z_ddot, blocks);
  HullState s;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) s.mass(i, j) = blocks.mass.at(i, j);
  }
  s.acceleration = z_ddot.head<3>();
  return s;
}

// The excitation of barge.3 at the wave's period, read from the file's lines (../barge_excitation_lines.hpp).
Eigen::Vector3cd file_excitation(double rho, double g) { return test_text::barge_file_excitation(8.100003, rho, g); }

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

// --- constant against Cummins for a nearly flat B(ω) ---

struct Lorentzian {
  double a, b = 1.0e6, infinite_added_mass = 4.0e6;  // [1/s], [N s/m], [kg]
  double damping(double w) const { return b * a * a / (a * a + w * w); }
  double added_mass(double w) const { return infinite_added_mass - a * b / (a * a + w * w); }
};

constexpr double kMass = 4.0e6, kHeaveStiffness = 1000.0 * 9.81 * 80.0 * 10.0, kStart = 0.1;

// Writes a WAMIT .1 of the Lorentzian heave (surge and pitch: constant added mass, no damping),
// ρ = 1000, ULEN = 1: Ā = A/ρ, B̄ = B/(ρω).
std::string write_radiation_file(const Lorentzian& p) {
  const auto path = std::filesystem::temp_directory_path() / fmt::format("ffrf_lorentzian_{}_{}.1", p.a, ::getpid());
  std::ofstream out(path);
  out << "synthetic Lorentzian heave damping\n";
  const auto rows = [&](double period, double w, bool with_damping) {
    const double heave = period == -1.0 ? p.added_mass(0.0) : period == 0.0 ? p.infinite_added_mass : p.added_mass(w);
    out << fmt::format("{:.9E} 1 1 {:.9E}{}\n", period, 100.0, with_damping ? " 0.0" : "");
    out << fmt::format("{:.9E} 3 3 {:.9E}{}\n", period, heave / 1000.0,
                       with_damping ? fmt::format(" {:.9E}", p.damping(w) / (1000.0 * w)) : "");
    out << fmt::format("{:.9E} 5 5 {:.9E}{}\n", period, 1.0e6, with_damping ? " 0.0" : "");
  };
  rows(-1.0, 0.0, false);
  rows(0.0, 0.0, false);
  for (int k = 2000; k >= 1; --k) rows(2 * kPi / (0.02 * k), 0.02 * k, true);  // ω = 40 … 0.02 rad/s, periods increasing
  return path.string();
}

// Heave of the crane's hull released 0.1 m above its equilibrium (CVODE, rtol 1e-8).
std::vector<double> crane_heave(const std::string& radiation_file, const std::string& model, std::vector<double>& time) {
  const std::string text = test::barge_hull_scene(kMass, 23.27, fmt::format(R"(radiation_file = "{}"
origin_above_keel = 5.0
radiation_model = "{}"
kernel_time_step = 0.01
truncation_time = 3.0)",
                                                                               radiation_file, model));
  const scene::Scene scene = scene::load_scene_text(text, "lorentzian.toml");
  study::PreparedRun prepared = study::prepare_run(scene, {scene::BoomKind::rigid, 1});
  Eigen::VectorXd z0 = prepared.initial_state;
  z0(1) += kStart;
  multibody::RunSettings settings;
  settings.relative_tolerance = 1e-8;
  settings.absolute_tolerance = 1e-9;
  settings.duration = 30.0;
  settings.output_interval = 0.05;
  const auto result = multibody::simulate(*prepared.equations, z0, settings);
  time = result.time;
  std::vector<double> heave;
  for (const auto& sample : result.samples) heave.push_back(sample.hull(1) - prepared.initial_state(1));
  return heave;
}

// Exact heave of (M + A∞)ẍ + μ + Cx = 0, μ̇ = −aμ + abẋ from (x0, 0, 0): eigen-decomposition.
double cummins_exact(const Lorentzian& p, double t) {
  Eigen::MatrixXd system(3, 3);  // dynamic size: the project's compiled-once eigen solver
  const double inertia = kMass + p.infinite_added_mass;
  system << 0, 1, 0, -kHeaveStiffness / inertia, 0, -1.0 / inertia, 0, p.a * p.b, -p.a;
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(system);
  const Eigen::MatrixXcd v = eigen.eigenvectors();
  Eigen::VectorXcd start = Eigen::VectorXcd::Zero(3);
  start(0) = kStart;
  const Eigen::VectorXcd c = v.fullPivLu().solve(start);
  std::complex<double> x = 0;
  for (int i = 0; i < 3; ++i) x += v(0, i) * c(i) * std::exp(eigen.eigenvalues()(i) * t);
  return x.real();
}

// The damped oscillator with A(ω), B(ω) at ω_c = √(C/(M + A(ω_c))) (the scene's default without a wave).
double constant_exact(const Lorentzian& p, double t) {
  double w = 1.0;
  for (int i = 0; i < 100; ++i) w = std::sqrt(kHeaveStiffness / (kMass + p.added_mass(w)));
  const double inertia = kMass + p.added_mass(w), sigma = p.damping(w) / (2 * inertia);
  const double wd = std::sqrt(kHeaveStiffness / inertia - sigma * sigma);
  return kStart * std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t));
}

double largest_gap(const std::vector<double>& time, const std::vector<double>& x, double (*exact)(const Lorentzian&, double),
                   const Lorentzian& p) {
  double gap = 0.0;
  for (std::size_t i = 0; i < time.size(); ++i) gap = std::max(gap, std::abs(x[i] - exact(p, time[i])));
  return gap;
}

TEST(BemCrane, ConstantAndCumminsRadiationAgreeWhereTheDampingIsFlat) {
  const Lorentzian p{6.0};
  const std::string file = write_radiation_file(p);
  std::vector<double> time;
  const auto convolution = crane_heave(file, "convolution", time);
  const auto state_space = crane_heave(file, "state-space", time);
  const auto constant = crane_heave(file, "constant", time);
  std::filesystem::remove(file);
  // Each crane run against its own closed form (the kernel's sampling and the history's linear
  // interpolation: well below 1 % of the release height).
  EXPECT_LT(largest_gap(time, convolution, cummins_exact, p), 0.005 * kStart);
  EXPECT_LT(largest_gap(time, state_space, cummins_exact, p), 0.005 * kStart);
  EXPECT_LT(largest_gap(time, constant, constant_exact, p), 0.002 * kStart);
  // The two closed forms approach each other as B flattens (a ≫ ω): the constant model's error is
  // B's and A's variation over the decay's complex frequency, O((ω/a)²) — a 4 × wider band, 16 × less.
  const auto model_gap = [](const Lorentzian& q) {
    double gap = 0.0;
    for (double t = 0.0; t <= 30.0; t += 0.01) gap = std::max(gap, std::abs(cummins_exact(q, t) - constant_exact(q, t)));
    return gap;
  };
  const double narrow = model_gap(p), wide = model_gap(Lorentzian{24.0});
  ::testing::Test::RecordProperty("model_gap", fmt::format("a = 6: {:.3g} m, a = 24: {:.3g} m (x0 = 0.1 m)", narrow, wide));
  EXPECT_GT(narrow / wide, 10.0);
  EXPECT_LT(narrow, 0.05 * kStart);
  // ... and the crane's constant and Cummins runs differ by that much, not more.
  EXPECT_LT(largest_gap(time, convolution, constant_exact, p), narrow + 0.005 * kStart);
}

}  // namespace bem_crane_test
