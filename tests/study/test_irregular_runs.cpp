// The crane in an irregular sea: the regular-wave scene and the same wave
// written as one user component run to the same motions (the new path adds nothing); a seed is a
// realisation — the same seed runs identically, another seed differently; the run's statistics
// are those of hydro's record analysis and, on a synthetic narrow-band Gaussian record, their
// Rayleigh most probable maximum is the closed form σ √(2 ln N) (Longuet-Higgins 1952) to the
// order of its next term, and 4σ of a sinusoid of amplitude A is 2√2 A exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>

#include "hydro/extreme_values.hpp"
#include "scene/irregular_sea.hpp"
#include "study/irregular_statistics.hpp"
#include "study/run_pipeline.hpp"
#include "study_test_support.hpp"

namespace {

using namespace ffrf;

std::string text_of(const std::string& name) {
  std::ifstream in(FFRF_SOURCE_DIR "/cases/" + name);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

study::ModelRun run(const scene::Scene& scene, double duration) {
  study::DynamicsRequest request;
  request.duration = duration;
  return study::run_model(scene, {scene::BoomKind::modal, 16, 2, true}, study::integrator_settings(scene, request));
}

TEST(IrregularRuns, OneComponentSeaRunsAsTheRegularWave) {
  const scene::Scene regular = test::scene_file("paper_floating_crane.toml");
  std::string text = replaced(text_of("paper_floating_crane.toml"), "height = 1.0 ",
                              "spectrum = \"components\"\ncomponent_frequencies = [0.6283185307179586]\n"
                              "component_amplitudes = [0.5]\ncomponent_phases = [0.0]\n#");
  const scene::Scene one = scene::load_scene_text(replaced(text, "period = 10.0 ", "#"), "one.toml");
  const study::ModelRun a = run(regular, 30.0), b = run(one, 30.0);
  ASSERT_EQ(a.result.samples.size(), b.result.samples.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.result.samples.size(); ++i) {
    worst = std::max({worst, std::abs(a.result.samples[i].hull.y() - b.result.samples[i].hull.y()),
                      std::abs(a.result.samples[i].cargo.y() - b.result.samples[i].cargo.y())});
  }
  // The ramp 2·2π/ω differs from 2·T in the last bit: far below the integration tolerance.
  EXPECT_LT(worst, 1e-7);
  EXPECT_GT(a.stats[study::series_index("crane_heave_m")].rms, 1e-3);  // the wave moves the crane
}

TEST(IrregularRuns, SameSeedSameRunOtherSeedOtherRun) {
  std::string text = replaced(text_of("irregular_sea_crane.toml"), "duration = 10800.0 ", "duration = 600.0 ");
  const scene::Scene first = scene::load_scene_text(text, "sea.toml");
  const scene::Scene again = scene::load_scene_text(text, "sea.toml");
  const scene::Scene other = scene::load_scene_text(replaced(text, "seed = 1 ", "seed = 2 "), "sea.toml");
  const study::ModelRun a = run(first, 40.0), b = run(again, 40.0), c = run(other, 40.0);
  ASSERT_EQ(a.result.samples.size(), b.result.samples.size());
  double same = 0.0, different = 0.0;
  for (std::size_t i = 0; i < a.result.samples.size() && i < c.result.samples.size(); ++i) {
    same = std::max(same, std::abs(a.result.samples[i].cargo.y() - b.result.samples[i].cargo.y()));
    different = std::max(different, std::abs(a.result.samples[i].cargo.y() - c.result.samples[i].cargo.y()));
  }
  EXPECT_EQ(same, 0.0);
  EXPECT_GT(different, 0.01);  // [m]: another sea moves the cargo otherwise
}

// Crane outputs whose crane heave is `record` (all else static).
std::vector<multibody::CraneOutputs> samples_with_heave(const std::vector<double>& record) {
  std::vector<multibody::CraneOutputs> samples(record.size());
  for (std::size_t i = 0; i < record.size(); ++i) {
    samples[i].hull = Eigen::Vector3d(0.0, record[i], 0.0);
    samples[i].wire_tension = 1e7;
  }
  return samples;
}

TEST(IrregularRuns, StatisticsOfANarrowBandGaussianRecordMatchRayleigh) {
  // A narrow-band Gaussian process: 100 harmonics of 2π/T (T = the record) within ±5.5 % of ω0 with
  // equal amplitudes and random phases. Over the whole record the harmonics are orthogonal: the
  // record's variance is Σ a²/2 = σ² exactly, whatever the phases.
  const scene::Scene scene = scene::load_scene_text(
      replaced(text_of("irregular_sea_crane.toml"), "duration = 10800.0 ", "duration = 7200.0 "), "sea.toml");
  const double dt = 0.25, omega0 = 0.8, sigma = 0.3, record_length = 7200.0;
  const std::size_t count = 28800;  // the whole record
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  const int harmonics = 100;
  const double step = 2.0 * std::numbers::pi / record_length;
  const double first = std::round(omega0 / step) - harmonics / 2;
  std::vector<double> w(harmonics), p(harmonics);
  for (int h = 0; h < harmonics; ++h) {
    w[static_cast<std::size_t>(h)] = (first + h) * step;
    p[static_cast<std::size_t>(h)] = phase(random);
  }
  const double amplitude = sigma * std::sqrt(2.0 / harmonics);
  std::vector<double> record(count), time(count);
  for (std::size_t i = 0; i < count; ++i) {
    time[i] = static_cast<double>(i) * dt;
    for (int h = 0; h < harmonics; ++h) {
      record[i] += amplitude * std::cos(w[static_cast<std::size_t>(h)] * time[i] + p[static_cast<std::size_t>(h)]);
    }
  }
  multibody::CraneOutputs statics;
  statics.wire_tension = 1e7;
  const auto stats = study::irregular_statistics(scene, time, samples_with_heave(record), statics, 0, dt);
  ASSERT_TRUE(stats.has_value());
  const study::ResponseStatistics& heave = stats->responses[0];
  ASSERT_EQ(heave.column, "crane_heave_m");
  ASSERT_TRUE(heave.extremes) << stats->note;
  EXPECT_NEAR(heave.standard_deviation, sigma, 1e-9);
  EXPECT_DOUBLE_EQ(heave.significant, 4.0 * heave.standard_deviation);
  EXPECT_NEAR(heave.zero_crossing_period, 2.0 * std::numbers::pi / omega0, 0.02 * 2.0 * std::numbers::pi / omega0);
  EXPECT_NEAR(heave.peak_frequency, omega0, 0.03 * omega0);
  // Rayleigh MPM over N = 7200 s / Tz cycles: σ √(2 ln N) (the mode's asymptote; the exact mode
  // differs by O(σ / √(2 ln N)) / (2 ln N), here < 2 %).
  const double cycles = record_length / heave.zero_crossing_period;
  const double closed_form = heave.standard_deviation * std::sqrt(2.0 * std::log(cycles));
  EXPECT_NEAR(heave.rayleigh - heave.mean, closed_form, 0.02 * closed_form);
  // For a Gaussian record the Weibull fit to the peaks is nearly Rayleigh (shape ≈ 2) and all three
  // estimates agree with the observed maximum to its scatter (a standard deviation of ~10 %).
  EXPECT_NEAR(heave.weibull_shape, 2.0, 0.3);
  for (double mpm : {heave.rayleigh, heave.weibull, heave.gumbel}) EXPECT_NEAR(mpm, heave.observed_maximum, 0.25 * closed_form);
  // The static outputs have no variance: no spectrum, no extremes, no NaN.
  const study::ResponseStatistics& pitch = stats->responses[1];
  EXPECT_EQ(pitch.standard_deviation, 0.0);
  EXPECT_FALSE(pitch.extremes);
  // A constant tension equal to the static one: DAF 1.
  EXPECT_DOUBLE_EQ(stats->wire.maximum_factor, 1.0);
}

TEST(IrregularRuns, SignificantValueOfASinusoidIsTwoRootTwoTimesItsAmplitude) {
  const scene::Scene scene = test::scene_file("irregular_sea_crane.toml");
  const double dt = 0.1, amplitude = 0.7, period = 8.0;
  std::vector<double> record, time;
  for (int i = 0; i < 8000; ++i) {  // 100 whole periods
    time.push_back(i * dt);
    record.push_back(amplitude * std::sin(2.0 * std::numbers::pi * time.back() / period));
  }
  multibody::CraneOutputs statics;
  const auto stats = study::irregular_statistics(scene, time, samples_with_heave(record), statics, 0, dt);
  ASSERT_TRUE(stats.has_value());
  EXPECT_NEAR(stats->responses[0].significant, 2.0 * std::sqrt(2.0) * amplitude, 1e-9);
  EXPECT_NEAR(stats->responses[0].zero_crossing_period, period, 1e-6);
  // The incident elevation is the scene's sea at x = 0: its 4σ is the realised Hs (the 10-s
  // window of this test only needs to be finite and positive).
  EXPECT_GT(stats->elevation.significant, 0.0);
}

}  // namespace
