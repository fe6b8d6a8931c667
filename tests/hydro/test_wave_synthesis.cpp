// Synthesized seas against the spectrum they come from. Over a whole repeat period the discrete
// mean square of η equals Σ a²/2 exactly (orthogonality of the harmonics n Δω on N > 2 n_max
// samples), and Σ a²/2 = Σ S(nΔω) Δω equals m0 less the tails left outside the band. Over a shorter
// record T the sample mean square scatters about m0 with the variance derived in
// docs/hydrodynamics.md §2.4,
//   Var = Σ_{m≠n} S_m S_n Δω² sinc²((ω_m − ω_n) T / 2)  [+ Σ S_n² Δω² with Rayleigh amplitudes],
// which the ensemble of realisations must reproduce (mean and spread).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "hydro/wave_synthesis.hpp"

namespace {

using namespace ffrf::hydro;

double mean_square(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v * v;
  return sum / static_cast<double>(x.size());
}

TEST(WaveSynthesis, WholePeriodVarianceEqualsM0LessTheTails) {
  const auto spectrum = jonswap(2.0, 8.0, 3.3);
  SynthesisOptions options;
  options.record_length = 1800.0;
  options.seed = 11;
  const auto sea = synthesize(spectrum, options);
  const double period = sea.repeat_period;
  ASSERT_NEAR(period, 1800.0, 1e-9);
  const double n_max = sea.components.frequency.back() / sea.components.frequency_step;
  const std::size_t samples = 7200;
  ASSERT_GT(static_cast<double>(samples), 2.0 * n_max);
  const auto eta = elevation_record(sea.components, 0.0, period / static_cast<double>(samples), samples);
  EXPECT_NEAR(mean_square(eta), sea.components.variance(), 1e-12 * sea.components.variance());
  EXPECT_NEAR(sea.components.variance(), sea.band_m0, 1e-12 * sea.band_m0);
  // Σ S(nΔω) Δω is the midpoint rule for ∫ S over [ω_first − Δω/2, ω_last + Δω/2] (error O(Δω²));
  // m0 = Hs²/16 = 0.25, of which the band leaves 1e-3 outside, give or take those half bins.
  const double step = sea.components.frequency_step;
  const double cells = spectral_moment(spectrum, 0, sea.components.frequency.front() - 0.5 * step,
                                       sea.components.frequency.back() + 0.5 * step);
  // Midpoint-rule error bound (Δω²/24) ∫|S''| dω, S'' by central differences.
  double curvature = 0.0;
  const double h = 1e-4;
  for (double w = sea.components.frequency.front(); w < sea.components.frequency.back(); w += h)
    curvature += std::abs(spectral_density(spectrum, w + h) - 2 * spectral_density(spectrum, w) + spectral_density(spectrum, w - h)) / h;
  EXPECT_NEAR(sea.band_m0, cells, step * step / 24.0 * curvature);
  EXPECT_NEAR(sea.band_m0 / 0.25, 1.0 - 1e-3, 5e-5);
  EXPECT_NEAR(sea.spectrum_m0, 0.25, 1e-12);
  // The sea repeats exactly after 2π/Δω.
  EXPECT_NEAR(elevation(sea.components, 123.4 + period), elevation(sea.components, 123.4), 1e-9);
}

double sinc(double x) { return x == 0.0 ? 1.0 : std::sin(x) / x; }

// Var of (1/T)∫η² for the components' expected energies e_n = S_n Δω.
double sampling_variance(const std::vector<double>& omega, const std::vector<double>& e, double record,
                         bool random_amplitudes) {
  double var = 0.0;
  for (std::size_t m = 0; m < omega.size(); ++m) {
    for (std::size_t n = 0; n < omega.size(); ++n) {
      if (m != n) var += e[m] * e[n] * std::pow(sinc(0.5 * (omega[m] - omega[n]) * record), 2);
    }
    if (random_amplitudes) var += e[m] * e[m];
  }
  return var;
}

void check_ensemble(bool random_amplitudes, double repeat_period, double record, int realisations) {
  const auto spectrum = jonswap(2.0, 8.0, 3.3);
  SynthesisOptions options;
  options.record_length = repeat_period;
  options.seed = 2024;
  options.random_amplitudes = random_amplitudes;
  const double dt = 0.25;
  const auto samples = static_cast<std::size_t>(record / dt);
  std::vector<double> variances;
  SeaRealisation sea;
  for (int r = 0; r < realisations; ++r) {
    options.realisation = static_cast<std::uint64_t>(r);
    sea = synthesize(spectrum, options);
    variances.push_back(mean_square(elevation_record(sea.components, 0.0, dt, samples)));
  }
  std::vector<double> expected_energy;
  for (double w : sea.components.frequency) expected_energy.push_back(spectral_density(spectrum, w) * sea.components.frequency_step);
  const double sd = std::sqrt(sampling_variance(sea.components.frequency, expected_energy, record, random_amplitudes));
  double mean = 0.0;
  for (double v : variances) mean += v;
  mean /= realisations;
  double spread = 0.0;
  for (double v : variances) spread += (v - mean) * (v - mean);
  spread = std::sqrt(spread / (realisations - 1));
  // The mean of the ensemble: within 4 standard errors of the band energy; each record within 4.5 sd.
  EXPECT_NEAR(mean, sea.band_m0, 4.0 * sd / std::sqrt(realisations));
  for (double v : variances) EXPECT_NEAR(v, sea.band_m0, 4.5 * sd);
  // The spread: its relative standard error is about 1/sqrt(2 M): 25 % is > 3.5 of them for M ≥ 100.
  EXPECT_NEAR(spread / sd, 1.0, 0.25) << "sd predicted " << sd << ", measured " << spread;
  ::testing::Test::RecordProperty("predicted_sd_over_m0", std::to_string(sd / sea.band_m0));
  ::testing::Test::RecordProperty("measured_sd_over_m0", std::to_string(spread / sea.band_m0));
}

TEST(WaveSynthesis, RayleighAmplitudeSeasScatterAsAGaussianSeaOverTheirPeriod) {
  check_ensemble(true, 600.0, 600.0, 200);
}

TEST(WaveSynthesis, ShortRecordsOfALongSeaScatterByTheDerivedSamplingError) {
  check_ensemble(false, 3600.0, 600.0, 120);
}

TEST(WaveSynthesis, RealisationsAreTheSameWhateverTheThreadAndOrder) {
  const auto spectrum = pierson_moskowitz(3.0, 10.0);
  SynthesisOptions options;
  options.record_length = 1200.0;
  options.seed = 99;
  options.random_amplitudes = true;
  constexpr int count = 8;
  std::vector<WaveComponents> serial(count), threaded(count);
  for (int r = 0; r < count; ++r) {
    auto o = options;
    o.realisation = static_cast<std::uint64_t>(r);
    serial[static_cast<std::size_t>(r)] = synthesize(spectrum, o).components;
  }
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int r = count - 1 - t; r >= 0; r -= 4) {  // reverse order, interleaved over threads
        auto o = options;
        o.realisation = static_cast<std::uint64_t>(r);
        threaded[static_cast<std::size_t>(r)] = synthesize(spectrum, o).components;
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int r = 0; r < count; ++r) {
    EXPECT_EQ(serial[static_cast<std::size_t>(r)].phase, threaded[static_cast<std::size_t>(r)].phase);
    EXPECT_EQ(serial[static_cast<std::size_t>(r)].amplitude, threaded[static_cast<std::size_t>(r)].amplitude);
  }
  EXPECT_NE(serial[0].phase, serial[1].phase);
  // A component's phase depends on its harmonic number only: a wider band keeps the common ones.
  auto wide = options;
  wide.omega_min = 0.2;
  wide.omega_max = 3.0;
  auto narrow = wide;
  narrow.omega_min = 0.5;
  const auto a = synthesize(spectrum, wide).components, b = synthesize(spectrum, narrow).components;
  const auto offset = static_cast<std::size_t>(std::find(a.frequency.begin(), a.frequency.end(), b.frequency.front()) - a.frequency.begin());
  ASSERT_LT(offset, a.size());
  for (std::size_t i = 0; i < b.size(); ++i) EXPECT_EQ(a.phase[offset + i], b.phase[i]);
}

