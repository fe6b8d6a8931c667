// Regular linear (Airy) wave: dispersion relation, C¹ ramp, elevation and total incident pressure
// (hydrostatic + linear dynamic part, hydrostatic extension up to the crest). See airy_wave.hpp
// and docs/theory.md §6.
#include "coupling/airy_wave.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ffrf::coupling {

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

}  // namespace

double AiryWave::wave_number_from_dispersion(double omega, double d, double g) {
  if (!(omega >= 0.0) || !std::isfinite(omega))
    throw std::invalid_argument("AiryWave: angular frequency must be finite and >= 0, got " + std::to_string(omega));
  if (!(d > 0.0)) throw std::invalid_argument("AiryWave: depth must be > 0 (+inf = deep), got " + std::to_string(d));
  if (!(g > 0.0) || !std::isfinite(g))
    throw std::invalid_argument("AiryWave: gravity must be finite and > 0, got " + std::to_string(g));
  const double deep = omega * omega / g;
  if (std::isinf(d)) return deep;
  return solve_x_tanh_x(deep * d) / d;
}

AiryWave AiryWave::from_height_period(double height, double period, double direction, double ramp_periods,
                                      double depth, double gravity) {
  if (!(height >= 0.0) || !std::isfinite(height))
    throw std::invalid_argument("AiryWave: height must be finite and >= 0, got " + std::to_string(height));
  if (!(period > 0.0) || !std::isfinite(period))
    throw std::invalid_argument("AiryWave: period must be finite and > 0, got " + std::to_string(period));
  if (direction != 1.0 && direction != -1.0)
    throw std::invalid_argument("AiryWave: direction must be +1 or -1, got " + std::to_string(direction));
  if (!(ramp_periods >= 0.0) || !std::isfinite(ramp_periods))
    throw std::invalid_argument("AiryWave: ramp periods must be finite and >= 0, got " + std::to_string(ramp_periods));
  AiryWave wave;
  wave.amplitude = 0.5 * height;
  wave.angular_frequency = 2.0 * std::numbers::pi / period;
  wave.wave_number = wave_number_from_dispersion(wave.angular_frequency, depth, gravity);
  wave.direction = direction;
  wave.ramp_duration = ramp_periods * period;
  wave.depth = depth;
  wave.gravity = gravity;
  return wave;
}

double AiryWave::ramp(double t) const {
  if (!(ramp_duration > 0.0) || t >= ramp_duration) return 1.0;
  if (t <= 0.0) return 0.0;
  return 0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp_duration));
}

double AiryWave::elevation(double x, double t) const {
  return amplitude * ramp(t) * std::cos(wave_number * x - direction * angular_frequency * t);
}

double AiryWave::depth_attenuation(double y) const {
  if (std::isinf(depth)) return std::exp(wave_number * y);
  // cosh(k(y + d)) / cosh(k d) written without overflow for large k d.
  return std::exp(wave_number * y) * (1.0 + std::exp(-2.0 * wave_number * (y + depth))) /
         (1.0 + std::exp(-2.0 * wave_number * depth));
}

double AiryWave::pressure(double x, double y, double t, double density) const {
  const double zeta = elevation(x, t);
  if (y > zeta) return 0.0;                                  // dry (above the crest or in a trough)
  if (y >= 0.0) return density * gravity * (zeta - y);       // hydrostatic extension to the crest
  return density * gravity * (zeta * depth_attenuation(y) - y);  // linear Airy + hydrostatic
}

double AiryWave::wavelength() const {
  return wave_number > 0.0 ? 2.0 * std::numbers::pi / wave_number : std::numeric_limits<double>::infinity();
}

double AiryWave::period() const {
  return angular_frequency > 0.0 ? 2.0 * std::numbers::pi / angular_frequency
                                 : std::numeric_limits<double>::infinity();
}

}  // namespace ffrf::coupling
