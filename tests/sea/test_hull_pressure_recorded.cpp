// The hull load with the sea read from a record (hull_pressure_recorded.hpp) against the same load
// with the sea summed component by component (hull_pressure.hpp, an independent evaluation of the
// same integral): the reference crane's 3-hour JONSWAP sea, poses over the motion range the record
// covers, times over the whole record. Forces within 1e-6 of the buoyancy, moments within 1e-6 of
// buoyancy × hull length; no fallback inside the range; the fallbacks the record must take.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sea/hull_pressure.hpp"
#include "sea/hull_pressure_recorded.hpp"
#include "sea/incident_wave_record.hpp"
#include "jonswap_test_sea.hpp"

namespace hull_pressure_recorded_test {

using namespace ffrf::sea;
using Eigen::Vector2d;
constexpr double water_density = 1025.0, gravity = 9.81;
const BoxHullSection reference_hull{-32.0, 58.0, -6.0, 2.0, 40.0};  // the reference hull (docs/architecture.md)
constexpr double level_g1_height = 1.9;  // G1 6 m above the keel at a 4.1 m draft

struct RecordedSea {
  WaveField wave;
  IncidentWaveRecord record;
};

RecordedSea recorded_sea(double duration, const HullMotionRange& range) {
  WaveField wave = ffrf::test_support::jonswap_test_sea(10800.0, std::numeric_limits<double>::infinity(), 1);
  IncidentWaveRecordOptions options;
  options.duration = duration;
  box_hull_x_range(reference_hull, level_g1_height, range, options.x_min, options.x_max);
  std::string why;
  auto record = IncidentWaveRecord::build(wave, box_hull_patches(reference_hull, level_g1_height, range), options, &why);
  if (!record) throw std::runtime_error(why);
  return {std::move(wave), std::move(*record)};
}

TEST(HullPressureRecorded, AgreesWithTheComponentSumsOverAThreeHourRecord) {
  const HullMotionRange range;
  const RecordedSea sea = recorded_sea(10800.0, range);
  const IncidentWaveRecordStats& stats = sea.record.stats();
  std::printf("record: %zu samples of %.4g s, degree %zu, radius %.2f m, truncation %.2g m, interpolation %.2g m, "
              "elevation bound %.3f m, slope bound %.3f, %.1f MB, %.2f s\n", stats.samples, stats.time_step, stats.degree,
              sea.record.patches()[0].radius, stats.truncation_bound, stats.interpolation_error, stats.elevation_bound,
              stats.slope_bound, stats.memory_bytes / 1e6, stats.build_seconds);
  EXPECT_EQ(stats.components, sea.wave.components().size());
  EXPECT_LE(stats.truncation_bound + stats.interpolation_error, 1e-6);
  EXPECT_GT(stats.elevation_bound, 1.0);  // a 3-hour Hs 2 m sea has crests above 1 m
  EXPECT_LT(stats.elevation_bound, 4.0);
  const double buoyancy = water_density * gravity * 90.0 * 40.0 * 4.1;
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> time(0.0, 10800.0), unit(-1.0, 1.0);
  WavePolynomials workspace;
  double force_error = 0.0, moment_error = 0.0, largest_force = 0.0;
  int fallbacks = 0;
  for (int sample = 0; sample < 600; ++sample) {
    // Half the samples at the motions a lift sees (heave ±0.5 m, pitch ±0.02 rad): the record must
    // answer every one; the other half over the whole range the patches cover (deck awash, keel in
    // the troughs' reach, keel out of the water between its corners): answered too.
    const bool moderate = sample % 2 == 0;
    const double t = time(random);
    const Vector2d g1(range.surge * unit(random), level_g1_height + (moderate ? 0.5 : range.heave) * unit(random));
    const double pitch = (moderate ? 0.02 : range.pitch) * unit(random);
    const HullLoad exact = hull_pressure_load(reference_hull, &sea.wave, water_density, gravity, g1, pitch, t);
    const auto recorded = recorded_hull_pressure_load(reference_hull, sea.record, sea.wave, workspace, sea.wave.ramp(t), water_density,
                                                      gravity, g1, pitch, t);
    if (!recorded) {
      ASSERT_FALSE(moderate) << "fallback at t = " << t << " pose " << g1.transpose() << " " << pitch;
      ++fallbacks;
      continue;
    }
    force_error = std::max(force_error, (recorded->force - exact.force).norm());
    moment_error = std::max(moment_error, std::abs(recorded->moment - exact.moment));
    largest_force = std::max(largest_force, (exact.force - Vector2d(0.0, buoyancy)).norm());
    EXPECT_NEAR(recorded->wetted_length, exact.wetted_length, 1e-6 * 200.0);
  }
  EXPECT_EQ(fallbacks, 0);  // a keel out of the water takes G and H from the sums at its crossings alone
  EXPECT_LE(force_error, 1e-6 * buoyancy);
  EXPECT_LE(moment_error, 1e-6 * buoyancy * 90.0);
  EXPECT_GT(largest_force, 1e-3 * buoyancy);  // the sea does load the hull: the comparison is not of zeros
  std::printf("recorded vs exact over 3 h: force %.3g N (%.2g of buoyancy), moment %.3g N m; %d fallbacks of 300 "
              "at the range's edges\n", force_error, force_error / buoyancy, moment_error, fallbacks);
}

// The record along still water (Chebyshev series) against ζ, ∂ζ/∂x, ∂²ζ/∂x² summed by the wave
// field, and its antiderivative against ∫ζ dx by Gauss–Legendre on the exact ζ.
TEST(HullPressureRecorded, RecordsTheElevationAlongTheWholeHull) {
  const HullMotionRange range;
  const RecordedSea sea = recorded_sea(1200.0, range);
  const IncidentWaveRecordStats& stats = sea.record.stats();
  EXPECT_GT(stats.line_degree, 10u);
  EXPECT_LE(stats.line_truncation_bound, 0.25e-6 + 1e-12);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> time(0.0, 1200.0), place(sea.record.x_min(), sea.record.x_max());
  WavePolynomials workspace;
  double elevation_error = 0.0, slope_error = 0.0, curvature_error = 0.0, integral_error = 0.0;
  for (int sample = 0; sample < 200; ++sample) {
    const double t = time(random), x = place(random), x2 = place(random);
    sea.record.at(t, 1.0, workspace);
    double zeta = 0.0, slope = 0.0, curvature = 0.0;
    sea.record.line_elevation(workspace, x, zeta, slope, curvature);
    elevation_error = std::max(elevation_error, std::abs(zeta - sea.wave.elevation(x, t)));
    slope_error = std::max(slope_error, std::abs(slope - sea.wave.elevation_slope(x, t)));
    const double h = 1e-3;  // the exact curvature by central differences of the exact slope
    const double exact_curvature = (sea.wave.elevation_slope(x + h, t) - sea.wave.elevation_slope(x - h, t)) / (2.0 * h);
    curvature_error = std::max(curvature_error, std::abs(curvature - exact_curvature));
    double first = 0.0, second = 0.0, first2 = 0.0, second2 = 0.0;
    sea.record.line_antiderivatives(workspace, x, first, second);
    sea.record.line_antiderivatives(workspace, x2, first2, second2);
    // ∫ from x to x2 of the exact ζ: 40 panels of 8-point Gauss–Legendre (λ_min ≈ 11 m).
    double exact = 0.0;
    const int panels = 40;
    const double width = (x2 - x) / panels;
    static const double node[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    static const double weight[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    for (int p = 0; p < panels; ++p) {
      const double centre = x + (p + 0.5) * width;
      for (int q = 0; q < 4; ++q)
        for (const double sign : {-1.0, 1.0}) exact += 0.5 * width * weight[q] * sea.wave.elevation(centre + sign * 0.5 * width * node[q], t);
    }
    integral_error = std::max(integral_error, std::abs((first2 - first) - exact));
  }
  EXPECT_LE(elevation_error, 1e-6);
  EXPECT_LE(slope_error, 1e-5);
  EXPECT_LE(curvature_error, 1e-4);
  EXPECT_LE(integral_error, 1e-4);  // over up to 110 m: 1e-6 m per metre
  std::printf("line record (degree %zu): elevation %.2g m, slope %.2g, curvature %.2g 1/m, integral %.2g m²\n",
              stats.line_degree, elevation_error, slope_error, curvature_error, integral_error);
}

TEST(HullPressureRecorded, FallsBackWhereTheRecordCannotAnswer) {
  const HullMotionRange range{2.0, 1.0, 0.02};
  const RecordedSea sea = recorded_sea(600.0, range);
  WavePolynomials workspace;
  const auto load = [&](double x, double pitch, double t) {
    return recorded_hull_pressure_load(reference_hull, sea.record, sea.wave, workspace, sea.wave.ramp(t), water_density, gravity,
                                       Vector2d(x, level_g1_height), pitch, t);
  };
  EXPECT_TRUE(load(0.0, 0.0, 300.0).has_value());
  EXPECT_FALSE(load(30.0, 0.0, 300.0).has_value());   // surged out of the patches
  EXPECT_FALSE(load(0.0, 0.0, 700.0).has_value());    // after the record
  EXPECT_FALSE(load(0.0, 0.0, -1.0).has_value());     // before it
  // Pitched far beyond the discs: the corners' G and H come from the component sums, and the load
  // still agrees with the exact one.
  const auto pitched = load(0.0, 0.3, 300.0);
  ASSERT_TRUE(pitched.has_value());
  const HullLoad exact = hull_pressure_load(reference_hull, &sea.wave, water_density, gravity,
                                            Vector2d(0.0, level_g1_height), 0.3, 300.0);
  const double buoyancy = water_density * gravity * 90.0 * 40.0 * 4.1;
  EXPECT_LE((pitched->force - exact.force).norm(), 1e-6 * buoyancy);
  EXPECT_LE(std::abs(pitched->moment - exact.moment), 1e-6 * buoyancy * 90.0);
}

TEST(HullPressureRecorded, RefusesWhatItCannotRecord) {
  const HullMotionRange range;
  IncidentWaveRecordOptions options;
  options.duration = 100.0;
  box_hull_x_range(reference_hull, level_g1_height, range, options.x_min, options.x_max);
  const auto patches = box_hull_patches(reference_hull, level_g1_height, range);
  std::string why;
  const WaveField finite_depth = ffrf::test_support::jonswap_test_sea(1200.0, 40.0, 1);
  EXPECT_FALSE(IncidentWaveRecord::build(finite_depth, patches, options, &why).has_value());
  EXPECT_NE(why.find("depth"), std::string::npos) << why;
  const WaveField regular = WaveField::regular(1.0, 10.0, 1.0, 2.0, std::numeric_limits<double>::infinity(), gravity);
  EXPECT_FALSE(IncidentWaveRecord::build(regular, patches, options, &why).has_value());
  EXPECT_NE(why.find("harmonic"), std::string::npos) << why;
  const WaveField sea = ffrf::test_support::jonswap_test_sea(10800.0, std::numeric_limits<double>::infinity(), 1);
  options.memory_limit = 1 << 20;
  EXPECT_THROW(IncidentWaveRecord::build(sea, patches, options), std::length_error);
  options.memory_limit = std::size_t{1} << 32;
  options.tolerance = -1.0;
  EXPECT_THROW(IncidentWaveRecord::build(sea, patches, options), std::invalid_argument);
}

}  // namespace hull_pressure_recorded_test
