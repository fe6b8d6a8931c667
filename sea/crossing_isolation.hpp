// The roots of g(s) = y(s) − ζ(x(s)) on a straight edge, s ∈ [0, 1], found without sampling: start
// intervals (with g, g', g'' at their ends) are cut until each is monotone (|g'| at an end > width ·
// max|g''|) or provably root-free (g keeps its sign and min|g(ends)| > max|g''| · width²/8, the
// chord's error bound; or |g(l)| + |g(r)| > width · max|g'|), with max|g''| on an interval bounded
// locally: the larger |g''| at its ends plus width/2 · max|g'''| (capped by the global max|g''|).
// Each monotone interval with a sign change holds exactly one root, found by Newton's method kept
// inside the bracket (bisection when a step leaves it) until its step is below 1e-9. The surface
// comes from the caller (`Gap`: evaluate(s, g, g', g'') and evaluate(s, g, g')): the component sums
// of a wave field (sea/waterline_crossings.cpp) or a record of the sea
// (sea/hull_pressure_recorded.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace ffrf::sea {

// Up to max_crossings roots in increasing s; wet_at_start tells whether r(0) is below the surface
// (y < ζ, strictly). A tangency (g touching zero without changing sign) is no crossing.
struct WaterlineCrossings {
  static constexpr int max_crossings = 64;
  std::array<double, max_crossings> s{};
  int count = 0;
  bool wet_at_start = false;
  bool truncated = false;  // more crossings than max_crossings: the later ones are missing
};

// An interval with g, g' and g'' at both ends.
struct CrossingInterval {
  double lo, hi, g_lo, g_hi, slope_lo, slope_hi, curvature_lo, curvature_hi;
};

// An edge is cut into start intervals about 2/k_max long along x (k_max the sea's largest wave
// number), at most this many (an edge up to 512/k_max long): the exact and the recorded sea alike.
inline constexpr int kMaxStartIntervals = 256;

// The start intervals of an edge spanning `dx` along x under a sea whose largest wave number is k_max.
inline int start_interval_count(double dx, double max_wave_number) {
  return std::clamp(static_cast<int>(std::ceil(0.5 * dx * max_wave_number)), 1, kMaxStartIntervals);
}

// Bounds over the edge of |g'|, |g''| and |g'''| (the field's bounds times the edge's components).
struct CrossingBounds {
  double slope = 0.0, curvature = 0.0, third = 0.0;
};

namespace crossing_detail {
constexpr double root_tolerance = 1e-9;      // Newton's step in s ∈ [0, 1]: quadratic convergence, round-off next
constexpr double bracket_tolerance = 1e-15;  // bisection alone (Newton left the bracket) stops here
constexpr double smallest_interval = 1e-13;
constexpr int max_newton_iterations = 100;
}  // namespace crossing_detail

// The one root of a monotone g in [lo, hi] where wet (g < 0) changes: Newton from the chord's root,
// kept inside the bracket.
template <class Gap>
double polish_crossing(const Gap& gap, double lo, double hi, double g_lo, double g_hi) {
  using namespace crossing_detail;
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

// The crossings in the `count` start intervals `first` (in order, covering [0, 1]), appended to `out`.
template <class Gap>
void isolate_crossings(const Gap& gap, const CrossingInterval* first, int count, const CrossingBounds& bounds,
                       WaterlineCrossings& out) {
  using namespace crossing_detail;
  for (int piece = 0; piece < count && !out.truncated; ++piece) {
    // Depth-first, left half first, so the roots come out in increasing s. Each split replaces one
    // interval by two, so the stack never holds more than one interval per halving level plus one.
    std::array<CrossingInterval, 64> stack;
    int size = 0;
    stack[size++] = first[piece];
    while (size > 0) {
      const CrossingInterval iv = stack[--size];
      const bool changes = (iv.g_lo < 0.0) != (iv.g_hi < 0.0);
      const double width = iv.hi - iv.lo;
      // |g''| on the interval: every point lies within width/2 of an end, so |g''| is at most the
      // larger end value plus width/2 times the bound on |g'''|, and never above the global bound.
      const double end_curvature = std::max(std::abs(iv.curvature_lo), std::abs(iv.curvature_hi));
      const double curvature = std::min(bounds.curvature, end_curvature + 0.5 * width * bounds.third);
      if (!changes) {
        // Root-free: g stays within curvature · width²/8 of its chord, or within width · max|g'| of its ends.
        const double nearest = std::min(std::abs(iv.g_lo), std::abs(iv.g_hi));
        if (nearest > 0.125 * curvature * width * width) continue;
        if (std::abs(iv.g_lo) + std::abs(iv.g_hi) > width * bounds.slope) continue;
      }
      // g' cannot change sign on the interval if it is larger than max|g''| · width at either end.
      const double reach = width * curvature;
      const bool monotone = std::abs(iv.slope_lo) > reach || std::abs(iv.slope_hi) > reach;
      if (monotone || width <= smallest_interval || size + 2 > static_cast<int>(stack.size())) {
        if (!changes) continue;  // monotone without a sign change (or an unresolved tangency): no root
        if (out.count == WaterlineCrossings::max_crossings) {
          out.truncated = true;
          break;
        }
        out.s[static_cast<std::size_t>(out.count++)] = polish_crossing(gap, iv.lo, iv.hi, iv.g_lo, iv.g_hi);
        continue;
      }
      const double mid = 0.5 * (iv.lo + iv.hi);
      double g_mid = 0.0, slope_mid = 0.0, curvature_mid = 0.0;
      gap.evaluate(mid, g_mid, slope_mid, curvature_mid);
      stack[size++] = {mid, iv.hi, g_mid, iv.g_hi, slope_mid, iv.slope_hi, curvature_mid, iv.curvature_hi};
      stack[size++] = {iv.lo, mid, iv.g_lo, g_mid, iv.slope_lo, slope_mid, iv.curvature_lo, curvature_mid};
    }
  }
}

}  // namespace ffrf::sea
