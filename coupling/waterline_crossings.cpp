// Roots of g(s) = y(s) − ζ(x(s), t) on a straight edge: monotone/root-free interval isolation from
// local curvature bounds (the curvature at an interval's ends plus the field's third-derivative bound
// times the half-width), then safeguarded Newton (see waterline_crossings.hpp).
#include "coupling/waterline_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ffrf::coupling {

namespace {

// Newton stops once its step is below 1e-9 in s ∈ [0, 1]: convergence is quadratic there, so the
// returned iterate is good to round-off (the step it would take next is ~1e-18).
constexpr double root_tolerance = 1e-9;
constexpr double bracket_tolerance = 1e-15;  // bisection alone (Newton left the bracket) stops here
constexpr double smallest_interval = 1e-13;
constexpr int max_newton_iterations = 100;

// g(s) and g'(s) along the edge.
struct SurfaceGap {
  const WaveField& wave;
  double t, ramp;
  Eigen::Vector2d a, d;

  // g, g' = dg/ds and g'' = d²g/ds² (one sine and cosine per component for all three).
  void evaluate(double s, double& g, double& slope, double& curvature) const {
    const double x = a.x() + s * d.x();
    const double direction = wave.direction();
    double zeta = 0.0, zeta_x = 0.0, zeta_xx = 0.0;
    for (const WaveComponent& c : wave.components()) {
      const double theta = c.wave_number * x - direction * c.angular_frequency * t + c.phase;
      const double cosine = c.amplitude * std::cos(theta);
      zeta += cosine;
      zeta_x -= c.amplitude * c.wave_number * std::sin(theta);
      zeta_xx -= cosine * c.wave_number * c.wave_number;
    }
    g = a.y() + s * d.y() - ramp * zeta;
    slope = d.y() - d.x() * ramp * zeta_x;
    curvature = -d.x() * d.x() * ramp * zeta_xx;
  }
  void evaluate(double s, double& g, double& slope) const {
    double curvature = 0.0;
    evaluate(s, g, slope, curvature);
  }
};

// The one root of a monotone g in [lo, hi] where wet (g < 0) changes: Newton from the chord's root,
// kept inside the bracket.
double polish_root(const SurfaceGap& gap, double lo, double hi, double g_lo, double g_hi) {
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

// An interval with g, g' and g'' at both ends.
struct Interval {
  double lo, hi, g_lo, g_hi, slope_lo, slope_hi, curvature_lo, curvature_hi;
};

constexpr int max_samples = 256;  // start intervals per edge (an edge up to 256/k_max long)

// The edge cut into `count` equal intervals with g, g', g'' at their ends. Component i's phase
// advances by k_i d_x / count from one sample to the next, so e^{iθ} is carried along by one complex
// multiplication per sample (two sines and cosines per component instead of one per sample).
void sample_edge(const SurfaceGap& gap, int count, std::array<Interval, max_samples>& out) {
  std::array<double, max_samples + 1> zeta{}, zeta_x{}, zeta_xx{};
  const double h = 1.0 / count;
  const double direction = gap.wave.direction();
  for (const WaveComponent& c : gap.wave.components()) {
    const double theta = c.wave_number * gap.a.x() - direction * c.angular_frequency * gap.t + c.phase;
    double cosine = std::cos(theta), sine = std::sin(theta);
    const double step = c.wave_number * gap.d.x() * h;
    const double step_cosine = std::cos(step), step_sine = std::sin(step);
    const double a = c.amplitude, ak = a * c.wave_number, akk = ak * c.wave_number;
    for (int j = 0; j <= count; ++j) {
      const auto k = static_cast<std::size_t>(j);
      zeta[k] += a * cosine;
      zeta_x[k] -= ak * sine;
      zeta_xx[k] -= akk * cosine;
      // e^{i(θ + step)} = e^{iθ} e^{i step}, written out (std::complex's product checks for inf/NaN).
      const double next_cosine = cosine * step_cosine - sine * step_sine;
      sine = sine * step_cosine + cosine * step_sine;
      cosine = next_cosine;
    }
  }
  double g_prev = 0.0, slope_prev = 0.0, curvature_prev = 0.0;
  for (int j = 0; j <= count; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const double s = j * h;
    const double g = gap.a.y() + s * gap.d.y() - gap.ramp * zeta[k];
    const double slope = gap.d.y() - gap.d.x() * gap.ramp * zeta_x[k];
    const double curvature = -gap.d.x() * gap.d.x() * gap.ramp * zeta_xx[k];
    if (j > 0) out[k - 1] = {(j - 1) * h, j == count ? 1.0 : s, g_prev, g, slope_prev, slope, curvature_prev, curvature};
    g_prev = g;
    slope_prev = slope;
    curvature_prev = curvature;
  }
}

}  // namespace

WaterlineCrossings waterline_crossings(const WaveField& wave, double t, const Eigen::Vector2d& start,
                                       const Eigen::Vector2d& direction) {
  const SurfaceGap gap{wave, t, wave.ramp(t), start, direction};
  WaterlineCrossings out;
  const double dx = std::abs(direction.x());
  const double max_slope = std::abs(direction.y()) + dx * wave.slope_bound(t);
  const double max_curvature = dx * dx * wave.curvature_bound(t);
  const double max_third = dx * dx * dx * wave.third_derivative_bound(t);

  // Start intervals about 1/k_max long along x (a sixth of the shortest wavelength): there the local
  // bound is already close to the surface's true curvature, and most intervals are settled at once.
  const int count = std::clamp(static_cast<int>(std::ceil(dx * wave.max_wave_number())), 1, max_samples);
  std::array<Interval, max_samples> first;
  if (count > 1) {
    sample_edge(gap, count, first);
  } else {
    first[0] = {0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    gap.evaluate(0.0, first[0].g_lo, first[0].slope_lo, first[0].curvature_lo);
    gap.evaluate(1.0, first[0].g_hi, first[0].slope_hi, first[0].curvature_hi);
  }
  out.wet_at_start = first[0].g_lo < 0.0;

  for (int piece = 0; piece < count && !out.truncated; ++piece) {
    // Depth-first, left half first, so the roots come out in increasing s. Each split replaces one
    // interval by two, so the stack never holds more than one interval per halving level plus one.
    std::array<Interval, 64> stack;
    int size = 0;
    stack[size++] = first[static_cast<std::size_t>(piece)];
    while (size > 0) {
      const Interval iv = stack[--size];
      const bool changes = (iv.g_lo < 0.0) != (iv.g_hi < 0.0);
      const double width = iv.hi - iv.lo;
      // |g''| on the interval: every point lies within width/2 of an end, so |g''| is at most the
      // larger end value plus width/2 times the field's bound on |g'''|, and never above the global bound.
      const double end_curvature = std::max(std::abs(iv.curvature_lo), std::abs(iv.curvature_hi));
      const double curvature = std::min(max_curvature, end_curvature + 0.5 * width * max_third);
      if (!changes) {
        // Root-free: g stays within curvature · width²/8 of its chord, or within width · max|g'| of
        // its ends (the field's slope bound).
        const double nearest = std::min(std::abs(iv.g_lo), std::abs(iv.g_hi));
        if (nearest > 0.125 * curvature * width * width) continue;
        if (std::abs(iv.g_lo) + std::abs(iv.g_hi) > width * max_slope) continue;
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
        out.s[static_cast<std::size_t>(out.count++)] = polish_root(gap, iv.lo, iv.hi, iv.g_lo, iv.g_hi);
        continue;
      }
      const double mid = 0.5 * (iv.lo + iv.hi);
      double g_mid = 0.0, slope_mid = 0.0, curvature_mid = 0.0;
      gap.evaluate(mid, g_mid, slope_mid, curvature_mid);
      stack[size++] = {mid, iv.hi, g_mid, iv.g_hi, slope_mid, iv.slope_hi, curvature_mid, iv.curvature_hi};
      stack[size++] = {iv.lo, mid, iv.g_lo, g_mid, iv.slope_lo, slope_mid, iv.curvature_lo, curvature_mid};
    }
  }
  return out;
}

}  // namespace ffrf::coupling
