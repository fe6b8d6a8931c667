// Damping added to the hull ([hull_damping]: F = −b v − q |v| v per DOF at G1), on the crane whose
// hull is the WAMIT fixture's barge and whose boom and cargo weigh 41 kg (the hull alone to ~1e-5;
// tests/study/barge_hull_scene.hpp). Independent results:
//  * linear, surge (no radiation, a mooring spring k): a 1-DOF oscillator m ẍ + b ẋ + k x = 0, whose
//    logarithmic decrement between successive maxima is δ = 2πζ/√(1 − ζ²), ζ = b / (2√(k m));
//  * linear, heave on a [bem] hull (constant radiation at the tabulated period 8.100003 s): the 1-DOF
//    (m + A33) ÿ + (B33 + b) ẏ + ρ g L B y = 0 with A33, B33 read here from barge.1's line at that period
//    (the box's waterplane stiffness is exact for a wall-sided hull);
//  * quadratic, surge: the energy lost over one cycle of amplitude a is ∮ q |v|³ dt = (8/3) q ω² a³ for
//    x = a cos ωt (small decay per cycle: first-order averaging), against ½ k (a_n² − a_{n+1}²) of
//    successive maxima;
//  * the linearisation (`ffrf rao`, natural modes) keeps b and has no linear part of q about rest.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <string>
#include <vector>

#include "barge_hull_scene.hpp"
#include "multibody/linearisation.hpp"
#include "multibody/crane_run.hpp"
#include "scene/scene_loader.hpp"
#include "study/run_pipeline.hpp"

namespace hull_damping_test {

using namespace ffrf;
constexpr double kPi = std::numbers::pi;
constexpr double kTotalMass = 4.0e6;  // ρ · 80 · 10 · 5 m³ at ρ = 1000 kg/m³: floating at the BEM draft
constexpr double kSurgeStiffness = 1.6e6;  // [N/m]: a 9.9 s surge period

// The barge crane without [bem] (no radiation), its mooring k and `damping` as the [hull_damping] lines.
std::string surge_scene(const std::string& damping) {
  std::string text = test::barge_hull_scene(kTotalMass, 23.27, "");
  text.erase(text.find("[bem]"));
  const std::string mooring = "surge_stiffness = 1.0";
  text.replace(text.find(mooring), mooring.size(), fmt::format("surge_stiffness = {}", kSurgeStiffness));
  return text + "[hull_damping]\n" + damping + "\n";
}

// Hull coordinate `dof` released `offset` from its static equilibrium, CVODE rtol 1e-9; the samples
// relative to the equilibrium.
std::vector<double> free_decay(const std::string& text, int dof, double offset, double duration, std::vector<double>& time) {
  const scene::Scene scene = scene::load_scene_text(text, "hull_damping.toml");
  study::PreparedRun prepared = study::prepare_run(scene, {scene::BoomKind::rigid, 1});
  Eigen::VectorXd z0 = prepared.initial_state;
  z0(dof) += offset;
  multibody::RunSettings settings;
  settings.relative_tolerance = 1e-9;
  settings.absolute_tolerance = 1e-10;
  settings.duration = duration;
  settings.output_interval = 0.01;
  const multibody::RunResult result = multibody::simulate(*prepared.equations, z0, settings);
  time = result.time;
  std::vector<double> x;
  for (const auto& sample : result.samples) x.push_back(sample.hull(dof) - prepared.initial_state(dof));
  return x;
}

// The maxima of a sampled record (a parabola through each sampled maximum and its neighbours).
std::vector<double> maxima(const std::vector<double>& x) {
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    if (x[i] > x[i - 1] && x[i] >= x[i + 1] && x[i] > 0.0) {
      const double curvature = x[i - 1] - 2.0 * x[i] + x[i + 1];
      const double shift = 0.5 * (x[i - 1] - x[i + 1]) / curvature;
      peaks.push_back(x[i] - 0.25 * (x[i - 1] - x[i + 1]) * shift);
    }
  }
  return peaks;
}

double decrement(double zeta) { return 2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta); }

