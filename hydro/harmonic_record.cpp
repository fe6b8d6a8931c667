// Harmonic sums sampled by FFT and read back by quintic Hermite interpolation, with the interpolation
// error measured at every segment midpoint (see harmonic_record.hpp).
#include "hydro/harmonic_record.hpp"

#include "hydro/constants.hpp"
#include "hydro/fftw_memory.hpp"

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
constexpr int max_attempts = 4;

// Adds the two-sided bins of real channels a (and b, if any) times factor(ω): ½(a + i b) f at bin n,
// its conjugate pair ½(ā + i b̄) f̄ at bin N − n, so the transform holds Re(Σ a f e) + i Re(Σ b f e).
template <class Factor, class Frequency>
void add_real_pair(const std::vector<Complex>& a, const std::vector<Complex>* b, std::int64_t first_harmonic, std::size_t n,
                   Factor factor, Frequency frequency, Complex* bins) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Complex f = factor(frequency(i));
    const Complex first = 0.5 * a[i] * f, second = b ? 0.5 * (*b)[i] * f : Complex(0.0);
    const auto positive = static_cast<std::size_t>((first_harmonic + static_cast<std::int64_t>(i)) % static_cast<std::int64_t>(n));
    const std::size_t negative = (n - positive) % n;
    bins[positive] += first + Complex(0.0, 1.0) * second;
    bins[negative] += std::conj(first) + Complex(0.0, 1.0) * std::conj(second);
  }
}

std::size_t component_count(const HarmonicSums& sums) {
  return sums.coefficients.empty() ? sums.real_parts.front().size() : sums.coefficients.front().size();
}

std::size_t recorded_channels(const HarmonicSums& sums) { return sums.coefficients.size() + (sums.real_parts.size() + 1) / 2; }

void check(const HarmonicSums& sums, const HarmonicRecordOptions& options) {
  if (!(sums.frequency_step > 0.0) || !std::isfinite(sums.frequency_step))
    throw std::invalid_argument(fmt::format("harmonic record: frequency step {} rad/s; valid range > 0", sums.frequency_step));
  if (sums.first_harmonic < 0)
    throw std::invalid_argument(fmt::format("harmonic record: first harmonic {}; valid range >= 0", sums.first_harmonic));
  if (sums.time_sign != 1 && sums.time_sign != -1)
    throw std::invalid_argument(fmt::format("harmonic record: time sign {}; valid: +1 or -1", sums.time_sign));
  if (sums.coefficients.empty() && sums.real_parts.empty())
    throw std::invalid_argument("harmonic record: no channel; valid: at least one");
  const std::size_t count = component_count(sums);
  for (std::size_t c = 0; c < sums.coefficients.size() + sums.real_parts.size(); ++c) {
    const std::size_t size = c < sums.coefficients.size() ? sums.coefficients[c].size()
                                                          : sums.real_parts[c - sums.coefficients.size()].size();
    if (size != count)
      throw std::invalid_argument(fmt::format("harmonic record: channel {} has {} components, channel 0 has {}; valid: equal",
                                              c, size, count));
  }
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
  const std::size_t count = component_count(sums);
  double largest_rms = 0.0;
  for (const auto* group : {&sums.coefficients, &sums.real_parts})
    for (const auto& channel : *group) {
      double power = 0.0;
      for (std::size_t i = 0; i < count; ++i) power += std::norm(channel[i]) * std::pow(frequency(sums, i), 12);
      largest_rms = std::max(largest_rms, std::sqrt(power));
    }
  double step = options.largest_time_step;
  if (count > 0) step = std::min(step, 0.25 * kTwoPi / std::max(frequency(sums, count - 1), sums.frequency_step));
  if (largest_rms > 0.0) step = std::min(step, std::pow(46080.0 * options.tolerance / (5.0 * largest_rms), 1.0 / 6.0));
  return step;
}

// N for a step: at least the period over the step, and above twice the highest harmonic when real
// channels put their conjugates at the negative bins.
std::size_t fft_size_for(const HarmonicSums& sums, double step) {
  const double period = kTwoPi / sums.frequency_step;
  auto n = static_cast<std::size_t>(std::ceil(period / step));
  if (!sums.real_parts.empty())
    n = std::max(n, 2 * static_cast<std::size_t>(sums.first_harmonic + static_cast<std::int64_t>(component_count(sums))) + 1);
  return fast_size(n);
}

// Samples covering [0, duration] and one segment beyond, at most one period (N + 1: periodic).
std::size_t samples_for(double duration, double step, std::size_t n) {
  const double wanted = std::floor(duration / step) + 2.0;
  return wanted >= static_cast<double>(n + 1) ? n + 1 : static_cast<std::size_t>(wanted);
}

std::size_t bytes_for(std::size_t channels, std::size_t samples) { return 3 * channels * samples * sizeof(Complex); }

}  // namespace

std::size_t HarmonicRecord::predicted_memory(const HarmonicSums& sums, const HarmonicRecordOptions& options) {
  check(sums, options);
  const std::size_t n = fft_size_for(sums, first_time_step(sums, options));
  const double step = kTwoPi / sums.frequency_step / static_cast<double>(n);
  return bytes_for(recorded_channels(sums), samples_for(options.duration, step, n));
}

