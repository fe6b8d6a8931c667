// The FFT-sampled harmonic record against the sums taken term by term (an independent evaluation):
// values and rates within the measured midpoint bound at random times, the bound itself within the
// requested tolerance, periodic continuation past one period, and its refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>

#include "hydro/harmonic_record.hpp"

namespace {

using Complex = std::complex<double>;
using ffrf::hydro::HarmonicRecord;
using ffrf::hydro::HarmonicRecordOptions;
using ffrf::hydro::HarmonicSums;

// Two channels of 300 components on ω = (n0 + i) Δω, random amplitudes falling off like a sea's tail.
HarmonicSums sea_like_sums(int time_sign) {
  HarmonicSums sums;
  sums.frequency_step = 2.0 * std::numbers::pi / 1800.0;
  sums.first_harmonic = 100;
  sums.time_sign = time_sign;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  sums.coefficients.assign(2, std::vector<Complex>(300));
  for (std::size_t c = 0; c < 2; ++c)
    for (std::size_t i = 0; i < 300; ++i) {
      const double w = (100.0 + static_cast<double>(i)) * sums.frequency_step;
      sums.coefficients[c][i] = std::polar((static_cast<double>(c) + 1.0) * 0.05 / std::pow(w, 2.5), phase(random));
    }
  return sums;
}

Complex direct_sum(const HarmonicSums& sums, const std::vector<Complex>& coefficients, double t, bool rate) {
  Complex total = 0.0;
  for (std::size_t i = 0; i < coefficients.size(); ++i) {
    const double w = static_cast<double>(sums.first_harmonic + static_cast<std::int64_t>(i)) * sums.frequency_step;
    const Complex term = coefficients[i] * std::polar(1.0, sums.time_sign * w * t);
    total += rate ? Complex(0.0, sums.time_sign * w) * term : term;
  }
  return total;
}

Complex direct_sum(const HarmonicSums& sums, std::size_t channel, double t, bool rate) {
  return direct_sum(sums, sums.coefficients[channel], t, rate);
}

TEST(HarmonicRecord, InterpolatesTheSumsWithinItsMeasuredBound) {
  for (const int sign : {-1, 1}) {
    const HarmonicSums sums = sea_like_sums(sign);
    HarmonicRecordOptions options;
    options.duration = 600.0;
    options.tolerance = 1e-8;
    const HarmonicRecord record = HarmonicRecord::build(sums, options);
    EXPECT_LE(record.midpoint_error(), options.tolerance);
    EXPECT_GT(record.midpoint_error(), 0.0);
    EXPECT_GE(record.duration(), options.duration);
    EXPECT_EQ(record.memory_bytes(), 3 * record.channels() * record.samples() * sizeof(Complex));
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> time(0.0, options.duration);
    double largest = 0.0, largest_rate = 0.0, scale = 0.0;
    Complex value[2], rate[2];
    for (int n = 0; n < 2000; ++n) {
      const double t = time(random);
      record.evaluate(t, value, rate);
      for (std::size_t c = 0; c < 2; ++c) {
        largest = std::max(largest, std::abs(value[c] - direct_sum(sums, c, t, false)));
        largest_rate = std::max(largest_rate, std::abs(rate[c] - direct_sum(sums, c, t, true)));
        scale = std::max(scale, std::abs(direct_sum(sums, c, t, true)));
      }
    }
    // The Hermite error τ²(1 − τ)² s⁗ Δt⁴/24 peaks at the midpoint; s⁗ varies little over one segment.
    EXPECT_LE(largest, 1.2 * record.midpoint_error()) << "sign " << sign;
    // The rate interpolates to one order less (Δt³): still small against the rate itself.
    EXPECT_LE(largest_rate, 1e-5 * scale) << "sign " << sign;
  }
}

TEST(HarmonicRecord, ContinuesPeriodicallyPastOnePeriod) {
  const HarmonicSums sums = sea_like_sums(-1);
  HarmonicRecordOptions options;
  options.duration = 2500.0;  // the period is 1800 s
  options.tolerance = 1e-7;
  const HarmonicRecord record = HarmonicRecord::build(sums, options);
  // One period is held (N + 1 samples, the last the first again) and read at t mod 1800 s.
  EXPECT_TRUE(record.periodic());
  EXPECT_EQ(record.samples(), record.fft_size() + 1);
  EXPECT_TRUE(record.covers(1e6));
  for (const double t : {1799.3, 1800.0, 2100.7, 2499.9, 7777.7}) {
    Complex value[2];
    record.evaluate(t, value);
    EXPECT_NEAR(std::abs(value[1] - direct_sum(sums, 1, t, false)), 0.0, 1.2 * record.midpoint_error()) << t;
  }
  // Shorter than a period: not periodic, and it ends.
  options.duration = 900.0;
  const HarmonicRecord part = HarmonicRecord::build(sums, options);
  EXPECT_FALSE(part.periodic());
  EXPECT_LT(part.samples(), part.fft_size());
  EXPECT_FALSE(part.covers(part.duration() + 1.0));
}

// Real parts recorded two to a complex channel (bins n and N − n of one transform) against the real
// parts of the sums taken term by term, beside a complex channel in the same record.
TEST(HarmonicRecord, RecordsRealPartsTwoToAChannel) {
  const HarmonicSums base = sea_like_sums(-1);
  HarmonicSums sums = base;
  sums.coefficients.resize(1);
  sums.real_parts = {base.coefficients[1], base.coefficients[0], base.coefficients[1]};
  for (Complex& a : sums.real_parts[2]) a *= Complex(0.0, 3.0);  // a third channel, unlike the first
  HarmonicRecordOptions options;
  options.duration = 600.0;
  options.tolerance = 1e-8;
  const HarmonicRecord record = HarmonicRecord::build(sums, options);
  EXPECT_EQ(record.channels(), 3u);  // one complex, then three real ones in two
  EXPECT_EQ(record.complex_channels(), 1u);
  EXPECT_EQ(record.real_channels(), 3u);
  EXPECT_LE(record.midpoint_error(), options.tolerance);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> time(0.0, options.duration);
  double largest = 0.0, largest_rate = 0.0, scale = 0.0;
  Complex value[3], rate[3];
  for (int n = 0; n < 1500; ++n) {
    const double t = time(random);
    record.evaluate(t, value, rate);
    largest = std::max(largest, std::abs(value[0] - direct_sum(sums, 0, t, false)));
    for (std::size_t r = 0; r < 3; ++r) {
      const double exact = direct_sum(sums, sums.real_parts[r], t, false).real();
      const double exact_rate = direct_sum(sums, sums.real_parts[r], t, true).real();
      largest = std::max(largest, std::abs(record.real_channel(value, r) - exact));
      largest_rate = std::max(largest_rate, std::abs(record.real_channel(rate, r) - exact_rate));
      scale = std::max(scale, std::abs(exact_rate));
    }
  }
  EXPECT_LE(largest, 1.2 * record.midpoint_error());
  EXPECT_LE(largest_rate, 1e-5 * scale);
  EXPECT_GT(scale, 0.0);
}

// Samples of real parts by FFT, exact to round-off, against the sums term by term.
TEST(HarmonicSamples, AreTheRealPartsAtTheSampleTimes) {
  const HarmonicSums base = sea_like_sums(1);
  HarmonicSums sums = base;
  sums.real_parts = base.coefficients;
  sums.real_parts.push_back(base.coefficients[0]);
  for (Complex& a : sums.real_parts[2]) a = std::conj(a);
  sums.coefficients.clear();
  const ffrf::hydro::HarmonicSamples samples = ffrf::hydro::sample_real_parts(sums, 0.7);
  ASSERT_EQ(samples.channels.size(), 3u);
  EXPECT_LE(samples.time_step, 0.7);
  EXPECT_NEAR(samples.time_step * static_cast<double>(samples.channels[0].size()), 1800.0, 1e-9);
  for (std::size_t r = 0; r < 3; ++r) {
    double largest = 0.0, total = 0.0;
    for (const Complex& a : sums.real_parts[r]) total += std::abs(a);
    EXPECT_NEAR(samples.magnitude_sums[r], total, 1e-12 * total);
    for (const std::size_t j : {std::size_t{0}, std::size_t{1}, std::size_t{777}, samples.channels[r].size() - 1}) {
      const double t = static_cast<double>(j) * samples.time_step;
      largest = std::max(largest, std::abs(samples.channels[r][j] - direct_sum(sums, sums.real_parts[r], t, false).real()));
    }
    EXPECT_LE(largest, 1e-12 * total) << "channel " << r;
  }
  HarmonicSums complex_sums = base;
  EXPECT_THROW(ffrf::hydro::sample_real_parts(complex_sums, 0.7), std::invalid_argument);
}

TEST(HarmonicRecord, AFinerToleranceTakesMoreSamples) {
  const HarmonicSums sums = sea_like_sums(1);
  HarmonicRecordOptions coarse, fine;
  coarse.duration = fine.duration = 300.0;
  coarse.tolerance = 1e-5;
  fine.tolerance = 1e-9;
  const HarmonicRecord a = HarmonicRecord::build(sums, coarse), b = HarmonicRecord::build(sums, fine);
  EXPECT_GT(b.samples(), a.samples());
  EXPECT_LE(a.midpoint_error(), 1e-5);
  EXPECT_LE(b.midpoint_error(), 1e-9);
  EXPECT_GE(HarmonicRecord::predicted_memory(sums, fine), b.memory_bytes() / 2);
}

TEST(HarmonicRecord, RefusesBadInputAndTooMuchMemory) {
  HarmonicSums sums = sea_like_sums(1);
  HarmonicRecordOptions options;
  options.duration = 100.0;
  options.memory_limit = 1000;
  EXPECT_THROW(HarmonicRecord::build(sums, options), std::length_error);
  options.memory_limit = std::size_t{1} << 30;
  options.duration = std::nan("");
  EXPECT_THROW(HarmonicRecord::build(sums, options), std::invalid_argument);
  options.duration = 100.0;
  sums.time_sign = 0;
  EXPECT_THROW(HarmonicRecord::build(sums, options), std::invalid_argument);
  sums.time_sign = 1;
  sums.coefficients[1].pop_back();
  EXPECT_THROW(HarmonicRecord::build(sums, options), std::invalid_argument);
  sums.coefficients.clear();
  EXPECT_THROW(HarmonicRecord::build(sums, options), std::invalid_argument);
}

}  // namespace
