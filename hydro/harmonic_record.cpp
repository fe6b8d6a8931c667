// Harmonic sums sampled by FFT and read back by cubic Hermite interpolation, with the interpolation
// error measured at every segment midpoint (see harmonic_record.hpp).
#include "hydro/harmonic_record.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace ffrf::hydro {

std::mutex& fftw_planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr int max_attempts = 4;

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

void check(const HarmonicSums& sums, const HarmonicRecordOptions& options) {
  if (!(sums.frequency_step > 0.0) || !std::isfinite(sums.frequency_step))
    throw std::invalid_argument(fmt::format("harmonic record: frequency step {} rad/s; valid range > 0", sums.frequency_step));
  if (sums.first_harmonic < 0)
    throw std::invalid_argument(fmt::format("harmonic record: first harmonic {}; valid range >= 0", sums.first_harmonic));
  if (sums.time_sign != 1 && sums.time_sign != -1)
    throw std::invalid_argument(fmt::format("harmonic record: time sign {}; valid: +1 or -1", sums.time_sign));
  if (sums.coefficients.empty()) throw std::invalid_argument("harmonic record: no channel; valid: at least one");
  for (std::size_t c = 1; c < sums.coefficients.size(); ++c)
    if (sums.coefficients[c].size() != sums.coefficients[0].size())
      throw std::invalid_argument(fmt::format("harmonic record: channel {} has {} components, channel 0 has {}; valid: equal",
                                              c, sums.coefficients[c].size(), sums.coefficients[0].size()));
  if (!(options.duration > 0.0) || !std::isfinite(options.duration))
    throw std::invalid_argument(fmt::format("harmonic record: duration {} s; valid range > 0, finite", options.duration));
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
    throw std::invalid_argument(fmt::format("harmonic record: tolerance {}; valid range > 0, finite", options.tolerance));
  if (!(options.largest_time_step > 0.0))
    throw std::invalid_argument(fmt::format("harmonic record: largest time step {} s; valid range > 0", options.largest_time_step));
}

double frequency(const HarmonicSums& sums, std::size_t i) {
  return static_cast<double>(sums.first_harmonic + static_cast<std::int64_t>(i)) * sums.frequency_step;
}

