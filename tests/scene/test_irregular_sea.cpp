// Irregular seas in a scene: the [wave] keys of a JONSWAP sea load into the sea the
// builder synthesizes; the coupling wave field built from it has the hydro synthesis's elevation
// (phase convention, heading) and, over the record, the variance the spectrum gives (checked
// against the spectrum's own Gauss–Legendre integral over the band: a second method, not the
// Riemann sum the synthesis uses); the regular wave is the one-component field; bad keys and a
// sea steeper than DNV-RP-C205's limit are named with file, key, value and range; a record
// longer than the sea's repeat period is warned about; in_irregular_sea validates the same way.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

#include "hydro/wave_spectrum.hpp"
#include "scene/irregular_sea.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf::scene {
namespace {

std::string sea_text() {
  std::ifstream in(FFRF_SOURCE_DIR "/cases/irregular_sea_crane.toml");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The reference crane's sea over a 20-minute record (fewer components: a fast test), over the
// automatic band (all but 0.1 % of m0).
std::string short_sea_text() {
  const std::string text = replaced(sea_text(), "duration = 10800.0 ", "duration = 1200.0 ");
  return replaced(replaced(text, "frequency_min = 0.3927 ", "#"), "frequency_max = 2.3562 ", "#");
}

Scene short_sea(const std::string& extra = "") {
  std::string text = short_sea_text();
  if (!extra.empty()) text = replaced(text, "ramp_periods = 2.0 ", extra + "\nramp_periods = 2.0 ");
  return load_scene_text(text, "sea.toml");
}

std::vector<SceneProblem> problems_of(const std::string& text) {
  try {
    (void)load_scene_text(text, "bad.toml");
  } catch (const SceneError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "accepted";
  return {};
}

TEST(IrregularSea, ShippedSceneLoadsTheJonswapKeys) {
  const Scene scene = load_scene(FFRF_SOURCE_DIR "/cases/irregular_sea_crane.toml");
  ASSERT_TRUE(scene.sea.has_value());
  EXPECT_FALSE(scene.wave.has_value());
  const IrregularSea& sea = *scene.sea;
  EXPECT_EQ(sea.spectrum, SeaSpectrum::jonswap);
  EXPECT_EQ(sea.significant_height, 2.0);
  EXPECT_EQ(sea.peak_period, 8.0);
  EXPECT_EQ(sea.peak_enhancement, 3.3);
  EXPECT_EQ(sea.sigma_below, 0.07);
  EXPECT_EQ(sea.sigma_above, 0.09);
  EXPECT_EQ(sea.heading, hydro::WaveHeading::following);
  EXPECT_EQ(sea.seed, 1u);
  EXPECT_EQ(sea.frequency_min, 0.3927);
  EXPECT_EQ(sea.frequency_max, 2.3562);
  EXPECT_EQ(scene.simulation.duration, 10800.0);
  EXPECT_TRUE(scene.warnings.empty());
  // Δω = 2π / record: the sea repeats exactly after the record, not before.
  const hydro::WaveComponents components = sea_components(scene);
  EXPECT_NEAR(components.repeat_period(), 10800.0, 1e-9);
  EXPECT_DOUBLE_EQ(wave_ramp_duration(scene), 16.0);
}

TEST(IrregularSea, ShippedBemSceneIsTheSameSeaOnTheBargeItsCoefficientsBelongTo) {
  // cases/irregular_bem_barge_crane.toml: the sea of cases/irregular_sea_crane.toml (compared key by
  // key, and the synthesized components one by one), on the 80 m × 10 m barge of the WAMIT fixture
  // (tests/hydro/data/README.md), with the Cummins convolution and the BEM excitation.
  const Scene reference = load_scene(FFRF_SOURCE_DIR "/cases/irregular_sea_crane.toml");
  const Scene scene = load_scene(FFRF_SOURCE_DIR "/cases/irregular_bem_barge_crane.toml");
  ASSERT_TRUE(scene.sea.has_value());
  ASSERT_TRUE(scene.bem.has_value());
  ASSERT_TRUE(scene.hull.has_value());
  EXPECT_TRUE(scene.warnings.empty());
  EXPECT_EQ(scene.hull->length, 80.0);
  EXPECT_EQ(scene.hull->width, 10.0);
  EXPECT_EQ(scene.bem->radiation_model, hydro::RadiationKind::convolution);
  EXPECT_EQ(scene.bem->excitation, ExcitationModel::bem);
  EXPECT_TRUE(scene.bem->excitation_table.has_value());
  EXPECT_EQ(scene.simulation.duration, reference.simulation.duration);
  const hydro::WaveComponents sea = sea_components(scene), expected = sea_components(reference);
  ASSERT_EQ(sea.frequency.size(), expected.frequency.size());
  for (std::size_t i = 0; i < sea.frequency.size(); ++i) {
    EXPECT_EQ(sea.frequency[i], expected.frequency[i]);
    EXPECT_EQ(sea.amplitude[i], expected.amplitude[i]);
    EXPECT_EQ(sea.phase[i], expected.phase[i]);
  }
}

TEST(IrregularSea, WaveFieldElevationIsTheSynthesisInBothHeadings) {
  for (const char* heading : {"following", "head"}) {
    const Scene scene = load_scene_text(
        replaced(replaced(sea_text(), "duration = 10800.0 ", "duration = 1200.0 "), "direction = \"following\"",
                 std::string("direction = \"") + heading + "\""),
        "sea.toml");
    const hydro::WaveComponents components = sea_components(scene);
    const std::optional<sea::WaveField> field = scene_wave_field(scene);
    ASSERT_TRUE(field.has_value());
    ASSERT_EQ(field->components().size(), components.size());
    const double sign = std::string(heading) == "following" ? 1.0 : -1.0;
    EXPECT_EQ(field->direction(), sign);
    for (double t : {20.0, 333.3, 1111.0}) {
      // η(0, t) = Σ a cos(ω t + φ) (hydro) and, at x, Σ a cos(ω t ∓ k x + φ) (travelling ±x).
      EXPECT_NEAR(field->elevation(0.0, t), hydro::elevation(components, t), 1e-10);
      const double x = 37.0;
      double expected = 0.0;
      for (std::size_t n = 0; n < components.size(); ++n) {
        const double k = components.frequency[n] * components.frequency[n] / scene.environment.gravity;
        expected += components.amplitude[n] * std::cos(components.frequency[n] * t - sign * k * x + components.phase[n]);
      }
      EXPECT_NEAR(field->elevation(x, t), expected, 1e-9);
    }
  }
}

TEST(IrregularSea, ElevationVarianceOverTheRecordIsTheSpectrumsBandIntegral) {
  // Deterministic amplitudes over one repeat period: the sampled variance of η equals Σ a²/2
  // (orthogonality of the harmonics of 2π/T); that sum is the Riemann sum of ∫ S dω over the band,
  // which the Gauss–Legendre moment of the spectrum gives independently; the band holds all but
  // 0.1 % of m0 = Hs²/16.
  const Scene scene = short_sea();
  const IrregularSea& sea = *scene.sea;
  ASSERT_EQ(sea.frequency_max, 0.0);  // the automatic band
  const std::optional<sea::WaveField> field = scene_wave_field(scene);
  const double record = scene.simulation.duration, dt = 0.25;
  const auto samples = static_cast<std::size_t>(record / dt);
  double sum = 0.0, square = 0.0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double eta = field->elevation(0.0, 100.0 + static_cast<double>(i) * dt);  // after the ramp
    sum += eta;
    square += eta * eta;
  }
  const double mean = sum / static_cast<double>(samples);
  const double variance = square / static_cast<double>(samples) - mean * mean;
  const hydro::WaveComponents components = sea_components(scene);
  EXPECT_NEAR(variance, components.variance(), 1e-9 * components.variance());
  const hydro::WaveSpectrum spectrum = sea_spectrum(sea);
  const double lo = components.frequency.front() - 0.5 * components.frequency_step;
  const double hi = components.frequency.back() + 0.5 * components.frequency_step;
  EXPECT_NEAR(components.variance(), hydro::spectral_moment(spectrum, 0, lo, hi), 2e-3 * components.variance());
  const double m0 = sea.significant_height * sea.significant_height / 16.0;
  EXPECT_NEAR(variance, m0, 2e-3 * m0);  // the 0.1 % tails + the midpoint rule's error
}

TEST(IrregularSea, OneComponentSeaIsTheRegularWave) {
  const Scene regular = load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  std::string text;
  {
    std::ifstream in(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
    text = std::string(std::istreambuf_iterator<char>(in), {});
  }
  text = replaced(text, "height = 1.0 ", "spectrum = \"components\"\ncomponent_frequencies = [0.6283185307179586]\n"
                                         "component_amplitudes = [0.5]\ncomponent_phases = [0.0]\n#");
  text = replaced(text, "period = 10.0 ", "#");
  const Scene one = load_scene_text(text, "one.toml");
  ASSERT_TRUE(one.sea.has_value());
  const std::optional<sea::WaveField> a = scene_wave_field(regular), b = scene_wave_field(one);
  ASSERT_EQ(b->components().size(), 1u);
  EXPECT_NEAR(b->ramp_duration(), a->ramp_duration(), 1e-12);
  EXPECT_EQ(b->components()[0].wave_number, a->components()[0].wave_number);
  for (double t : {1.0, 7.0, 19.99, 20.0, 55.5})
    for (double x : {-40.0, 0.0, 61.0})
      for (double y : {-6.0, -1.0, 0.2}) {
        EXPECT_NEAR(b->pressure(x, y, t, 1025.0), a->pressure(x, y, t, 1025.0), 1e-9);
        EXPECT_NEAR((b->velocity(x, y, t) - a->velocity(x, y, t)).norm(), 0.0, 1e-12);
      }
}

TEST(IrregularSea, SeedChoosesTheRealisation) {
  const hydro::WaveComponents one = sea_components(short_sea()), again = sea_components(short_sea());
  const Scene other = load_scene_text(replaced(short_sea_text(), "seed = 1 ", "seed = 2 "), "sea.toml");
  const hydro::WaveComponents two = sea_components(other);
  EXPECT_EQ(one.phase, again.phase);
  EXPECT_EQ(one.amplitude, two.amplitude);  // deterministic amplitudes: the spectrum's
  EXPECT_NE(one.phase, two.phase);
}

TEST(IrregularSea, ComponentCountCoarserThanTheRecordIsWarned) {
  const Scene scene = short_sea("components = 100");
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("wave.components"), std::string::npos) << scene.warnings[0];
  EXPECT_NE(scene.warnings[0].find("repeats after"), std::string::npos) << scene.warnings[0];
  EXPECT_NEAR(static_cast<double>(sea_components(scene).size()), 100.0, 1.0);
}

TEST(IrregularSea, SteepSeaNamesKeyValueAndTheDnvLimit) {
  // 2π Hs / (g Tp²) ≤ 1/15 at Tp = 6 s: Hs ≤ g 36 / (30 π) = 3.747 m.
  const auto problems = problems_of(replaced(replaced(sea_text(), "significant_height = 2.0 ", "significant_height = 5.0 "),
                                             "peak_period = 8.0 ", "peak_period = 6.0 "));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "wave.significant_height");
  EXPECT_EQ(problems[0].value, "5.0");
  EXPECT_NE(problems[0].message.find("valid range (0, 3.747] m"), std::string::npos) << problems[0].message;
}

TEST(IrregularSea, KeysOfAnotherSpectrumAndMissingKeysAreNamed) {
  const auto missing = problems_of(replaced(sea_text(), "peak_period = 8.0 ", "#"));
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0].key, "wave.peak_period");
  EXPECT_NE(missing[0].message.find("valid range [1, 40] s"), std::string::npos);
  const auto foreign = problems_of(replaced(sea_text(), "peak_period = 8.0 ", "period = 8.0\npeak_period = 8.0 "));
  ASSERT_EQ(foreign.size(), 1u);
  EXPECT_EQ(foreign[0].key, "wave.period");
  const auto unequal = problems_of(replaced(
      replaced(replaced(sea_text(), "significant_height = 2.0 ", "#"), "peak_period = 8.0 ", "#"),
      "spectrum = \"jonswap\" ",
      "spectrum = \"components\"\ncomponent_frequencies = [0.5, 0.6]\ncomponent_amplitudes = [0.5]\n"
      "component_phases = [0, 1]\n#"));
  ASSERT_FALSE(unequal.empty());
  bool named = false;
  for (const SceneProblem& p : unequal) named = named || p.key == "wave.component_amplitudes";
  EXPECT_TRUE(named) << SceneError(unequal).what();
}