TEST(WaveSynthesis, FlagsASeaThatRepeatsWithinTheRecord) {
  const auto spectrum = jonswap(2.0, 8.0, 3.3);
  SynthesisOptions options;
  options.record_length = 10800.0;
  EXPECT_FALSE(synthesize(spectrum, options).repeats_within_record);
  options.frequency_step = 2 * std::numbers::pi / 3600.0;
  const auto sea = synthesize(spectrum, options);
  EXPECT_TRUE(sea.repeats_within_record);
  EXPECT_NEAR(sea.repeat_period, 3600.0, 1e-9);
  EXPECT_NE(sea.warning.find("repeats after 3600 s"), std::string::npos) << sea.warning;
}

TEST(WaveSynthesis, RecordByPhasorsEqualsDirectSuperposition) {
  const auto c = user_components({0.5, 0.8, 1.3}, {1.0, 0.5, 0.25}, {0.1, 2.0, -1.0}, WaveHeading::head);
  const auto eta = elevation_record(c, 10.0, 0.1, 5000);
  for (std::size_t k = 0; k < eta.size(); k += 37) EXPECT_NEAR(eta[k], elevation(c, 10.0 + 0.1 * static_cast<double>(k)), 1e-12);
  EXPECT_DOUBLE_EQ(elevation(c, 0.0), std::cos(0.1) + 0.5 * std::cos(2.0) + 0.25 * std::cos(-1.0));
}