// The smallest n' ≥ n of the form 2^a 3^b 5^c 7^d (FFTW's fast sizes).
std::size_t fast_size(std::size_t n) {
  for (std::size_t m = std::max<std::size_t>(n, 1);; ++m) {
    std::size_t r = m;
    for (const std::size_t p : {2u, 3u, 5u, 7u})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

// The first time step to try: the Hermite error s⁽⁶⁾ Δt⁶/46080 with |s⁽⁶⁾| taken as 5 × its rms over
// the period (√(Σ|a|² ω¹²); a long Gaussian record's largest value is about 5 standard deviations), at
// most a quarter of the shortest period and the caller's ceiling. The measured error decides afterwards.
double first_time_step(const HarmonicSums& sums, const HarmonicRecordOptions& options) {
  const std::size_t count = sums.coefficients[0].size();
  double largest_rms = 0.0;
  for (const auto& channel : sums.coefficients) {
    double power = 0.0;
    for (std::size_t i = 0; i < count; ++i) power += std::norm(channel[i]) * std::pow(frequency(sums, i), 12);
    largest_rms = std::max(largest_rms, std::sqrt(power));
  }
  double step = options.largest_time_step;
  if (count > 0) step = std::min(step, 0.25 * kTwoPi / std::max(frequency(sums, count - 1), sums.frequency_step));
  if (largest_rms > 0.0) step = std::min(step, std::pow(46080.0 * options.tolerance / (5.0 * largest_rms), 1.0 / 6.0));
  return step;
}

std::size_t fft_size_for(const HarmonicSums& sums, double step) {
  const double period = kTwoPi / sums.frequency_step;
  return fast_size(static_cast<std::size_t>(std::ceil(period / step)));
}

std::size_t samples_for(double duration, double step) { return static_cast<std::size_t>(std::floor(duration / step)) + 2; }

std::size_t bytes_for(std::size_t channels, std::size_t samples) { return 3 * channels * samples * sizeof(Complex); }

}  // namespace

std::size_t HarmonicRecord::predicted_memory(const HarmonicSums& sums, const HarmonicRecordOptions& options) {
  check(sums, options);
  const std::size_t n = fft_size_for(sums, first_time_step(sums, options));
  const double step = kTwoPi / sums.frequency_step / static_cast<double>(n);
  return bytes_for(sums.coefficients.size(), samples_for(options.duration, step));
}

HarmonicRecord HarmonicRecord::build(const HarmonicSums& sums, const HarmonicRecordOptions& options) {
  check(sums, options);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t channels = sums.coefficients.size(), count = sums.coefficients[0].size();
  const double period = kTwoPi / sums.frequency_step;
  double step = first_time_step(sums, options);
  for (int attempt = 0;; ++attempt) {
    const std::size_t n = fft_size_for(sums, step);
    step = period / static_cast<double>(n);
    const std::size_t samples = samples_for(options.duration, step);
    if (bytes_for(channels, samples) > options.memory_limit) {
      throw std::length_error(fmt::format(
          "harmonic record: {} channels x {} samples (time step {:.4g} s over {:g} s) take {:.1f} MB; the limit is {:.1f} MB",
          channels, samples, step, options.duration, static_cast<double>(bytes_for(channels, samples)) / 1e6,
          static_cast<double>(options.memory_limit) / 1e6));
    }
    HarmonicRecord record;
    record.channels_ = channels;
    record.samples_ = samples;
    record.fft_size_ = n;
    record.time_step_ = step;
    record.duration_ = static_cast<double>(samples - 1) * step;  // ≥ the requested duration
    record.values_.assign(channels * samples, Complex(0.0));
    record.rates_.assign(channels * samples, Complex(0.0));
    record.accelerations_.assign(channels * samples, Complex(0.0));

    std::unique_ptr<fftw_complex, FftwFree> in(fftw_alloc_complex(n)), out(fftw_alloc_complex(n));
    fftw_plan plan = nullptr;
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      plan = fftw_plan_dft_1d(static_cast<int>(n), in.get(), out.get(), sums.time_sign > 0 ? FFTW_BACKWARD : FFTW_FORWARD,
                              FFTW_ESTIMATE);
    }
    if (plan == nullptr) throw std::runtime_error(fmt::format("harmonic record: FFTW could not plan a transform of {} samples", n));
    auto* bins = reinterpret_cast<Complex*>(in.get());
    const auto* result = reinterpret_cast<const Complex*>(out.get());
    // One transform: bins of the coefficients times factor(ω_i), read out at samples j (mod N: periodic).
    const auto transform = [&](const std::vector<Complex>& channel, auto factor, auto&& store) {
      std::fill(bins, bins + n, Complex(0.0));
      for (std::size_t i = 0; i < count; ++i) {
        const auto bin = static_cast<std::size_t>((sums.first_harmonic + static_cast<std::int64_t>(i)) % static_cast<std::int64_t>(n));
        bins[bin] += channel[i] * factor(frequency(sums, i));
      }
      fftw_execute(plan);
      for (std::size_t j = 0; j < samples; ++j) store(j, result[j % n]);
    };
    const double sign = static_cast<double>(sums.time_sign);
    std::vector<Complex> midpoint(samples);
    double error = 0.0;
    for (std::size_t c = 0; c < channels; ++c) {
      const std::vector<Complex>& channel = sums.coefficients[c];
      transform(channel, [](double) { return Complex(1.0); }, [&](std::size_t j, Complex v) { record.values_[j * channels + c] = v; });
      transform(channel, [&](double w) { return Complex(0.0, sign * w); },
                [&](std::size_t j, Complex v) { record.rates_[j * channels + c] = v; });
      transform(channel, [](double w) { return Complex(-w * w); },
                [&](std::size_t j, Complex v) { record.accelerations_[j * channels + c] = v; });
      transform(channel, [&](double w) { return std::polar(1.0, 0.5 * sign * w * step); },
                [&](std::size_t j, Complex v) { midpoint[j] = v; });
      for (std::size_t j = 0; j + 1 < samples; ++j) {
        const std::size_t at = j * channels + c, next = at + channels;
        // The quintic Hermite basis at τ = ½: ½, 5/32 Δt, 1/64 Δt² (left); ½, −5/32 Δt, 1/64 Δt² (right).
        const Complex hermite = 0.5 * (record.values_[at] + record.values_[next]) +
                                (5.0 / 32.0) * step * (record.rates_[at] - record.rates_[next]) +
                                (1.0 / 64.0) * step * step * (record.accelerations_[at] + record.accelerations_[next]);
        error = std::max(error, std::abs(hermite - midpoint[j]));
      }
    }
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      fftw_destroy_plan(plan);
    }
    record.midpoint_error_ = error;
    if (error <= options.tolerance || attempt + 1 == max_attempts) {
      record.build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (error > options.tolerance) {
        throw std::runtime_error(fmt::format("harmonic record: interpolation error {:.3g} above the tolerance {:.3g} after {} "
                                             "refinements (time step {:.4g} s)",
                                             error, options.tolerance, max_attempts, step));
      }
      return record;
    }
    step *= 0.9 * std::pow(options.tolerance / error, 1.0 / 6.0);  // quintic Hermite error ∝ Δt⁶
  }
}

