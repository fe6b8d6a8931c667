// Welch power spectral density with FFTW (see spectral_estimate.hpp).
#include "hydro/spectral_estimate.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include "hydro/constants.hpp"
#include "hydro/fftw_memory.hpp"
#include "hydro/harmonic_record.hpp"

namespace ffrf::hydro {

namespace {

}  // namespace

PowerSpectrum welch_spectrum(const std::vector<double>& record, double dt, const WelchOptions& options) {
  const std::size_t n = record.size();
  if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument(fmt::format("Welch spectrum: time step {} s; valid range > 0", dt));
  if (n < 16) throw std::invalid_argument(fmt::format("Welch spectrum: {} samples; valid: at least 16", n));
  if (!(options.overlap >= 0.0 && options.overlap <= 0.9))
    throw std::invalid_argument(fmt::format("Welch spectrum: overlap {}; valid range [0, 0.9]", options.overlap));
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(record[i])) throw std::invalid_argument(fmt::format("Welch spectrum: sample {} is {}; valid: finite", i, record[i]));
  std::size_t length = options.segment_length;
  if (length == 0) {
    length = 16;
    while (length * 2 <= n / 8) length *= 2;
  }
  if (length < 16 || length > n)
    throw std::invalid_argument(fmt::format("Welch spectrum: segment length {}; valid range [16, {}] (the record)", length, n));
  double mean = 0.0;
  for (double v : record) mean += v;
  mean /= static_cast<double>(n);

  std::vector<double> window(length);
  double window_power = 0.0;
  for (std::size_t j = 0; j < length; ++j) {
    window[j] = 0.5 * (1.0 - std::cos(kTwoPi * static_cast<double>(j) / static_cast<double>(length)));  // periodic Hann
    window_power += window[j] * window[j];
  }
  const std::size_t bins = length / 2 + 1;
  std::unique_ptr<double, FftwFree> in(fftw_alloc_real(length));
  std::unique_ptr<fftw_complex, FftwFree> out(fftw_alloc_complex(bins));
  fftw_plan plan = nullptr;
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    plan = fftw_plan_dft_r2c_1d(static_cast<int>(length), in.get(), out.get(), FFTW_ESTIMATE);
  }
  if (plan == nullptr) throw std::runtime_error(fmt::format("Welch spectrum: FFTW could not plan a transform of {} samples", length));

  PowerSpectrum result;
  result.resolution = kTwoPi / (static_cast<double>(length) * dt);
  result.density.assign(bins, 0.0);
  const auto hop = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(static_cast<double>(length) * (1.0 - options.overlap))));
  for (std::size_t start = 0; start + length <= n; start += hop) {
    for (std::size_t j = 0; j < length; ++j) in.get()[j] = window[j] * (record[start + j] - mean);
    fftw_execute_dft_r2c(plan, in.get(), out.get());
    for (std::size_t k = 0; k < bins; ++k) {
      const double power = out.get()[k][0] * out.get()[k][0] + out.get()[k][1] * out.get()[k][1];
      const double sides = (k == 0 || 2 * k == length) ? 1.0 : 2.0;
      result.density[k] += sides * dt * power / (kTwoPi * window_power);
    }
    ++result.segments;
  }
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
  for (auto& s : result.density) s /= static_cast<double>(result.segments);
  for (std::size_t k = 0; k < bins; ++k) result.frequency.push_back(static_cast<double>(k) * result.resolution);
  return result;
}

double spectral_moment(const PowerSpectrum& s, int order) {
  double sum = 0.0;
  for (std::size_t k = 0; k < s.density.size(); ++k) {
    const double weight = (k == 0 || k + 1 == s.density.size()) ? 0.5 : 1.0;
    sum += weight * std::pow(s.frequency[k], order) * s.density[k];
  }
  return sum * s.resolution;
}

double peak_frequency(const PowerSpectrum& s) {
  const auto it = std::max_element(s.density.begin(), s.density.end());
  const auto k = static_cast<std::size_t>(it - s.density.begin());
  if (k == 0 || k + 1 == s.density.size()) return s.frequency[k];
  const double a = s.density[k - 1], b = s.density[k], c = s.density[k + 1];
  const double denominator = a - 2 * b + c;
  return s.frequency[k] + (denominator != 0.0 ? 0.5 * (a - c) / denominator : 0.0) * s.resolution;
}

}  // namespace ffrf::hydro
