// Most probable maxima by Rayleigh, Weibull and Gumbel models; tension amplification (see extreme_values.hpp).
#include "hydro/extreme_values.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "hydro/record_statistics.hpp"

namespace ffrf::hydro {

namespace {
// Root of an increasing-then-decreasing sign change of f on [lo, hi] by bisection (f(lo) > 0 > f(hi)).
template <class F>
double bisect(F&& f, double lo, double hi) {
  for (int it = 0; it < 200 && hi - lo > 1e-14 * std::max(1.0, std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
}  // namespace

double rayleigh_most_probable_maximum(double sigma, double cycles) {
  if (!(sigma >= 0.0) || !(cycles >= 1.0))
    throw std::invalid_argument(fmt::format("Rayleigh MPM: sigma {} (valid >= 0), cycles {} (valid >= 1)", sigma, cycles));
  // d/dy ln[N y e^{−y²/2} (1 − e^{−y²/2})^{N−1}] = 1/y − y + (N − 1) y / (e^{y²/2} − 1) = 0, y = x/σ.
  auto slope = [&](double y) { return 1.0 / y - y + (cycles - 1.0) * y / std::expm1(0.5 * y * y); };
  return sigma * bisect(slope, 1e-6, std::sqrt(2.0 * std::log(cycles)) + 10.0);
}

double rayleigh_most_probable_maximum_asymptotic(double sigma, double cycles) { return sigma * std::sqrt(2.0 * std::log(cycles)); }

double WeibullFit::exceeded_once_in(double count) const { return scale * std::pow(std::log(count), 1.0 / shape); }

WeibullFit fit_weibull(const std::vector<double>& samples) {
  std::vector<double> x;
  for (double v : samples)
    if (v > 0.0 && std::isfinite(v)) x.push_back(v);
  if (x.size() < 10) throw std::invalid_argument(fmt::format("Weibull fit: {} positive samples; valid: at least 10", x.size()));
  const double top = *std::max_element(x.begin(), x.end());
  for (auto& v : x) v /= top;  // scale-free: α is rescaled at the end
  const auto n = static_cast<double>(x.size());
  double mean_log = 0.0;
  for (double v : x) mean_log += std::log(v) / n;
  // Likelihood equation for β: Σ x^β ln x / Σ x^β − 1/β − mean ln x = 0, increasing in β.
  auto equation = [&](double beta) {
    double s = 0.0, sl = 0.0;
    for (double v : x) {
      const double p = std::pow(v, beta);
      s += p;
      sl += p * std::log(v);
    }
    return -(sl / s - 1.0 / beta - mean_log);  // decreasing for bisect's sign convention
  };
  const double beta = bisect(equation, 0.05, 50.0);
  double s = 0.0;
  for (double v : x) s += std::pow(v, beta);
  return {top * std::pow(s / n, 1.0 / beta), beta};
}

GumbelFit fit_gumbel(const std::vector<double>& samples) {
  if (samples.size() < 5) throw std::invalid_argument(fmt::format("Gumbel fit: {} samples; valid: at least 5", samples.size()));
  const auto n = static_cast<double>(samples.size());
  const double mean = std::accumulate(samples.begin(), samples.end(), 0.0) / n;
  double var = 0.0;
  for (double v : samples) var += (v - mean) * (v - mean) / (n - 1.0);
  if (!(var > 0.0)) throw std::invalid_argument("Gumbel fit: all samples are equal");
  // Likelihood equation β = mean − Σ x e^{−x/β} / Σ e^{−x/β} (x about the mean for stability).
  auto equation = [&](double beta) {
    double s = 0.0, sx = 0.0;
    for (double v : samples) {
      const double e = std::exp(-(v - mean) / beta);
      s += e;
      sx += (v - mean) * e;
    }
    return -(sx / s) - beta;  // positive for small β, negative for large
  };
  const double moments = std::sqrt(6.0 * var) / std::numbers::pi;
  const double beta = bisect(equation, 1e-3 * moments, 20.0 * moments);
  double s = 0.0;
  for (double v : samples) s += std::exp(-(v - mean) / beta) / n;
  return {mean - beta * std::log(s), beta};
}

ExtremeEstimates most_probable_maxima(const std::vector<double>& record, double dt, std::size_t blocks) {
  if (blocks < 5) throw std::invalid_argument(fmt::format("most probable maxima: {} Gumbel blocks; valid: at least 5", blocks));
  const RecordStatistics stats = record_statistics(record, dt);
  if (stats.waves < 10) throw std::invalid_argument(fmt::format("most probable maxima: {} zero up-crossing waves; valid: at least 10", stats.waves));
  ExtremeEstimates e;
  e.cycles = static_cast<double>(stats.waves);
  e.observed = stats.maximum - stats.mean;
  e.rayleigh = rayleigh_most_probable_maximum(stats.standard_deviation, e.cycles);
  e.weibull_fit = fit_weibull(stats.crests);
  e.weibull = e.weibull_fit.exceeded_once_in(e.cycles);
  std::vector<double> maxima;
  const std::size_t length = record.size() / blocks;
  for (std::size_t b = 0; b < blocks; ++b) {
    const auto first = record.begin() + static_cast<std::ptrdiff_t>(b * length);
    maxima.push_back(*std::max_element(first, first + static_cast<std::ptrdiff_t>(length)) - stats.mean);
  }
  e.gumbel_fit = fit_gumbel(maxima);
  e.gumbel = e.gumbel_fit.mode_of_maximum_of(static_cast<double>(blocks));
  return e;
}

TensionAmplification tension_amplification(const std::vector<double>& tension, double dt, double static_tension) {
  if (!(static_tension > 0.0) || !std::isfinite(static_tension))
    throw std::invalid_argument(fmt::format("tension amplification: static tension {} N; valid range > 0", static_tension));
  const RecordStatistics stats = record_statistics(tension, dt);
  TensionAmplification t;
  t.static_tension = static_tension;
  t.maximum_factor = stats.maximum / static_tension;
  t.minimum_factor = stats.minimum / static_tension;
  const double cycles = std::max(1.0, static_cast<double>(stats.waves));
  t.most_probable_factor = (stats.mean + rayleigh_most_probable_maximum(stats.standard_deviation, cycles)) / static_tension;
  const auto slack = std::count_if(tension.begin(), tension.end(), [](double v) { return v <= 0.0; });
  t.slack_fraction = static_cast<double>(slack) / static_cast<double>(tension.size());
  return t;
}

}  // namespace ffrf::hydro
