// A∞ from a table without it: Kramers–Kronig and the high-frequency end (see the header).
#include "hydro/infinite_frequency.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hydro/retardation.hpp"

namespace ffrf::hydro {

namespace {

// x ln|x|, continued by 0 at x = 0.
double x_log_abs(double x) { return x == 0.0 ? 0.0 : x * std::log(std::abs(x)); }

// PV∫₀^∞ B(ν)/(ν² − ω²) dν for B piecewise linear on the nodes (0 outside them), ω > 0.
double principal_value(const DampingModel& b, double omega) {
  const auto& nu = b.omega;
  const auto& v = b.value;
  const std::size_t last = nu.size() - 1;
  const auto slope = [&](std::size_t k) { return (v[k + 1] - v[k]) / (nu[k + 1] - nu[k]); };  // segment k → k+1
  double sum = 0.0;
  for (std::size_t k = 0; k <= last; ++k) {
    const double left = k > 0 ? slope(k - 1) : 0.0, right = k < last ? slope(k) : 0.0;
    // Coefficients of ln|ν_k − ω| and ln(ν_k + ω): the difference of the two segments' lines,
    // B_s(±ω), taken at the node; at an end node the outside is B = 0 (a jump of v[k]).
    const double jump = (k == 0 ? -v[k] : 0.0) + (k == last ? v[k] : 0.0);
    const double d = left - right;
    // (d(ω − ν_k) + jump) ln|ν_k − ω|: written as x ln|x| so that a node at ω contributes its limit 0.
    sum += d * x_log_abs(omega - nu[k]) + (jump != 0.0 && nu[k] != omega ? jump * std::log(std::abs(nu[k] - omega)) : 0.0);
    sum -= (d * (-omega - nu[k]) + jump) * std::log(nu[k] + omega);
  }
  return sum / (2.0 * omega);
}

double median(std::vector<double> values) {
  const std::size_t n = values.size();
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n / 2), values.end());
  const double upper = values[n / 2];
  if (n % 2 == 1) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n / 2)));
}

}  // namespace

std::string to_string(InfiniteFrequencyMethod method) {
  return method == InfiniteFrequencyMethod::kramers_kronig ? "kramers-kronig" : "high-frequency";
}

std::vector<PlanarMatrix> kramers_kronig_estimates(const PlanarRadiation& r) {
  const std::size_t n = r.frequency.size();
  if (n < 3 || r.added_mass.size() != n || r.damping.size() != n)
    throw std::invalid_argument(fmt::format("Kramers–Kronig A∞ of {}: {} frequencies, {} added-mass and {} damping matrices; "
                                            "valid: equal counts, at least 3", r.source, n, r.added_mass.size(), r.damping.size()));
  std::vector<PlanarMatrix> estimates(n - 1);
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      const DampingModel b = damping_model(r, i, j);
      for (std::size_t k = 0; k + 1 < n; ++k) {
        const double omega = r.frequency[k];
        if (!(omega > 0.0)) {
          estimates[k](i, j) = std::nan("");  // no relation at ω = 0: left out of the median
          continue;
        }
        estimates[k](i, j) = r.added_mass[k](i, j) - 2.0 / std::numbers::pi * principal_value(b, omega);
      }
    }
  if (r.frequency.front() == 0.0) estimates.erase(estimates.begin());
  return estimates;
}

InfiniteFrequencyEstimate estimate_infinite_frequency_added_mass(const PlanarRadiation& r, InfiniteFrequencyMethod method,
                                                                 int points) {
  const std::vector<PlanarMatrix> per_frequency = kramers_kronig_estimates(r);
  InfiniteFrequencyEstimate e;
  e.method = method;
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      std::vector<double> values;
      for (const PlanarMatrix& m : per_frequency) values.push_back(m(i, j));
      e.kramers_kronig(i, j) = median(values);
    }
  // A = A∞ + c x with x = 1/ω², least squares over the last samples.
  const std::size_t n = r.frequency.size();
  const std::size_t m = std::min<std::size_t>(n, static_cast<std::size_t>(std::max(points, 2)));
  e.high_frequency_points = static_cast<int>(m);
  double sx = 0.0, sxx = 0.0;
  for (std::size_t k = n - m; k < n; ++k) {
    const double x = 1.0 / (r.frequency[k] * r.frequency[k]);
    sx += x;
    sxx += x * x;
  }
  const double count = static_cast<double>(m), determinant = count * sxx - sx * sx;
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      double sy = 0.0, sxy = 0.0;
      for (std::size_t k = n - m; k < n; ++k) {
        const double x = 1.0 / (r.frequency[k] * r.frequency[k]);
        sy += r.added_mass[k](i, j);
        sxy += x * r.added_mass[k](i, j);
      }
      e.high_frequency(i, j) = (sxx * sy - sx * sxy) / determinant;
    }
  e.added_mass = method == InfiniteFrequencyMethod::kramers_kronig ? e.kramers_kronig : e.high_frequency;
  return e;
}

PlanarRadiation with_infinite_frequency(PlanarRadiation radiation, const InfiniteFrequencyEstimate& estimate) {
  radiation.has_infinite_frequency = true;
  radiation.infinite_frequency_added_mass = estimate.added_mass;
  return radiation;
}

}  // namespace ffrf::hydro