TEST(HullDamping, LinearSurgeDampingGivesTheOscillatorsLogarithmicDecrement) {
  const double mass = kTotalMass - 1.0;  // hull and clamped boom; the 1 kg cargo swings on its wire
  const double zeta = 0.05, b = 2.0 * zeta * std::sqrt(kSurgeStiffness * mass);
  std::vector<double> time;
  const auto x = free_decay(surge_scene(fmt::format("surge_linear = {}", b)), 0, 1.0, 60.0, time);
  const auto peaks = maxima(x);
  ASSERT_GE(peaks.size(), 5u);
  for (std::size_t n = 0; n + 1 < peaks.size(); ++n) {
    EXPECT_NEAR(std::log(peaks[n] / peaks[n + 1]), decrement(zeta), 1e-4 * decrement(zeta)) << "cycle " << n;
  }
}

TEST(HullDamping, LinearHeaveDampingAddsToTheBemRadiationDamping) {
  // barge.1, "  8.100003E+00     3     3  3.518381E+03  2.645009E+03": A33 = ρ Ā, B33 = ρ ω B̄ (ULEN = 1).
  const double rho = 1000.0, omega_c = 2.0 * kPi / 8.100003;
  const double a33 = rho * 3.518381E+03, b33 = rho * omega_c * 2.645009E+03;
  const double stiffness = rho * 9.81 * 80.0 * 10.0, inertia = kTotalMass - 1.0 + a33;
  const std::string data = std::string(FFRF_SOURCE_DIR "/tests/hydro/data/");
  const auto scene_with = [&](double b) {
    std::string text = test::barge_hull_scene(kTotalMass, 23.27, fmt::format(R"(radiation_file = "{}barge.1"
origin_above_keel = 5.0
radiation_model = "constant"
constant_period = 8.100003)", data));
    return text + fmt::format("[hull_damping]\nheave_linear = {}\n", b);
  };
  for (const double b : {0.0, 1.0e6}) {
    const double zeta = (b33 + b) / (2.0 * std::sqrt(stiffness * inertia));
    std::vector<double> time;
    const auto peaks = maxima(free_decay(scene_with(b), 1, 0.2, 20.0, time));
    ASSERT_GE(peaks.size(), 3u);
    for (std::size_t n = 0; n + 1 < 3; ++n) {
      EXPECT_NEAR(std::log(peaks[n] / peaks[n + 1]), decrement(zeta), 1e-3 * decrement(zeta)) << "b = " << b << " cycle " << n;
    }
  }
}

TEST(HullDamping, QuadraticSurgeDampingLosesTheAveragedEnergyPerCycle) {
  const double q = 3.0e4;  // [N s²/m²]: about 2 % of the amplitude lost per cycle at 1 m
  const double mass = kTotalMass - 1.0, omega = std::sqrt(kSurgeStiffness / mass);
  std::vector<double> time;
  const auto peaks = maxima(free_decay(surge_scene(fmt::format("surge_quadratic = {}", q)), 0, 1.0, 60.0, time));
  ASSERT_GE(peaks.size(), 5u);
  for (std::size_t n = 0; n + 1 < peaks.size(); ++n) {
    const double lost = 0.5 * kSurgeStiffness * (peaks[n] * peaks[n] - peaks[n + 1] * peaks[n + 1]);
    const double mean = 0.5 * (peaks[n] + peaks[n + 1]);
    const double averaged = 8.0 / 3.0 * q * omega * omega * mean * mean * mean;
    EXPECT_NEAR(lost / averaged, 1.0, 2e-3) << "cycle " << n;
  }
}

TEST(HullDamping, TheLinearisationKeepsTheLinearPartOnly) {
  const double b = 2.5e5, q = 3.0e4;
  const auto surge_damping = [](const std::string& text) {
    const scene::Scene scene = scene::load_scene_text(text, "hull_damping.toml");
    study::PreparedRun prepared = study::prepare_run(scene, {scene::BoomKind::rigid, 1});
    return multibody::linearise_crane(*prepared.equations, prepared.statics.z).damping(0, 0);
  };
  const double none = surge_damping(surge_scene(""));
  EXPECT_NEAR(surge_damping(surge_scene(fmt::format("surge_linear = {}", b))) - none, b, 1e-6 * b);
  // q |v| v has no derivative at rest (what remains is the forward difference's q·δv, δv = 1e-7 m/s).
  EXPECT_LT(std::abs(surge_damping(surge_scene(fmt::format("surge_quadratic = {}", q))) - none), 1e-6 * q);
}

}  // namespace hull_damping_test