HarmonicRecord HarmonicRecord::build(const HarmonicSums& sums, const HarmonicRecordOptions& options) {
  check(sums, options);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t complex_channels = sums.coefficients.size(), real_channels = sums.real_parts.size();
  const std::size_t channels = recorded_channels(sums), count = component_count(sums);
  const double period = kTwoPi / sums.frequency_step, sign = static_cast<double>(sums.time_sign);
  double step = first_time_step(sums, options);
  for (int attempt = 0;; ++attempt) {
    const std::size_t n = fft_size_for(sums, step);
    step = period / static_cast<double>(n);
    const std::size_t samples = samples_for(options.duration, step, n);
    if (bytes_for(channels, samples) > options.memory_limit) {
      throw std::length_error(fmt::format(
          "harmonic record: {} channels x {} samples (time step {:.4g} s over {:g} s) take {:.1f} MB; the limit is {:.1f} MB",
          channels, samples, step, options.duration, static_cast<double>(bytes_for(channels, samples)) / 1e6,
          static_cast<double>(options.memory_limit) / 1e6));
    }
    HarmonicRecord record;
    record.channels_ = channels;
    record.complex_channels_ = complex_channels;
    record.real_channels_ = real_channels;
    record.samples_ = samples;
    record.fft_size_ = n;
    record.time_step_ = step;
    record.period_ = period;
    record.periodic_ = samples == n + 1;
    record.duration_ = record.periodic_ ? INFINITY : static_cast<double>(samples - 1) * step;  // ≥ the requested duration
    record.values_.resize(channels * samples);
    record.rates_.resize(channels * samples);
    record.accelerations_.resize(channels * samples);

    // Channels go through in blocks: each channel's four transforms into its block's buffers (one
    // per kind: value, rate, acceleration, midpoint), then the block is written sample by sample
    // into the records (sample-major, as evaluate reads them) — contiguous writes, not one cache
    // line per sample and channel.
    constexpr std::size_t block = 4;
    std::unique_ptr<fftw_complex, FftwFree> in(fftw_alloc_complex(n));
    std::vector<std::unique_ptr<fftw_complex, FftwFree>> out;
    for (std::size_t b = 0; b < 3 * block + 1; ++b) out.emplace_back(fftw_alloc_complex(n));
    std::vector<fftw_plan> plans(out.size(), nullptr);
    {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      for (std::size_t b = 0; b < out.size(); ++b)
        plans[b] = fftw_plan_dft_1d(static_cast<int>(n), in.get(), out[b].get(), sums.time_sign > 0 ? FFTW_BACKWARD : FFTW_FORWARD,
                                    FFTW_ESTIMATE);
    }
    const auto destroy = [&] {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      for (fftw_plan plan : plans)
        if (plan != nullptr) fftw_destroy_plan(plan);
    };
    if (std::find(plans.begin(), plans.end(), nullptr) != plans.end()) {
      destroy();
      throw std::runtime_error(fmt::format("harmonic record: FFTW could not plan a transform of {} samples", n));
    }
    auto* bins = reinterpret_cast<Complex*>(in.get());
    const auto buffer = [&](std::size_t b) { return reinterpret_cast<const Complex*>(out[b].get()); };
    const auto bin_of = [&](std::size_t i) {
      return static_cast<std::size_t>((sums.first_harmonic + static_cast<std::int64_t>(i)) % static_cast<std::int64_t>(n));
    };
    // Record channel c's bins for the kind with factor(ω), transformed into buffer b.
    const auto transform = [&](std::size_t c, auto factor, std::size_t b) {
      std::fill(bins, bins + n, Complex(0.0));
      if (c < complex_channels) {
        const std::vector<Complex>& channel = sums.coefficients[c];
        for (std::size_t i = 0; i < count; ++i) bins[bin_of(i)] += channel[i] * factor(frequency(sums, i));
      } else {
        const std::size_t r = 2 * (c - complex_channels);
        add_real_pair(sums.real_parts[r], r + 1 < real_channels ? &sums.real_parts[r + 1] : nullptr, sums.first_harmonic, n,
                      factor, [&](std::size_t i) { return frequency(sums, i); }, bins);
      }
      fftw_execute_dft(plans[b], in.get(), out[b].get());
    };
    double largest_norm = 0.0;
    for (std::size_t c0 = 0; c0 < channels; c0 += block) {
      const std::size_t width = std::min(block, channels - c0);
      for (std::size_t b = 0; b < width; ++b) {
        const std::size_t c = c0 + b;
        transform(c, [](double) { return Complex(1.0); }, 3 * b);
        transform(c, [&](double w) { return Complex(0.0, sign * w); }, 3 * b + 1);
        transform(c, [](double w) { return Complex(-w * w); }, 3 * b + 2);
        transform(c, [&](double w) { return std::polar(1.0, 0.5 * sign * w * step); }, 3 * block);
        const Complex *value = buffer(3 * b), *rate = buffer(3 * b + 1), *acceleration = buffer(3 * b + 2),
                      *midpoint = buffer(3 * block);
        for (std::size_t j = 0; j + 1 < samples; ++j) {
          const std::size_t next = j + 1 == n ? 0 : j + 1;  // j < n: the last segment wraps to sample 0
          // The quintic Hermite basis at τ = ½: ½, 5/32 Δt, 1/64 Δt² (left); ½, −5/32 Δt, 1/64 Δt² (right).
          const Complex hermite = 0.5 * (value[j] + value[next]) + (5.0 / 32.0) * step * (rate[j] - rate[next]) +
                                  (1.0 / 64.0) * step * step * (acceleration[j] + acceleration[next]);
          largest_norm = std::max(largest_norm, std::norm(hermite - midpoint[j]));
        }
      }
      for (std::size_t j = 0; j < samples; ++j) {
        const std::size_t source = j == n ? 0 : j;
        Complex* value = &record.values_[j * channels + c0];
        Complex* rate = &record.rates_[j * channels + c0];
        Complex* acceleration = &record.accelerations_[j * channels + c0];
        for (std::size_t b = 0; b < width; ++b) {
          value[b] = buffer(3 * b)[source];
          rate[b] = buffer(3 * b + 1)[source];
          acceleration[b] = buffer(3 * b + 2)[source];
        }
      }
    }
    destroy();
    const double error = std::sqrt(largest_norm);
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

HarmonicSamples sample_real_parts(const HarmonicSums& sums, double largest_step) {
  HarmonicRecordOptions options;
  options.duration = 1.0;
  options.largest_time_step = largest_step;
  check(sums, options);
  if (!sums.coefficients.empty()) throw std::invalid_argument("harmonic samples: complex channels; valid: real parts only");
  const std::size_t n = fft_size_for(sums, largest_step);
  HarmonicSamples out;
  out.time_step = kTwoPi / sums.frequency_step / static_cast<double>(n);
  out.channels.assign(sums.real_parts.size(), std::vector<double>(n));
  std::unique_ptr<fftw_complex, FftwFree> in(fftw_alloc_complex(n)), result(fftw_alloc_complex(n));
  fftw_plan plan = nullptr;
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    plan = fftw_plan_dft_1d(static_cast<int>(n), in.get(), result.get(), sums.time_sign > 0 ? FFTW_BACKWARD : FFTW_FORWARD,
                            FFTW_ESTIMATE);
  }
  if (plan == nullptr) throw std::runtime_error(fmt::format("harmonic samples: FFTW could not plan a transform of {} samples", n));
  auto* bins = reinterpret_cast<Complex*>(in.get());
  const auto* values = reinterpret_cast<const Complex*>(result.get());
  for (std::size_t r = 0; r < sums.real_parts.size(); r += 2) {
    const bool pair = r + 1 < sums.real_parts.size();
    std::fill(bins, bins + n, Complex(0.0));
    add_real_pair(sums.real_parts[r], pair ? &sums.real_parts[r + 1] : nullptr, sums.first_harmonic, n,
                  [](double) { return Complex(1.0); }, [&](std::size_t i) { return frequency(sums, i); }, bins);
    fftw_execute(plan);
    for (std::size_t j = 0; j < n; ++j) out.channels[r][j] = values[j].real();
    if (pair)
      for (std::size_t j = 0; j < n; ++j) out.channels[r + 1][j] = values[j].imag();
  }
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
  for (const std::vector<Complex>& channel : sums.real_parts) {
    double total = 0.0;
    for (const Complex& a : channel) total += std::abs(a);
    out.magnitude_sums.push_back(total);
  }
  return out;
}

// The segment holding t (modulo the period when periodic) and the position τ ∈ [0, 1] in it (t
// outside the record: the end segments).
std::size_t HarmonicRecord::segment(double t, double& tau) const {
  if (periodic_ && t >= period_) t -= std::floor(t / period_) * period_;
  const double position = t / time_step_;
  auto j = static_cast<std::size_t>(std::max(position, 0.0));
  if (j + 1 >= samples_) j = samples_ - 2;
  tau = position - static_cast<double>(j);
  return j;
}

void HarmonicRecord::evaluate(double t, std::complex<double>* out) const {
  double tau = 0.0;
  const std::size_t j = segment(t, tau);
  const double u = 1.0 - tau, tau3 = tau * tau * tau, u3 = u * u * u, h = time_step_;
  const double weights[6] = {u3 * (6.0 * tau * tau + 3.0 * tau + 1.0), h * tau * u3 * (3.0 * tau + 1.0),
                             0.5 * h * h * tau * tau * u3,          tau3 * (6.0 * u * u + 3.0 * u + 1.0),
                             -h * tau3 * u * (3.0 * u + 1.0),       0.5 * h * h * tau3 * u * u};
  combine(j, weights, out);
}

void HarmonicRecord::evaluate(double t, std::complex<double>* out, std::complex<double>* rate_out) const {
  evaluate(t, out);
  double tau = 0.0;
  const std::size_t j = segment(t, tau);
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
