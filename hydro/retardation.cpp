// Retardation function from tabulated radiation damping (see retardation.hpp).
#include "hydro/retardation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hydro/linear_fourier.hpp"

namespace ffrf::hydro {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTailRatio = 1.01;
constexpr double kTailRemainder = 1e-9;
static_assert(sizeof(PlanarMatrix) == 9 * sizeof(double), "PlanarMatrix must be 9 packed doubles");

DampingModel damping_curve(const PlanarRadiation& r, int i, int j, const RetardationOptions& o, double noise_floor) {
  DampingModel c;
  if (r.frequency.front() > 0.0) {
    c.omega.push_back(0.0);
    c.value.push_back(0.0);
  }
  for (std::size_t k = 0; k < r.frequency.size(); ++k) {
    c.omega.push_back(r.frequency[k]);
    c.value.push_back(r.damping[k](i, j));
  }
  if (!o.high_frequency_tail) return c;
  const std::size_t n = r.frequency.size(), p = static_cast<std::size_t>(std::clamp(o.tail_points, 2, static_cast<int>(n)));
  const double last = r.damping[n - 1](i, j);
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = n - p; k < n; ++k) {
    const double b = r.damping[k](i, j);
    if (!(std::abs(b) > noise_floor) || (b > 0) != (last > 0)) return c;  // noise or a sign change: no tail
    const double x = std::log(r.frequency[k]), y = std::log(std::abs(b));
    sx += x; sy += y; sxx += x * x; sxy += x * y;
  }
  const auto count = static_cast<double>(p);
  const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
  const double exponent = std::clamp(-slope, 2.0, 12.0);
  double integral = 0.0;
  for (std::size_t k = 1; k < c.omega.size(); ++k) integral += 0.5 * (c.value[k] + c.value[k - 1]) * (c.omega[k] - c.omega[k - 1]);
  const double w_n = r.frequency[n - 1];
  const double tail_total = last * w_n / (exponent - 1.0);  // ∫_{ω_N}^∞ B_N (ω_N/ω)^n dω
  // Ω: remaining tail B_N ω_N^n Ω^(1−n) / (n − 1) ≤ 1e-9 (|∫B| + |tail|).
  const double limit = w_n * std::pow(kTailRemainder * (std::abs(integral) + std::abs(tail_total)) / std::abs(tail_total), 1.0 / (1.0 - exponent));
  for (double w = w_n * kTailRatio; w < limit * kTailRatio; w *= kTailRatio) {
    c.omega.push_back(w);
    c.value.push_back(last * std::pow(w_n / w, exponent));
  }
  c.tail_exponent = exponent;
  c.tail_share = tail_total / (integral + tail_total);
  return c;
}

void check(const PlanarRadiation& r, const RetardationOptions& o) {
  if (r.frequency.size() < 2 || r.damping.size() != r.frequency.size())
    throw std::invalid_argument(fmt::format("retardation function: {} frequencies and {} damping matrices; valid: equal, at least 2",
                                            r.frequency.size(), r.damping.size()));
  if (!(o.time_step > 0.0) || !std::isfinite(o.time_step))
    throw std::invalid_argument(fmt::format("retardation function: time step {} s; valid range > 0", o.time_step));
  if (!(o.truncation_time >= 0.0) || !std::isfinite(o.truncation_time))
    throw std::invalid_argument(fmt::format("retardation function: truncation time {} s; valid range >= 0 (0 = automatic)", o.truncation_time));
  if (!(o.truncation_tolerance > 0.0 && o.truncation_tolerance < 1.0))
    throw std::invalid_argument(fmt::format("retardation function: truncation tolerance {}; valid range (0, 1)", o.truncation_tolerance));
  if (!r.has_infinite_frequency)
    throw std::invalid_argument(fmt::format(
        "retardation function: {} has no infinite-frequency added mass; the Cummins equation needs A(inf)",
        r.source.empty() ? "the coefficient set" : r.source));
}

double noise_floor(const PlanarRadiation& r) {
  double largest = 0.0;
  for (const auto& b : r.damping) largest = std::max(largest, b.diagonal().cwiseAbs().maxCoeff());
  return 1e-9 * largest;
}

double entry_scale(const std::vector<PlanarMatrix>& kernel, int i, int j) {
  double ii = 0.0, jj = 0.0;
  for (const auto& k : kernel) {
    ii = std::max(ii, std::abs(k(i, i)));
    jj = std::max(jj, std::abs(k(j, j)));
  }
  return std::sqrt(ii * jj);
}

