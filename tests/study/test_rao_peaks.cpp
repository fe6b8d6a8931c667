// The resonance peaks of the RAOs (study/rao_peaks.hpp) and the sea's significant responses
// (study/rao_spectrum.hpp) against independent results: a one-degree-of-freedom oscillator's
// closed-form peaks (displacement F/(2kζ√(1 − ζ²)) at ω_n√(1 − 2ζ²), velocity F/c at ω_n); the
// reference crane's rigid cargo-surge peak against a brute-force grid of 2001 frequencies across its
// resonance; the significant response against Simpson's rule of |Y|²S on a fine uniform grid; the
// boom's element count of `rao` against the scene's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "study/rao.hpp"
#include "study/rao_peaks.hpp"
#include "study/rao_spectrum.hpp"
#include "study_test_support.hpp"

namespace ffrf {
namespace {

using cd = std::complex<double>;

// `ffrf rao`'s default grid: 109 periods evenly spaced over 3–30 s, as angular frequencies.
std::vector<double> default_grid() {
  std::vector<double> omegas;
  for (int i = 108; i >= 0; --i) omegas.push_back(2.0 * std::numbers::pi / (3.0 + 27.0 * i / 108.0));
  return omegas;
}

double largest(const std::vector<cd>& values) {
  double best = 0.0;
  for (const cd& v : values) best = std::max(best, std::abs(v));
  return best;
}

// m ẍ + c ẋ + k x = F e^{iωt} with ω_n at 12.9 s: displacement and velocity.
TEST(RaoPeaks, OneDegreeOfFreedomPeaksMatchTheClosedForm) {
  for (const double zeta : {0.05, 0.015, 1e-3, 3e-5}) {
    const double m = 2.0e6, omega_n = 2.0 * std::numbers::pi / 12.9, k = m * omega_n * omega_n, c = 2.0 * zeta * m * omega_n;
    const double force = 3.0e5;
    int calls = 0;
    const study::OutputResponse response_at = [&](double omega) {
      ++calls;
      Eigen::VectorXcd y(2);
      y(0) = force / (k - m * omega * omega + cd(0.0, c * omega));
      y(1) = cd(0.0, omega) * y(0);
      return y;
    };
    const std::vector<double> grid = default_grid();
    std::vector<Eigen::VectorXcd> responses;
    for (const double omega : grid) responses.push_back(response_at(omega));
    calls = 0;
    const std::vector<study::NaturalMode> modes{{omega_n, zeta, "x", ""}};
    const study::RefinedResponse refined = study::refine_resonance_peaks(grid, responses, modes, response_at, {true, true});
    ASSERT_EQ(refined.peaks.size(), 2u) << zeta;
    EXPECT_EQ(refined.added, static_cast<std::size_t>(calls));
    EXPECT_EQ(refined.angular_frequencies.size(), grid.size() + refined.added);
    EXPECT_TRUE(std::is_sorted(refined.angular_frequencies.begin(), refined.angular_frequencies.end()));
    const double displacement_peak = force / (k * 2.0 * zeta * std::sqrt(1.0 - zeta * zeta));
    const double velocity_peak = force / c;
    double coarse = 0.0;
    for (const auto& y : responses) coarse = std::max(coarse, std::abs(y(0)));
    std::printf("zeta %.0e: displacement peak %.6g (closed form %.6g, coarse grid %.6g), velocity peak %.6g (%.6g), %zu frequencies added\n",
                zeta, refined.peaks[0].amplitude, displacement_peak, coarse, refined.peaks[1].amplitude, velocity_peak, refined.added);
    for (const study::ResonancePeak& peak : refined.peaks) EXPECT_TRUE(peak.converged) << zeta << " output " << peak.output;
    EXPECT_NEAR(refined.peaks[0].amplitude / displacement_peak, 1.0, 1e-3) << zeta;
    EXPECT_NEAR(refined.peaks[1].amplitude / velocity_peak, 1.0, 1e-3) << zeta;
    // Where: within a tenth of the half-power half-width ζω_n of the closed form's frequencies.
    EXPECT_NEAR(refined.peaks[0].angular_frequency, omega_n * std::sqrt(1.0 - 2.0 * zeta * zeta), 0.1 * zeta * omega_n) << zeta;
    EXPECT_NEAR(refined.peaks[1].angular_frequency, omega_n, 0.1 * zeta * omega_n) << zeta;
    EXPECT_LE(refined.added, 30u) << zeta;
  }
}

// An output without a local maximum at the mode (here a constant) is not searched; a mode outside
// the band or without a resonance (ζ ≥ 1/√2) adds no frequency.
TEST(RaoPeaks, OutputsWithoutAPeakAndModesOutsideTheBandAddNothing) {
  const std::vector<double> grid{0.2, 0.4, 0.6, 0.8, 1.0};
  const study::OutputResponse flat = [](double) { return Eigen::VectorXcd::Constant(1, cd(2.0, 0.0)); };
  std::vector<Eigen::VectorXcd> responses(grid.size(), Eigen::VectorXcd::Constant(1, cd(2.0, 0.0)));
  const study::RefinedResponse outside =
      study::refine_resonance_peaks(grid, responses, {{3.0, 0.01, "x", ""}, {0.5, 0.8, "y", ""}}, flat, {true});
  EXPECT_EQ(outside.added, 0u);
  EXPECT_TRUE(outside.peaks.empty());
  const study::RefinedResponse inside = study::refine_resonance_peaks(grid, responses, {{0.5, 0.01, "x", ""}}, flat, {true});
  EXPECT_EQ(inside.added, 7u);  // the seeds only
  EXPECT_TRUE(inside.peaks.empty());
}

const study::NaturalMode& mode_named(const study::ModelRao& model, const std::string& dominant) {
  const auto it = std::find_if(model.modes.begin(), model.modes.end(), [&](const study::NaturalMode& m) { return m.dominant == dominant; });
  if (it == model.modes.end()) throw std::runtime_error("no " + dominant + " mode");
  return *it;
}

// The reference crane's rigid cargo surge: the refined default grid's peak equals the largest of
// 2001 frequencies evenly spread over ±5ζω_n around the mode.
TEST(RaoPeaks, ReferenceCraneCargoSurgePeakMatchesABruteForceGrid) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  study::RaoRequest request;
  request.models = {{scene::BoomKind::rigid, 1}};
  request.angular_frequencies = default_grid();
  const auto surge = static_cast<std::size_t>(multibody::LinearOutput::cargo_surge);
  const double coarse = largest(study::response_amplitude_operators(scene, request).models[0].response[surge]);
  request.refine_peaks = true;
  const study::RaoResult refined = study::response_amplitude_operators(scene, request);
  const study::ModelRao& model = refined.models[0];
  const study::NaturalMode& mode = mode_named(model, "cargo surge");
  request.refine_peaks = false;
  request.angular_frequencies.clear();
  const double width = mode.damping_ratio * mode.angular_frequency;
  for (int i = 0; i <= 2000; ++i) request.angular_frequencies.push_back(mode.angular_frequency + width * (-5.0 + 10.0 * i / 2000.0));
  const double brute = largest(study::response_amplitude_operators(scene, request).models[0].response[surge]);
  const double peak = largest(model.response[surge]);
  std::printf("rigid cargo surge: T_n %.4f s, zeta %.4f; default grid %.6g m/m, refined %.6g m/m (%zu frequencies added), "
              "2001-point grid %.6g m/m\n", mode.period(), mode.damping_ratio, coarse, peak, model.added_frequencies, brute);
  EXPECT_NEAR(peak / brute, 1.0, 1e-3);
  const auto found = std::find_if(model.peaks.begin(), model.peaks.end(), [&](const study::ResonancePeak& p) {
    return p.output == static_cast<int>(surge) && model.modes[p.mode].dominant == "cargo surge";
  });
  ASSERT_NE(found, model.peaks.end());
  EXPECT_TRUE(found->converged);
  EXPECT_DOUBLE_EQ(found->amplitude, peak);
  for (const study::ResonancePeak& p : model.peaks) EXPECT_TRUE(p.converged) << p.mode << " " << p.output;
}

// 4 √(∫ |Y|² S dω) over the refined default grid against Simpson's rule on 4001 evenly spaced
// frequencies of the same band, in a JONSWAP sea (Hs 1.5 m, Tp 9 s).
TEST(RaoSpectrum, SignificantResponseEqualsAFineQuadratureOfTheResponseSpectrum) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const hydro::WaveSpectrum sea = hydro::jonswap(1.5, 9.0, 3.3);
  study::RaoRequest request;
  request.models = {{scene::BoomKind::rigid, 1}};
  request.angular_frequencies = default_grid();
  request.refine_peaks = true;
  request.sea_spectrum = sea;
  const study::RaoResult result = study::response_amplitude_operators(scene, request);
  ASSERT_TRUE(result.sea);
  const double low = request.angular_frequencies.front(), high = request.angular_frequencies.back();
  EXPECT_NEAR(result.sea->m0, 1.5 * 1.5 / 16.0, 1e-9);
  const int intervals = 4000;
  request.refine_peaks = false;
  request.sea_spectrum.reset();
  request.angular_frequencies.clear();
  for (int i = 0; i <= intervals; ++i) request.angular_frequencies.push_back(low + (high - low) * i / intervals);
  const study::RaoResult fine = study::response_amplitude_operators(scene, request);
  for (const auto output : {multibody::LinearOutput::hull_heave, multibody::LinearOutput::hull_pitch, multibody::LinearOutput::cargo_surge,
                            multibody::LinearOutput::cargo_heave, multibody::LinearOutput::wire_tension}) {
    const auto k = static_cast<std::size_t>(output);
    double m0 = 0.0;
    for (int i = 0; i <= intervals; ++i) {
      const double weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      const double omega = request.angular_frequencies[static_cast<std::size_t>(i)];
      m0 += weight * std::norm(fine.models[0].response[k][static_cast<std::size_t>(i)]) * hydro::spectral_density(sea, omega);
    }
    const double expected = 4.0 * std::sqrt(m0 * (high - low) / intervals / 3.0);
    const double significant = result.models[0].significant_response[k];
    std::printf("%s: significant %.6g, Simpson on 4001 points %.6g (%+.2e)\n", std::string(multibody::to_string(output)).c_str(),
                significant, expected, significant / expected - 1.0);
    EXPECT_NEAR(significant / expected, 1.0, 5e-3) << multibody::to_string(output);
  }
}

// `rao` builds the nodal and modal booms on the scene's boom.elements (12 in the BEM barge crane):
// the nodal model has 3 elastic coordinates per element beside the hull's and the cargo's 3 + 3.
TEST(RaoModels, TheBoomHasTheScenesElementCount) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  ASSERT_EQ(scene.boom.mesh.element_count, 12);
  study::RaoRequest request;
  request.angular_frequencies = {0.6};
  const study::RaoResult result = study::response_amplitude_operators(scene, request);
  ASSERT_EQ(result.models.size(), 3u);
  EXPECT_EQ(result.models[0].choice.kind, scene::BoomKind::rigid);
  EXPECT_EQ(result.models[0].coordinates, 6);
  EXPECT_EQ(result.models[1].choice.elements, 12);
  EXPECT_EQ(result.models[1].coordinates, 6 + 3 * 12);
  EXPECT_EQ(result.models[2].choice.elements, 12);
}

}  // namespace
}  // namespace ffrf