// On a harmonic grid whose period is a whole number of steps the record is one FFT: the same values
// as the direct superposition, past one period too.
TEST(WaveSynthesis, RecordByFftOnAHarmonicGridEqualsDirectSuperposition) {
  const double step = 2.0 * std::numbers::pi / 100.0;
  const auto c = user_components({3.0 * step, 7.0 * step, 40.0 * step, 41.0 * step}, {1.0, 0.5, 0.25, 0.1}, {0.1, 2.0, -1.0, 0.4},
                                 WaveHeading::following, step);
  const auto eta = elevation_record(c, 3.3, 0.25, 1000);  // 400 steps per period
  ASSERT_EQ(eta.size(), 1000u);
  for (std::size_t k = 0; k < eta.size(); k += 13) EXPECT_NEAR(eta[k], elevation(c, 3.3 + 0.25 * static_cast<double>(k)), 1e-12);
  // A step that does not divide the period: the phasors, the same values.
  const auto uneven = elevation_record(c, 3.3, 0.3, 500);
  for (std::size_t k = 0; k < uneven.size(); k += 17) EXPECT_NEAR(uneven[k], elevation(c, 3.3 + 0.3 * static_cast<double>(k)), 1e-12);
}

TEST(WaveSynthesis, BadComponentsNameIndexValueAndRange) {
  try {
    user_components({0.5, -0.8}, {1.0, 1.0}, {0.0, 0.0}, WaveHeading::following);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("component 1 frequency [rad/s] = -0.8"), std::string::npos) << e.what();
  }
  EXPECT_THROW(user_components({0.5}, {1.0, 1.0}, {0.0}, WaveHeading::following), std::invalid_argument);
  EXPECT_THROW(user_components({0.5, 0.75}, {1.0, 1.0}, {0.0, 0.0}, WaveHeading::following, 0.1), std::invalid_argument);
  SynthesisOptions options;
  options.record_length = -1.0;
  EXPECT_THROW(synthesize(pierson_moskowitz(1.0, 8.0), options), std::invalid_argument);
}

}  // namespace
