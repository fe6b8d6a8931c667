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

Complex direct_sum(const HarmonicSums& sums, std::size_t channel, double t, bool rate) {
  Complex total = 0.0;
  for (std::size_t i = 0; i < sums.coefficients[channel].size(); ++i) {
    const double w = static_cast<double>(sums.first_harmonic + static_cast<std::int64_t>(i)) * sums.frequency_step;
    const Complex term = sums.coefficients[channel][i] * std::polar(1.0, sums.time_sign * w * t);
    total += rate ? Complex(0.0, sums.time_sign * w) * term : term;
  }
  return total;
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
  for (const double t : {1799.3, 1800.0, 2100.7, 2499.9}) {
    Complex value[2];
    record.evaluate(t, value);
    EXPECT_NEAR(std::abs(value[1] - direct_sum(sums, 1, t, false)), 0.0, 1.2 * record.midpoint_error()) << t;
  }
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