namespace {

// The segment holding t and the position τ ∈ [0, 1] in it (t outside the record: the end segments).
std::size_t segment(double t, double step, std::size_t samples, double& tau) {
  const double position = t / step;
  auto j = static_cast<std::size_t>(std::max(position, 0.0));
  if (j + 1 >= samples) j = samples - 2;
  tau = position - static_cast<double>(j);
  return j;
}

}  // namespace

void HarmonicRecord::evaluate(double t, std::complex<double>* out) const {
  double tau = 0.0;
  const std::size_t j = segment(t, time_step_, samples_, tau);
  const double u = 1.0 - tau, tau3 = tau * tau * tau, u3 = u * u * u, h = time_step_;
  const double weights[6] = {u3 * (6.0 * tau * tau + 3.0 * tau + 1.0), h * tau * u3 * (3.0 * tau + 1.0),
                             0.5 * h * h * tau * tau * u3,          tau3 * (6.0 * u * u + 3.0 * u + 1.0),
                             -h * tau3 * u * (3.0 * u + 1.0),       0.5 * h * h * tau3 * u * u};
  combine(j, weights, out);
}

void HarmonicRecord::evaluate(double t, std::complex<double>* out, std::complex<double>* rate_out) const {
  evaluate(t, out);
  double tau = 0.0;
  const std::size_t j = segment(t, time_step_, samples_, tau);
  // d/dt of the basis above (d/dτ divided by Δt).
  const double u = 1.0 - tau, h = time_step_;
  const double weights[6] = {-30.0 * tau * tau * u * u / h, u * u * (1.0 - 3.0 * tau) * (5.0 * tau + 1.0),
                             0.5 * h * tau * u * u * (2.0 - 5.0 * tau), 30.0 * tau * tau * u * u / h,
                             tau * tau * (2.0 - 3.0 * tau) * (5.0 * tau - 6.0), -0.5 * h * tau * tau * u * (5.0 * tau - 3.0)};
  combine(j, weights, rate_out);
}

void HarmonicRecord::combine(std::size_t j, const double (&weights)[6], std::complex<double>* out) const {
  const Complex* value = &values_[j * channels_];
  const Complex* rate = &rates_[j * channels_];
  const Complex* acceleration = &accelerations_[j * channels_];
  const std::size_t n = channels_;
  for (std::size_t c = 0; c < n; ++c) {
    out[c] = weights[0] * value[c] + weights[1] * rate[c] + weights[2] * acceleration[c] + weights[3] * value[c + n] +
             weights[4] * rate[c + n] + weights[5] * acceleration[c + n];
  }
}

}  // namespace ffrf::hydro
