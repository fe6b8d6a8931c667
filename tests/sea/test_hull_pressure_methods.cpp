// The closed-form hull pressure integral against the second method, the sampled-and-bisected
// waterline with 8-point Gauss–Legendre quadrature ffrf used before (hull_pressure_quadrature.hpp),
// over poses that put the waterline on every edge (trimmed, heaved, deck overtopped, keel emerging,
// submerged), regular waves deep and finite depth, and an irregular sea of several components; the
// reference crane's 20-minute and 3-hour JONSWAP seas with sums by the harmonic-grid recurrence
// (sea/component_phasors.hpp) against the same seas summed component by component and against
// the quadrature; and the waterline crossings against dense sampling of y − ζ along an edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "sea/hull_pressure.hpp"
#include "sea/waterline_crossings.hpp"
#include "hull_pressure_quadrature.hpp"
#include "jonswap_test_sea.hpp"

namespace hull_pressure_methods_test {

using namespace ffrf::sea;
using Eigen::Vector2d;
constexpr double rho = 1025.0, g = 9.81;
const double deep = std::numeric_limits<double>::infinity();
const BoxHullSection hull{-32.0, 58.0, -6.0, 2.0, 40.0};  // the reference hull (docs/architecture.md)

struct Pose {
  double x, y, theta;
};
// Floating level, trimmed both ways, deck awash, keel out of the water at the stern, deep submerged.
const std::vector<Pose> poses = {{0.0, -1.9, 0.0},  {7.0, -1.5, 0.04}, {-11.0, -2.4, -0.05}, {20.0, -0.8, 0.1},
                                 {3.0, 1.0, 0.12},  {0.0, 3.5, -0.02}, {-5.0, -20.0, 0.3},   {40.0, -2.0, -0.2}};

std::vector<WaveField> waves() {
  return {WaveField::regular(1.0, 10.0, 1.0, 2.0, deep, g),  // the reference scene's wave
          WaveField::regular(3.0, 6.0, -1.0, 0.0, deep, g),  // steep, short: several crossings per edge
          WaveField::regular(2.0, 8.0, 1.0, 0.0, 30.0, g),   // finite depth
          WaveField::from_components({{0.45, 0.4, 0.3}, {0.63, 1.1, 2.0}, {0.8, 0.6, -1.0}, {1.1, 0.3, 0.5},
                                      {1.5, 0.12, 3.1}, {2.0, 0.05, -2.2}},
                                     1.0, 5.0, deep, g),  // an irregular sea, λ from 15 m to 300 m
          WaveField::from_components({{0.5, 0.9, 0.0}, {0.9, 0.5, 1.0}, {1.3, 0.25, 2.0}}, -1.0, 0.0, 25.0, g)};
}

TEST(HullPressureMethods, ClosedFormAgreesWithQuadratureToRoundOff) {
  double worst = 0.0;
  int cases = 0;
  for (const WaveField& wave : waves()) {
    for (const double t : {0.0, 3.3, 17.0, 44.4, 101.0}) {
      // 512 samples per edge so the reference resolves every crossing of the 15 m components.
      const ffrf::sea::testing::QuadratureHullPressure reference(&wave, rho, g, t, 512);
      for (const Pose& p : poses) {
        const HullLoad closed = hull_pressure_load(hull, &wave, rho, g, Vector2d(p.x, p.y), p.theta, t);
        const HullLoad quadrature = reference.load(hull, Vector2d(p.x, p.y), p.theta);
        const double scale = rho * g * hull.width * 90.0 * 8.0;  // the box's full buoyancy
        EXPECT_NEAR(closed.force.x(), quadrature.force.x(), 1e-12 * scale) << t << " " << p.theta;
        EXPECT_NEAR(closed.force.y(), quadrature.force.y(), 1e-12 * scale) << t << " " << p.theta;
        EXPECT_NEAR(closed.moment, quadrature.moment, 1e-12 * scale * 90.0) << t << " " << p.theta;
        EXPECT_NEAR(closed.wetted_length, quadrature.wetted_length, 1e-10) << t << " " << p.theta;
        worst = std::max({worst, std::abs(closed.force.x() - quadrature.force.x()) / scale,
                          std::abs(closed.force.y() - quadrature.force.y()) / scale,
                          std::abs(closed.moment - quadrature.moment) / (scale * 90.0)});
        ++cases;
      }
    }
  }
  EXPECT_EQ(cases, 5 * 5 * 8);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", worst);
  RecordProperty("worst_relative_difference", text);
}

TEST(HullPressureMethods, CalmWaterClosedFormIsExactArchimedes) {
  const ffrf::sea::testing::QuadratureHullPressure reference(nullptr, rho, g, 0.0);
  for (const Pose& p : poses) {
    const HullLoad closed = hull_pressure_load(hull, nullptr, rho, g, Vector2d(p.x, p.y), p.theta, 0.0);
    const HullLoad quadrature = reference.load(hull, Vector2d(p.x, p.y), p.theta);
    const double scale = rho * g * hull.width * 90.0 * 8.0;
    EXPECT_NEAR(closed.force.y(), quadrature.force.y(), 1e-13 * scale);
    EXPECT_NEAR(closed.moment, quadrature.moment, 1e-13 * scale * 90.0);
  }
}

// Sign changes of y − ζ on a 200 000-point grid, each refined by bisection.
std::vector<double> sampled_crossings(const WaveField& wave, double t, const Vector2d& a, const Vector2d& d) {
  const auto gap = [&](double s) { return a.y() + s * d.y() - wave.elevation(a.x() + s * d.x(), t); };
  std::vector<double> roots;
  const int n = 200000;
  double prev = gap(0.0);
  for (int i = 1; i <= n; ++i) {
    const double s = static_cast<double>(i) / n, now = gap(s);
    if ((prev < 0.0) != (now < 0.0)) {
      double lo = static_cast<double>(i - 1) / n, hi = s;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        ((gap(mid) < 0.0) == (prev < 0.0) ? lo : hi) = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    prev = now;
  }
  return roots;
}

TEST(HullPressureMethods, WaterlineCrossingsMatchDenseSampling) {
  int total = 0;
  for (const WaveField& wave : waves()) {
    for (const double t : {17.0, 44.4}) {
      // A nearly level deck at the waterline (many crossings) and a trimmed keel crossing it.
      for (const auto& [a, d] : {std::pair{Vector2d(-40.0, 0.05), Vector2d(90.0, 0.2)},
                                 std::pair{Vector2d(-40.0, -1.5), Vector2d(90.0, 3.0)},
                                 std::pair{Vector2d(10.0, -6.0), Vector2d(0.5, 8.0)}}) {
        const WaterlineCrossings found = waterline_crossings(wave, t, a, d);
        const std::vector<double> reference = sampled_crossings(wave, t, a, d);
        ASSERT_FALSE(found.truncated);
        ASSERT_EQ(found.count, static_cast<int>(reference.size())) << t;
        for (int i = 0; i < found.count; ++i) EXPECT_NEAR(found.s[static_cast<std::size_t>(i)], reference[static_cast<std::size_t>(i)], 1e-13);
        EXPECT_EQ(found.wet_at_start, a.y() < wave.elevation(a.x(), t));
        total += found.count;
      }
    }
  }
  EXPECT_GE(total, 40);  // the cases really cross the surface, many times
}

// The crane's long seas (deep: sums by recurrence; 30 m: direct, the fallback) on random poses and
// times against the same field summed by the direct formula, to 1e-10 of the box's buoyancy; and, in
// the 3-hour deep sea, against the quadrature (direct point pressures, sampled and bisected waterline).
TEST(HullPressureMethods, LongSeaRecurrenceAgreesWithDirectSumsAndQuadrature) {
  std::mt19937_64 random(31);
  std::uniform_real_distribution<double> surge(-20.0, 20.0), heave(-1.5, 1.5), pitch(-0.03, 0.03), time(60.0, 10799.0);
  const double scale = rho * g * hull.width * 90.0 * 8.0;  // the box's full buoyancy
  double worst = 0.0, worst_quadrature = 0.0;
  for (const double record : {1200.0, 10800.0}) {
    for (const double depth : {deep, 30.0}) {
      const WaveField wave = ffrf::test_support::jonswap_test_sea(record, depth, 3);
      ASSERT_EQ(wave.harmonic_grid().active, std::isinf(depth));
      const WaveField direct = wave.with_direct_sums();
      for (int trial = 0; trial < 12; ++trial) {
        const Vector2d g1(surge(random), 1.91 + heave(random));
        const double theta = pitch(random), t = trial == 0 ? 10799.9 : time(random);
        const HullLoad fast = hull_pressure_load(hull, &wave, rho, g, g1, theta, t);
        const HullLoad reference = hull_pressure_load(hull, &direct, rho, g, g1, theta, t);
        worst = std::max({worst, std::abs(fast.force.x() - reference.force.x()) / scale,
                          std::abs(fast.force.y() - reference.force.y()) / scale,
                          std::abs(fast.moment - reference.moment) / (scale * 90.0),
                          std::abs(fast.wetted_length - reference.wetted_length) / 196.0});
        if (record == 10800.0 && std::isinf(depth) && trial < 3) {
          const HullLoad quadrature = ffrf::sea::testing::QuadratureHullPressure(&wave, rho, g, t, 512).load(hull, g1, theta);
          worst_quadrature = std::max({worst_quadrature, std::abs(fast.force.x() - quadrature.force.x()) / scale,
                                       std::abs(fast.force.y() - quadrature.force.y()) / scale,
                                       std::abs(fast.moment - quadrature.moment) / (scale * 90.0)});
        }
      }
    }
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worst_quadrature, 1e-10);
  char text[64];
  std::snprintf(text, sizeof text, "%.3g / %.3g", worst, worst_quadrature);
  RecordProperty("worst_relative_difference_direct_quadrature", text);
}

}  // namespace hull_pressure_methods_test
