// The waterline-crossing search as it was before the local curvature bounds (commit 7adb74e): the
// same isolation and Newton polish, with the wave field's GLOBAL bounds |g'| ≤ |d_y| + |d_x| r Σ a k and
// |g''| ≤ d_x² r Σ a k² on every interval. Exact (the same roots), only slower for many components.
// Kept for tests (a second, independently bounded search to compare the roots with) and for
// bench/bench_waterline_crossings.cpp (old/new cost side by side).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "coupling/waterline_crossings.hpp"
#include "coupling/wave_field.hpp"

namespace ffrf::test_support {

using ffrf::coupling::WaveComponent;
using ffrf::coupling::WaveField;
using ffrf::coupling::WaterlineCrossings;

namespace global_bounds_detail {

// Newton stops once its step is below 1e-9 in s ∈ [0, 1]: convergence is quadratic there, so the
// returned iterate is good to round-off (the step it would take next is ~1e-18).
inline constexpr double root_tolerance = 1e-9;
inline constexpr double bracket_tolerance = 1e-15;  // bisection alone (Newton left the bracket) stops here
inline constexpr double smallest_interval = 1e-13;
inline constexpr int max_newton_iterations = 100;

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

// The one root of a monotone g in [lo, hi] where wet (g < 0) changes: Newton from the chord's root,
// kept inside the bracket.
inline double polish_root(const SurfaceGap& gap, double lo, double hi, double g_lo, double g_hi) {
  const bool lo_wet = g_lo < 0.0;
  double s = g_lo != g_hi ? lo + (hi - lo) * g_lo / (g_lo - g_hi) : 0.5 * (lo + hi);
  if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < max_newton_iterations; ++iteration) {
    double g = 0.0, slope = 0.0;
    gap.evaluate(s, g, slope);
    if (g == 0.0) return s;
    ((g < 0.0) == lo_wet ? lo : hi) = s;
    double next = slope != 0.0 ? s - g / slope : 0.5 * (lo + hi);
    const bool newton = next > lo && next < hi;
    if (!newton) next = 0.5 * (lo + hi);  // the step left the bracket: bisect
    if ((newton && std::abs(next - s) <= root_tolerance) || hi - lo <= bracket_tolerance) return next;
    s = next;
  }
  return s;
}

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
      out.s[static_cast<std::size_t>(out.count++)] = polish_root(gap, iv.lo, iv.hi, iv.g_lo, iv.g_hi);
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
