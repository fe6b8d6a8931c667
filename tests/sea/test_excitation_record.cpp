// The recorded BEM excitation (sea/excitation_record.hpp) against BemExcitation::at, the sum taken
// component by component with a sine and cosine each (independent of the FFT and the interpolation):
// the WAMIT barge of tests/hydro/data (barge.3, Froude–Krylov + diffraction, the BEM origin 3 m forward
// of G1 as in cases/irregular_bem_barge_crane.toml) in a 3-hour JONSWAP sea from hydro::synthesize
// (Hs 2 m, Tp 8 s, 3 376 components on ω = n · 2π/3 h). Over the whole record the error stays within
// the measured bound and the bound within the tolerance; outside it the record is the exact sum; off a
// harmonic grid, with another wave's excitation and above the memory limit it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "sea/bem_excitation.hpp"
#include "sea/excitation_record.hpp"
#include "hydro/wamit_reader.hpp"
#include "jonswap_test_sea.hpp"

namespace excitation_record_test {

using namespace ffrf;
using sea::BemExcitation;
using sea::ExcitationRecord;
using sea::ExcitationRecordOptions;
using sea::WaveField;

constexpr double three_hours = 10800.0;
const double deep = std::numeric_limits<double>::infinity();
const Eigen::Vector2d origin_offset(3.0, 0.0);  // the BEM origin amidships, G1 3 m aft of it
constexpr double origin_x = 3.0;                // G1 at x = 0

const hydro::PlanarExcitation& barge_table() {
  static const hydro::PlanarExcitation table =
      hydro::read_wamit_excitation(std::string(FFRF_SOURCE_DIR "/tests/hydro/data/barge.3"), {1.0, 1025.0, 9.81});
  return table;
}

BemExcitation barge_excitation(const WaveField& wave) {
  return sea::bem_excitation(barge_table(), wave, origin_x, origin_offset);
}

ExcitationRecordOptions options_for(const BemExcitation& excitation, double duration) {
  ExcitationRecordOptions options;
  options.duration = duration;
  options.tolerance = sea::excitation_tolerance(excitation);
  return options;
}

TEST(ExcitationRecord, IsTheExactExcitationWithinItsMeasuredBoundOverAThreeHourRecord) {
  const WaveField wave = test_support::jonswap_test_sea(three_hours, deep, 1);
  ASSERT_TRUE(wave.harmonic_grid().active);
  ASSERT_EQ(wave.components().size(), 3376u);
  const BemExcitation excitation = barge_excitation(wave);
  const ExcitationRecordOptions options = options_for(excitation, three_hours);
  const Eigen::Vector3d sigma = sea::excitation_standard_deviation(excitation);
  ASSERT_GT(sigma.minCoeff(), 1e4);  // every channel carries force: the comparison is not of zeros

  const auto outcome = ExcitationRecord::build(excitation, wave, options);
  ASSERT_TRUE(outcome.record) << outcome.refusal;
  const ExcitationRecord& record = *outcome.record;
  EXPECT_GE(record.duration(), three_hours);
  EXPECT_GT(record.midpoint_error_fraction(), 0.0);
  EXPECT_LE(record.midpoint_error_fraction(), 1.0);
  for (int c = 0; c < 3; ++c) EXPECT_LE(record.midpoint_error()(c), options.tolerance(c)) << "channel " << c;
  // Three real channels, two to a complex channel, each with its value and two time derivatives
  // (quintic Hermite); the record is the sea's whole period (three hours), read periodically.
  EXPECT_EQ(record.memory_bytes(), 2 * 3 * record.samples() * sizeof(std::complex<double>));
  EXPECT_NEAR(record.time_step() * static_cast<double>(record.samples() - 1), three_hours, 1e-9 * three_hours);
  EXPECT_EQ(record.duration(), INFINITY);

  // Random times over the whole record, and the midpoints of the first and last segments.
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> time(0.0, three_hours);
  std::vector<double> times{0.0, 0.5 * record.time_step(), three_hours, three_hours - 0.5 * record.time_step(),
                            1.5 * three_hours + 0.3 * record.time_step(), 2.0 * three_hours - 0.5 * record.time_step()};
  for (int n = 0; n < 12000; ++n) times.push_back(time(random));
  Eigen::Vector3d largest = Eigen::Vector3d::Zero(), largest_force = Eigen::Vector3d::Zero();
  for (const double t : times) {
    const Eigen::Vector3d exact = excitation.at(t);
    largest = largest.cwiseMax((record.at(t) - exact).cwiseAbs());
    largest_force = largest_force.cwiseMax(exact.cwiseAbs());
  }
  for (int c = 0; c < 3; ++c) {
    // The Hermite error τ²(1 − τ)² s⁗ Δt⁴/24 peaks at the midpoint; s⁗ changes little over one segment.
    EXPECT_LE(largest(c), 1.2 * record.midpoint_error()(c)) << "channel " << c;
    EXPECT_GT(largest_force(c), 2.0 * sigma(c)) << "channel " << c;  // a force of a sea's size was compared
  }
}

TEST(ExcitationRecord, HoldsEachChannelToItsOwnTolerance) {
  const WaveField wave = test_support::jonswap_test_sea(1200.0, deep, 3);
  const BemExcitation excitation = barge_excitation(wave);
  ExcitationRecordOptions options = options_for(excitation, 1200.0);
  options.tolerance(2) *= 1e-3;  // pitch a thousand times tighter than its share
  const auto tight = ExcitationRecord::build(excitation, wave, options);
  const auto even = ExcitationRecord::build(excitation, wave, options_for(excitation, 1200.0));
  ASSERT_TRUE(tight.record) << tight.refusal;
  ASSERT_TRUE(even.record) << even.refusal;
  EXPECT_GT(tight.record->samples(), even.record->samples());
  std::mt19937_64 random(9);
  std::uniform_real_distribution<double> time(0.0, 1200.0);
  double largest_pitch = 0.0;
  for (int n = 0; n < 3000; ++n) {
    const double t = time(random);
    largest_pitch = std::max(largest_pitch, std::abs(tight.record->at(t)(2) - excitation.at(t)(2)));
  }
  EXPECT_LE(largest_pitch, 1.2 * tight.record->midpoint_error()(2));
  EXPECT_LE(tight.record->midpoint_error()(2), options.tolerance(2));
}

TEST(ExcitationRecord, IsTheExactSumOutsideTheRecord) {
  const WaveField wave = test_support::jonswap_test_sea(1200.0, deep, 2);
  const BemExcitation excitation = barge_excitation(wave);
  const auto outcome = ExcitationRecord::build(excitation, wave, options_for(excitation, 600.0));
  ASSERT_TRUE(outcome.record) << outcome.refusal;
  for (const double t : {-3.0, -1e-9, outcome.record->duration() + 1e-6, 900.0}) {
    EXPECT_EQ(outcome.record->at(t), excitation.at(t)) << "t = " << t;
  }
}

TEST(ExcitationRecord, RefusesComponentsOffAHarmonicGrid) {
  const WaveField on_grid = test_support::jonswap_test_sea(1200.0, deep, 4);
  std::vector<sea::ComponentSpec> specs;
  for (const sea::WaveComponent& c : on_grid.components()) specs.push_back({c.angular_frequency, c.amplitude, c.phase});
  specs[10].angular_frequency *= 1.0 + 1e-9;  // one component off the grid
  const WaveField off_grid = WaveField::from_components(specs, 1.0, 0.0, deep, 9.81);
  ASSERT_FALSE(off_grid.harmonic_grid().active);
  const BemExcitation excitation = barge_excitation(off_grid);
  const auto outcome = ExcitationRecord::build(excitation, off_grid, options_for(excitation, 600.0));
  EXPECT_FALSE(outcome.record);
  EXPECT_NE(outcome.refusal.find("harmonic grid"), std::string::npos) << outcome.refusal;
}

TEST(ExcitationRecord, RefusesAnExcitationThatIsNotTheWavesGrid) {
  const WaveField wave = test_support::jonswap_test_sea(1200.0, deep, 4);
  const BemExcitation own = barge_excitation(wave);
  const ExcitationRecordOptions options = options_for(own, 600.0);
  // Another record length: another grid and component count.
  const BemExcitation other_sea = barge_excitation(test_support::jonswap_test_sea(1800.0, deep, 4));
  const auto from_other_sea = ExcitationRecord::build(other_sea, wave, options);
  EXPECT_FALSE(from_other_sea.record);
  EXPECT_NE(from_other_sea.refusal.find("components"), std::string::npos) << from_other_sea.refusal;
  // The same count, one frequency moved by far more than rounding.
  BemExcitation moved = own;
  moved.frequency[17] *= 1.0 + 1e-10;
  const auto from_moved = ExcitationRecord::build(moved, wave, options);
  EXPECT_FALSE(from_moved.record);
  EXPECT_NE(from_moved.refusal.find("component 17"), std::string::npos) << from_moved.refusal;
  EXPECT_TRUE(ExcitationRecord::build(own, wave, options).record);
}

TEST(ExcitationRecord, RefusesARecordAboveTheMemoryLimit) {
  const WaveField wave = test_support::jonswap_test_sea(1200.0, deep, 6);
  const BemExcitation excitation = barge_excitation(wave);
  ExcitationRecordOptions options = options_for(excitation, 1200.0);
  const auto unlimited = ExcitationRecord::build(excitation, wave, options);
  ASSERT_TRUE(unlimited.record) << unlimited.refusal;
  const std::size_t bytes = unlimited.record->memory_bytes();
  options.memory_limit = bytes;  // exactly enough
  EXPECT_TRUE(ExcitationRecord::build(excitation, wave, options).record);
  options.memory_limit = bytes - 1;
  const auto refused = ExcitationRecord::build(excitation, wave, options);
  EXPECT_FALSE(refused.record);
  EXPECT_NE(refused.refusal.find("limit"), std::string::npos) << refused.refusal;
}

TEST(ExcitationRecord, RejectsBadOptions) {
  const WaveField wave = test_support::jonswap_test_sea(1200.0, deep, 8);
  const BemExcitation excitation = barge_excitation(wave);
  ExcitationRecordOptions options = options_for(excitation, 600.0);
  options.tolerance(1) = 0.0;  // heave carries force: it needs a tolerance
  EXPECT_THROW(ExcitationRecord::build(excitation, wave, options), std::invalid_argument);
  options = options_for(excitation, std::nan(""));
  EXPECT_THROW(ExcitationRecord::build(excitation, wave, options), std::invalid_argument);
  BemExcitation short_phases = excitation;
  short_phases.phase.pop_back();
  EXPECT_THROW(ExcitationRecord::build(short_phases, wave, options_for(excitation, 600.0)), std::invalid_argument);
  EXPECT_THROW(sea::excitation_tolerance(excitation, 0.0), std::invalid_argument);
}

}  // namespace excitation_record_test