std::complex<double> kernel_transform(const RetardationFunction& kernel, int i, int j, double omega) {
  std::vector<double> t(kernel.kernel.size());
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<double>(k) * kernel.time_step;
  return linear_fourier_integral(t.data(), kernel.kernel.front().data() + i + 3 * j, t.size(), omega, 9);
}

}  // namespace

DampingModel damping_model(const PlanarRadiation& radiation, int i, int j, const RetardationOptions& options) {
  if (radiation.frequency.size() < 2 || radiation.damping.size() != radiation.frequency.size())
    throw std::invalid_argument(fmt::format("damping model: {} frequencies and {} damping matrices; valid: equal, at least 2",
                                            radiation.frequency.size(), radiation.damping.size()));
  return damping_curve(radiation, i, j, options, noise_floor(radiation));
}

RetardationFunction retardation_function(const PlanarRadiation& radiation, const RetardationOptions& options) {
  check(radiation, options);
  RetardationFunction result;
  result.time_step = options.time_step;
  result.infinite_frequency_added_mass = radiation.infinite_frequency_added_mass;
  const double horizon = options.truncation_time > 0.0 ? options.truncation_time : options.max_time;
  const auto samples = static_cast<std::size_t>(std::ceil(horizon / options.time_step - 1e-9)) + 1;
  result.kernel.assign(samples, PlanarMatrix::Zero());
  const double floor = noise_floor(radiation);
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      const DampingModel c = damping_curve(radiation, i, j, options, floor);
      result.tail_exponent(i, j) = c.tail_exponent;
      result.tail_share(i, j) = c.tail_share;
      if (std::all_of(c.value.begin(), c.value.end(), [](double v) { return v == 0.0; })) continue;
      for (std::size_t k = 0; k < samples; ++k) {
        const double t = static_cast<double>(k) * options.time_step;
        result.kernel[k](i, j) = 2.0 / kPi * linear_fourier_integral(c.omega.data(), c.value.data(), c.omega.size(), t).real();
      }
    }
  // Truncation: the last sample after which every scaled entry stays below the tolerance.
  std::size_t last = 0;
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      const double scale = entry_scale(result.kernel, i, j);
      if (scale == 0.0) continue;
      for (std::size_t k = samples; k-- > 0;)
        if (std::abs(result.kernel[k](i, j)) > options.truncation_tolerance * scale) {
          last = std::max(last, k + 1);
          break;
        }
    }
  if (options.truncation_time == 0.0) {
    last = std::min(std::max<std::size_t>(last, 1), samples - 1);
    for (int i = 0; i < kPlanarDofs; ++i)
      for (int j = 0; j < kPlanarDofs; ++j) {
        const double scale = entry_scale(result.kernel, i, j);
        for (std::size_t k = last; k < samples && scale > 0.0; ++k)
          result.truncated_peak = std::max(result.truncated_peak, std::abs(result.kernel[k](i, j)) / scale);
      }
    result.kernel.resize(last + 1);
  }
  result.truncation_time = static_cast<double>(result.kernel.size() - 1) * options.time_step;
  return result;
}

PlanarMatrix retardation_at(const PlanarRadiation& radiation, double t, const RetardationOptions& options) {
  check(radiation, options);
  PlanarMatrix k = PlanarMatrix::Zero();
  const double floor = noise_floor(radiation);
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      const DampingModel c = damping_curve(radiation, i, j, options, floor);
      k(i, j) = 2.0 / kPi * linear_fourier_integral(c.omega.data(), c.value.data(), c.omega.size(), t).real();
    }
  return k;
}

PlanarMatrix damping_from_kernel(const RetardationFunction& kernel, double omega) {
  PlanarMatrix b;
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) b(i, j) = kernel_transform(kernel, i, j, omega).real();
  return b;
}

PlanarMatrix added_mass_from_kernel(const RetardationFunction& kernel, double omega) {
  if (!(omega > 0.0)) throw std::invalid_argument(fmt::format("added_mass_from_kernel: omega = {} rad/s; valid range > 0", omega));
  PlanarMatrix a;
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j)
      a(i, j) = kernel.infinite_frequency_added_mass(i, j) - kernel_transform(kernel, i, j, omega).imag() / omega;
  return a;
}

std::vector<PlanarMatrix> infinite_frequency_estimates(const PlanarRadiation& radiation, const RetardationFunction& kernel) {
  std::vector<PlanarMatrix> estimates;
  for (std::size_t k = 0; k < radiation.frequency.size(); ++k) {
    const double omega = radiation.frequency[k];
    estimates.push_back(radiation.added_mass[k] + kernel.infinite_frequency_added_mass - added_mass_from_kernel(kernel, omega));
  }
  return estimates;
}

}  // namespace ffrf::hydro
