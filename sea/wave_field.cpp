// Superposed linear (Airy) wave components: dispersion relation, C¹ ramp, elevation, total incident
// pressure (hydrostatic extension up to the crest) and particle kinematics. See wave_field.hpp and
// docs/theory.md §6.
#include "sea/wave_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ffrf::sea {

namespace {

// Solves x tanh x = ν (x = k d, ν = ω² d / g) by Newton's method safeguarded by a bracket:
// tanh x < 1 and tanh x ≤ x give x ≥ max(ν, √ν); tanh increasing then gives x ≤ ν / tanh(x_lo).
double solve_x_tanh_x(double nu) {
  if (nu == 0.0) return 0.0;
  double lo = std::max(nu, std::sqrt(nu));
  double hi = nu / std::tanh(lo);
  if (!(hi > lo)) return lo;  // tanh(lo) rounds to 1: the root is ν to machine precision
  double x = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double th = std::tanh(x);
    const double h = x * th - nu;
    if (h == 0.0) return x;
    (h > 0.0 ? hi : lo) = x;
    const double dh = th + x * (1.0 - th * th);
    double next = x - h / dh;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(next - x) <= 2.0 * std::numeric_limits<double>::epsilon() * x) return next;
    x = next;
  }
  return x;
}

void check_environment(double direction, double depth, double gravity) {
  if (direction != 1.0 && direction != -1.0)
    throw std::invalid_argument("WaveField: direction must be +1 or -1, got " + std::to_string(direction));
  if (!(depth > 0.0)) throw std::invalid_argument("WaveField: depth must be > 0 (+inf = deep), got " + std::to_string(depth));
  if (!(gravity > 0.0) || !std::isfinite(gravity))
    throw std::invalid_argument("WaveField: gravity must be finite and > 0, got " + std::to_string(gravity));
}

// ω_i = (n0 + i) Δω to 4 ulp for every i (N ≥ 2, deep water only: there k_i is quadratic in n).
WaveField::HarmonicGrid detect_harmonic_grid(const std::vector<WaveComponent>& components, double depth, double gravity) {
  WaveField::HarmonicGrid grid;
  const std::size_t count = components.size();
  if (count < 2 || !std::isinf(depth)) return grid;
  const double first = components.front().angular_frequency, last = components.back().angular_frequency;
  const double guess = (last - first) / static_cast<double>(count - 1);
  if (!(guess > 0.0)) return grid;
  const double n0 = std::round(first / guess);
  if (!(n0 >= 0.0) || n0 > 1e7) return grid;  // (2n + 1) stays exact in the recurrence
  const double step = last / (n0 + static_cast<double>(count - 1));
  for (std::size_t i = 0; i < count; ++i) {
    const double omega = components[i].angular_frequency, on_grid = (n0 + static_cast<double>(i)) * step;
    if (!(std::abs(omega - on_grid) <= 4.0 * std::numeric_limits<double>::epsilon() * omega)) return grid;
  }
  return {true, n0, step, step * step / gravity};
}

}  // namespace

double WaveField::wave_number_from_dispersion(double omega, double d, double g) {
  if (!(omega >= 0.0) || !std::isfinite(omega))
    throw std::invalid_argument("WaveField: angular frequency must be finite and >= 0, got " + std::to_string(omega));
  if (!(d > 0.0)) throw std::invalid_argument("WaveField: depth must be > 0 (+inf = deep), got " + std::to_string(d));
  if (!(g > 0.0) || !std::isfinite(g))
    throw std::invalid_argument("WaveField: gravity must be finite and > 0, got " + std::to_string(g));
  const double deep = omega * omega / g;
  if (std::isinf(d)) return deep;
  return solve_x_tanh_x(deep * d) / d;
}

WaveField WaveField::from_components(const std::vector<ComponentSpec>& components, double direction,
                                     double ramp_duration, double depth, double gravity) {
  check_environment(direction, depth, gravity);
  if (!std::isfinite(ramp_duration))
    throw std::invalid_argument("WaveField: ramp duration must be finite, got " + std::to_string(ramp_duration));
  WaveField field;
  field.direction_ = direction;
  field.ramp_duration_ = ramp_duration;
  field.depth_ = depth;
  field.gravity_ = gravity;
  field.components_.reserve(components.size());
  field.complex_amplitudes_.reserve(components.size());
  for (std::size_t i = 0; i < components.size(); ++i) {
    const ComponentSpec& c = components[i];
    const std::string which = "WaveField: component " + std::to_string(i) + ": ";
    if (!(c.amplitude >= 0.0) || !std::isfinite(c.amplitude))
      throw std::invalid_argument(which + "amplitude must be finite and >= 0, got " + std::to_string(c.amplitude));
    if (!(c.angular_frequency >= 0.0) || !std::isfinite(c.angular_frequency))
      throw std::invalid_argument(which + "angular frequency must be finite and >= 0, got " + std::to_string(c.angular_frequency));
    if (!std::isfinite(c.phase)) throw std::invalid_argument(which + "phase must be finite, got " + std::to_string(c.phase));
    const double k = wave_number_from_dispersion(c.angular_frequency, depth, gravity);
    field.components_.push_back({c.amplitude, c.angular_frequency, k, c.phase});
    field.complex_amplitudes_.push_back(std::polar(c.amplitude, c.phase));
    field.amplitude_sum_ += c.amplitude;
    field.slope_sum_ += c.amplitude * k;
    field.curvature_sum_ += c.amplitude * k * k;
    field.third_derivative_sum_ += c.amplitude * k * k * k;
    if (c.amplitude > 0.0) field.max_wave_number_ = std::max(field.max_wave_number_, k);
  }
  field.harmonic_grid_ = detect_harmonic_grid(field.components_, depth, gravity);
  return field;
}

