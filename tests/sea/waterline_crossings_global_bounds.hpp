// The waterline-crossing search as it was before the local curvature bounds (commit 7adb74e): the
// same isolation and the same Newton polish (sea/crossing_isolation.hpp), with the wave field's
// GLOBAL bounds |g'| ≤ |d_y| + |d_x| r Σ a k and |g''| ≤ d_x² r Σ a k² on every interval. Exact (the
// same roots), only slower for many components.
// Kept for tests (a second, independently bounded search to compare the roots with) and for
// bench/bench_waterline_crossings.cpp (old/new cost side by side).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "sea/waterline_crossings.hpp"
#include "sea/wave_field.hpp"

namespace ffrf::test_support {

using ffrf::sea::WaveComponent;
using ffrf::sea::WaveField;
using ffrf::sea::WaterlineCrossings;

namespace global_bounds_detail {

inline constexpr double smallest_interval = 1e-13;

// g(s) and g'(s) along the edge.
struct SurfaceGap {
  const WaveField& wave;
  double t, ramp;
  Eigen::Vector2d a, d;

  void evaluate(double s, double& g, double& slope) const {
    const double x = a.x() + s * d.x();
    const double direction = wave.direction();
    double zeta = 0.0, zeta_x = 0.0;
    for (const WaveComponent& c : wave.components()) {
      const double theta = c.wave_number * x - direction * c.angular_frequency * t + c.phase;
      zeta += c.amplitude * std::cos(theta);
      zeta_x -= c.amplitude * c.wave_number * std::sin(theta);
    }
    g = a.y() + s * d.y() - ramp * zeta;
    slope = d.y() - d.x() * ramp * zeta_x;
  }
};

// An interval with g and g' at both ends.
struct Interval {
  double lo, hi, g_lo, g_hi, slope_lo, slope_hi;
};

}  // namespace global_bounds_detail

inline WaterlineCrossings waterline_crossings_global_bounds(const WaveField& wave, double t, const Eigen::Vector2d& start,
                                                            const Eigen::Vector2d& direction) {
  using namespace global_bounds_detail;
  const SurfaceGap gap{wave, t, wave.ramp(t), start, direction};
  WaterlineCrossings out;
  Interval whole{0.0, 1.0, 0.0, 0.0, 0.0, 0.0};
  gap.evaluate(0.0, whole.g_lo, whole.slope_lo);
  gap.evaluate(1.0, whole.g_hi, whole.slope_hi);
  out.wet_at_start = whole.g_lo < 0.0;
  const double max_slope = std::abs(direction.y()) + std::abs(direction.x()) * wave.slope_bound(t);
  const double max_curvature = direction.x() * direction.x() * wave.curvature_bound(t);

  // Depth-first, left half first, so the roots come out in increasing s. Each split replaces one
  // interval by two, so the stack never holds more than one interval per halving level plus one.
  std::array<Interval, 64> stack;
  int size = 0;
  stack[size++] = whole;
  while (size > 0) {
    const Interval iv = stack[--size];
    const bool changes = (iv.g_lo < 0.0) != (iv.g_hi < 0.0);
    const double width = iv.hi - iv.lo;
    if (!changes && std::abs(iv.g_lo) + std::abs(iv.g_hi) > width * max_slope) continue;  // root-free
    // g' cannot change sign on the interval if it is larger than max|g''| · width at either end.
    const double reach = width * max_curvature;
    const bool monotone = std::abs(iv.slope_lo) > reach || std::abs(iv.slope_hi) > reach;
    if (monotone || width <= smallest_interval || size + 2 > static_cast<int>(stack.size())) {
      if (!changes) continue;  // monotone without a sign change (or an unresolved tangency): no root
      if (out.count == WaterlineCrossings::max_crossings) {
        out.truncated = true;
        break;
      }
      out.s[static_cast<std::size_t>(out.count++)] = sea::polish_crossing(gap, iv.lo, iv.hi, iv.g_lo, iv.g_hi);
      continue;
    }
    const double mid = 0.5 * (iv.lo + iv.hi);
    double g_mid = 0.0, slope_mid = 0.0;
    gap.evaluate(mid, g_mid, slope_mid);
    stack[size++] = {mid, iv.hi, g_mid, iv.g_hi, slope_mid, iv.slope_hi};
    stack[size++] = {iv.lo, mid, iv.g_lo, g_mid, iv.slope_lo, slope_mid};
  }
  return out;
}

}  // namespace ffrf::test_support
