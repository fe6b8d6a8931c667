// Waterline crossings with local curvature bounds (sea/waterline_crossings.hpp) on random
// irregular seas, against two references independent of the local bound: the search with the wave
// field's global bounds only (tests/sea/waterline_crossings_global_bounds.hpp, the code before
// the local bounds; rigorous, slow for many components) and sign changes on a dense grid refined by
// bisection. Seas: the reference crane's JONSWAP sea (Hs 2 m, Tp 8 s) on Δω = 2π/record over [ωp/2, 3ωp]
// with random phases (jonswap_test_sea.hpp), 20-minute and 3-hour records (376 and 3 376 components),
// deep water (sums by the harmonic-grid recurrence, sea/component_phasors.hpp) and 30 m depth
// (direct sums); the recurrence's phasors against the direct formula up to a 3-hour sea's last
// component; edges: the reference hull's box (90 m × 8 m) at random heave, pitch and time, and a
// nearly level edge at the still-water line (many crossings).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "sea/component_phasors.hpp"
#include "sea/waterline_crossings.hpp"
#include "sea/wave_field.hpp"
#include "jonswap_test_sea.hpp"
#include "waterline_crossings_global_bounds.hpp"

namespace waterline_crossings_test {

using Eigen::Vector2d;
using ffrf::sea::ComponentSpec;
using ffrf::sea::WaterlineCrossings;
using ffrf::sea::WaveField;

constexpr double g = 9.81;

WaveField jonswap_sea(double record, double depth, unsigned seed) {
  return ffrf::test_support::jonswap_test_sea(record, depth, seed);
}

struct Edge {
  Vector2d a, d;
};

// The four edges of the 90 m × 8 m box (G1 6 m above the keel, 13 m aft of mid-length) at heave y,
// pitch θ, counter-clockwise like sea/hull_pressure.cpp, plus a nearly level edge at still water.
std::vector<Edge> hull_edges(double heave, double pitch) {
  const double c = std::cos(pitch), s = std::sin(pitch);
  const auto place = [&](double x, double y) { return Vector2d(c * x - s * y, 1.91 + heave + s * x + c * y); };
  const std::vector<Vector2d> corner = {place(-32.0, -6.0), place(58.0, -6.0), place(58.0, 2.0), place(-32.0, 2.0)};
  std::vector<Edge> edges;
  for (std::size_t e = 0; e < corner.size(); ++e) edges.push_back({corner[e], corner[(e + 1) % corner.size()] - corner[e]});
  edges.push_back({Vector2d(-40.0, 0.02 * heave), Vector2d(90.0, 0.01)});
  return edges;
}

// Sign changes of y − ζ on an n-point grid, each refined by bisection to round-off.
std::vector<double> sampled_crossings(const WaveField& wave, double t, const Edge& edge, int n) {
  const auto gap = [&](double s) { return edge.a.y() + s * edge.d.y() - wave.elevation(edge.a.x() + s * edge.d.x(), t); };
  std::vector<double> roots;
  double previous = gap(0.0);
  for (int i = 1; i <= n; ++i) {
    const double s = static_cast<double>(i) / n, now = gap(s);
    if ((previous < 0.0) != (now < 0.0)) {
      double lo = static_cast<double>(i - 1) / n, hi = s;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        ((gap(mid) < 0.0) == (previous < 0.0) ? lo : hi) = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    previous = now;
  }
  return roots;
}

TEST(WaterlineCrossings, LocalBoundsFindTheSameRootsAsGlobalBoundsOnRandomSeas) {
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> heave(-1.5, 1.5), pitch(-0.03, 0.03), time(100.0, 10000.0);
  int crossings = 0, edges_with_crossings = 0;
  for (const double record : {1200.0, 10800.0}) {
    for (const double depth : {std::numeric_limits<double>::infinity(), 30.0}) {
      const WaveField wave = jonswap_sea(record, depth, static_cast<unsigned>(record + depth));
      ASSERT_EQ(wave.harmonic_grid().active, std::isinf(depth));  // deep: the recurrence; 30 m: direct sums
      for (int trial = 0; trial < 8; ++trial) {
        const double t = time(random);
        for (const Edge& edge : hull_edges(heave(random), pitch(random))) {
          const WaterlineCrossings local = ffrf::sea::waterline_crossings(wave, t, edge.a, edge.d);
          const WaterlineCrossings global = ffrf::test_support::waterline_crossings_global_bounds(wave, t, edge.a, edge.d);
          ASSERT_FALSE(local.truncated);
          ASSERT_FALSE(global.truncated);
          EXPECT_EQ(local.wet_at_start, global.wet_at_start);
          ASSERT_EQ(local.count, global.count) << "record " << record << " depth " << depth << " t " << t;
          for (int i = 0; i < local.count; ++i) {
            const auto k = static_cast<std::size_t>(i);
            EXPECT_NEAR(local.s[k], global.s[k], 1e-10);  // both polished to a 1e-9 Newton step (quadratic)
          }
          crossings += local.count;
          edges_with_crossings += local.count > 0 ? 1 : 0;
        }
      }
    }
  }
  EXPECT_GE(crossings, 150);            // the still-water edge crosses many times
  EXPECT_GE(edges_with_crossings, 64);  // and the bow and stern every time (2 of 5 edges × 32 poses)
}

TEST(WaterlineCrossings, LocalBoundsMatchDenseSamplingOnA20MinuteSea) {
  const WaveField wave = jonswap_sea(1200.0, std::numeric_limits<double>::infinity(), 7);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> heave(-1.5, 1.5), pitch(-0.03, 0.03), time(100.0, 1100.0);
  int crossings = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const double t = time(random);
    for (const Edge& edge : hull_edges(heave(random), pitch(random))) {
      const WaterlineCrossings found = ffrf::sea::waterline_crossings(wave, t, edge.a, edge.d);
      // 20 000 points: 4.5 mm on the 90 m edges, 2 400 points per shortest wavelength (11 m).
      const std::vector<double> reference = sampled_crossings(wave, t, edge, 20000);
      ASSERT_EQ(found.count, static_cast<int>(reference.size())) << t;
      for (int i = 0; i < found.count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        EXPECT_NEAR(found.s[k], reference[k], 1e-10);
      }
      EXPECT_EQ(found.wet_at_start, edge.a.y() < wave.elevation(edge.a.x(), t));
      crossings += found.count;
    }
  }
  EXPECT_GE(crossings, 15);
}

TEST(WaterlineCrossings, ThirdDerivativeBoundHoldsAndIsTheComponentSum) {
  // |∂³ζ/∂x³| = |Σ a k³ sin θ| ≤ Σ a k³: checked by central differences of the slope's slope on a grid.
  const WaveField wave = jonswap_sea(1200.0, std::numeric_limits<double>::infinity(), 3);
  double sum = 0.0;
  for (const auto& c : wave.components()) sum += c.amplitude * c.wave_number * c.wave_number * c.wave_number;
  EXPECT_DOUBLE_EQ(wave.third_derivative_bound(500.0), sum);
  const double h = 0.05;
  double largest = 0.0;
  for (double x = -50.0; x <= 50.0; x += 0.5) {
    const double third = (wave.elevation_slope(x + h, 500.0) - 2.0 * wave.elevation_slope(x, 500.0) +
                          wave.elevation_slope(x - h, 500.0)) / (h * h);
    largest = std::max(largest, std::abs(third));
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(largest, sum);
}

// Every phasor e^{k z − iδωt} of a 3-hour sea (3 376 components on the harmonic grid) by the recurrence
// against the direct formula, at the end of the record and at points that decay (keel depth), that
// only turn (the elevation) and that grow along a piece (the pressure integral's e^{λh}). Without
// re-seeding the recurrence drifts by ~j²/2 ulp after j components (3e-10 at the last one); the seeds
// keep it to round-off.
TEST(ComponentPhasors, RecurrenceMatchesTheDirectFormulaToTheLastComponentOfA3HourSea) {
  const WaveField wave = jonswap_sea(10800.0, std::numeric_limits<double>::infinity(), 5);
  ASSERT_TRUE(wave.harmonic_grid().active);
  ASSERT_EQ(wave.components().size(), 3376u);
  using ffrf::sea::Complex;
  double worst = 0.0, last = 0.0;
  for (const double t : {0.0, 4321.0, 10799.9}) {
    for (const Complex z : {Complex(0.0, 61.3), Complex(-6.2, -37.9), Complex(-0.4, 88.0), Complex(-7.9, 1.2)}) {
      ffrf::sea::ComponentPhasors phasors(wave, z, t);
      for (const auto& c : wave.components()) {
        const Complex direct = std::exp(c.wave_number * z.real()) *
                               Complex(std::cos(c.wave_number * z.imag() - c.angular_frequency * t),
                                       std::sin(c.wave_number * z.imag() - c.angular_frequency * t));
        const double error = std::abs(phasors.next() - direct) / std::abs(direct);
        worst = std::max(worst, error);
        if (&c == &wave.components().back()) last = std::max(last, error);
      }
    }
  }
  // The direct formula's own phase rounds to ~ulp(ω t) = 4e-12 rad at t = 3 h.
  EXPECT_LT(worst, 2e-11);
  EXPECT_LT(last, 2e-11);
  // Off the grid (components listed out of order) every phasor is the direct formula.
  std::vector<ComponentSpec> shuffled;
  for (const auto& c : wave.components()) shuffled.insert(shuffled.begin(), {c.angular_frequency, c.amplitude, c.phase});
  EXPECT_FALSE(WaveField::from_components(shuffled, 1.0, 0.0, std::numeric_limits<double>::infinity(), g).harmonic_grid().active);
}

}  // namespace waterline_crossings_test