WaveField WaveField::regular(double height, double period, double direction, double ramp_periods, double depth,
                             double gravity) {
  if (!(height >= 0.0) || !std::isfinite(height))
    throw std::invalid_argument("WaveField: height must be finite and >= 0, got " + std::to_string(height));
  if (!(period > 0.0) || !std::isfinite(period))
    throw std::invalid_argument("WaveField: period must be finite and > 0, got " + std::to_string(period));
  if (!(ramp_periods >= 0.0) || !std::isfinite(ramp_periods))
    throw std::invalid_argument("WaveField: ramp periods must be finite and >= 0, got " + std::to_string(ramp_periods));
  return from_components({{2.0 * std::numbers::pi / period, 0.5 * height, 0.0}}, direction, ramp_periods * period,
                         depth, gravity);
}

double WaveField::ramp(double t) const {
  if (!(ramp_duration_ > 0.0) || t >= ramp_duration_) return 1.0;
  if (t <= 0.0) return 0.0;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp_duration_));
}

double WaveField::elevation(double x, double t) const {
  double sum = 0.0;
  for (const WaveComponent& c : components_) {
    sum += c.amplitude * std::cos(c.wave_number * x - direction_ * c.angular_frequency * t + c.phase);
  }
  return ramp(t) * sum;
}

double WaveField::elevation_slope(double x, double t) const {
  double sum = 0.0;
  for (const WaveComponent& c : components_) {
    sum -= c.amplitude * c.wave_number * std::sin(c.wave_number * x - direction_ * c.angular_frequency * t + c.phase);
  }
  return ramp(t) * sum;
}

double WaveField::depth_attenuation(const WaveComponent& c, double y) const {
  const double k = c.wave_number;
  if (deep()) return std::exp(k * y);
  // cosh(k(y + d)) / cosh(k d) written without overflow for large k d.
  return std::exp(k * y) * (1.0 + std::exp(-2.0 * k * (y + depth_))) / (1.0 + std::exp(-2.0 * k * depth_));
}

double WaveField::pressure(double x, double y, double t, double density) const {
  const double zeta = elevation(x, t);
  if (y > zeta) return 0.0;                              // dry (above the crest or in a trough)
  if (y >= 0.0) return density * gravity_ * (zeta - y);  // hydrostatic extension to the crest
  const double r = ramp(t);
  double dynamic = 0.0;
  for (const WaveComponent& c : components_) {
    dynamic += c.amplitude * std::cos(c.wave_number * x - direction_ * c.angular_frequency * t + c.phase) *
               depth_attenuation(c, y);
  }
  return density * gravity_ * (r * dynamic - y);  // linear Airy + hydrostatic
}

namespace {

// cosh(k(y + d)) / sinh(k d) and sinh(k(y + d)) / sinh(k d) for y ≤ 0 (both e^{ky} in deep water),
// written without overflow.
Eigen::Vector2d velocity_profiles(double k, double y, double depth) {
  const double decay = std::exp(k * y);
  if (std::isinf(depth)) return {decay, decay};
  const double bottom = std::exp(-2.0 * k * (y + depth)), denominator = 1.0 - std::exp(-2.0 * k * depth);
  return {decay * (1.0 + bottom) / denominator, decay * (1.0 - bottom) / denominator};
}

}  // namespace

Eigen::Vector2d WaveField::velocity(double x, double y, double t) const {
  const double depth_y = std::min(y, 0.0);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const WaveComponent& c : components_) {
    if (c.angular_frequency == 0.0) continue;  // a still component carries no motion
    const double theta = c.wave_number * x - direction_ * c.angular_frequency * t + c.phase;
    const Eigen::Vector2d profile = velocity_profiles(c.wave_number, depth_y, depth_);
    sum += c.amplitude * c.angular_frequency * Eigen::Vector2d(std::cos(theta) * profile.x(), std::sin(theta) * profile.y());
  }
  return ramp(t) * direction_ * sum;
}

Eigen::Vector2d WaveField::acceleration(double x, double y, double t) const {
  const double depth_y = std::min(y, 0.0);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const WaveComponent& c : components_) {
    if (c.angular_frequency == 0.0) continue;
    const double theta = c.wave_number * x - direction_ * c.angular_frequency * t + c.phase;
    const Eigen::Vector2d profile = velocity_profiles(c.wave_number, depth_y, depth_);
    const double scale = c.amplitude * c.angular_frequency * c.angular_frequency;
    sum += scale * Eigen::Vector2d(std::sin(theta) * profile.x(), -std::cos(theta) * profile.y());
  }
  return ramp(t) * sum;
}

}  // namespace ffrf::sea