TEST(IrregularSea, InIrregularSeaSetsTheSeaAndTheRecord) {
  const Scene base = load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  IrregularSeaState state;
  state.significant_height = 1.5;
  state.peak_period = 9.0;
  state.seed = 7;
  state.duration = 600.0;
  const Scene scene = in_irregular_sea(base, state);
  EXPECT_FALSE(scene.wave.has_value());
  ASSERT_TRUE(scene.sea.has_value());
  EXPECT_EQ(scene.sea->significant_height, 1.5);
  EXPECT_EQ(scene.sea->peak_period, 9.0);
  EXPECT_EQ(scene.sea->seed, 7u);
  EXPECT_EQ(scene.simulation.duration, 600.0);
  EXPECT_NEAR(sea_components(scene).repeat_period(), 600.0, 1e-9);
}

TEST(IrregularSea, InIrregularSeaNamesBadValues) {
  const Scene base = load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  const auto problem = [&](IrregularSeaState state) -> SceneProblem {
    try {
      (void)in_irregular_sea(base, state);
    } catch (const SceneError& error) {
      return error.problems().front();
    }
    ADD_FAILURE() << "accepted";
    return {};
  };
  IrregularSeaState good{"jonswap", 2.0, 8.0, 3.3, hydro::WaveHeading::following, 1, 600.0};
  IrregularSeaState bad = good;
  bad.significant_height = -1.0;
  SceneProblem p = problem(bad);
  EXPECT_EQ(p.file, base.file);
  EXPECT_EQ(p.key, "wave.significant_height");
  EXPECT_EQ(p.value, "-1");
  EXPECT_NE(p.message.find("valid range (0, 30] m"), std::string::npos);
  bad = good;
  bad.peak_period = 0.0;
  EXPECT_EQ(problem(bad).key, "wave.peak_period");
  bad = good;
  bad.peak_enhancement = 0.5;
  p = problem(bad);
  EXPECT_EQ(p.key, "wave.peak_enhancement");
  EXPECT_NE(p.message.find("valid range [1, 20]"), std::string::npos);
  bad = good;
  bad.significant_height = 8.0;
  bad.peak_period = 6.0;
  p = problem(bad);
  EXPECT_EQ(p.key, "wave.significant_height");
  EXPECT_NE(p.message.find("too steep"), std::string::npos);
  bad = good;
  bad.spectrum = "bretschneider";
  EXPECT_EQ(problem(bad).key, "wave.spectrum");
}

}  // namespace
}  // namespace ffrf::scene
