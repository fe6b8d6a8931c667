// Random-phase synthesis of an irregular sea and its elevation (see wave_synthesis.hpp).
#include "hydro/wave_synthesis.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "hydro/constants.hpp"
#include "hydro/fftw_memory.hpp"
#include "hydro/harmonic_record.hpp"
#include "hydro/random_stream.hpp"

namespace ffrf::hydro {

namespace {
constexpr double kMaxComponents = 2e6;

void require_synthesis(bool ok, std::string_view what, double value, std::string_view range) {
  if (!ok) throw std::invalid_argument(fmt::format("wave synthesis: {} = {} is invalid; valid range {}", what, value, range));
}
}  // namespace

double WaveComponents::variance() const {
  double sum = 0.0;
  for (double a : amplitude) sum += 0.5 * a * a;
  return sum;
}

double WaveComponents::repeat_period() const {
  return frequency_step > 0.0 ? kTwoPi / frequency_step : std::numeric_limits<double>::infinity();
}

WaveComponents user_components(std::vector<double> frequency, std::vector<double> amplitude,
                               std::vector<double> phase, WaveHeading heading, double frequency_step) {
  if (frequency.empty() || frequency.size() != amplitude.size() || frequency.size() != phase.size())
    throw std::invalid_argument(fmt::format(
        "wave components: {} frequencies, {} amplitudes, {} phases; valid: equal sizes, at least one", frequency.size(),
        amplitude.size(), phase.size()));
  require_synthesis(std::isfinite(frequency_step) && frequency_step >= 0.0, "frequency step [rad/s]", frequency_step, ">= 0");
  for (std::size_t i = 0; i < frequency.size(); ++i) {
    require_synthesis(std::isfinite(frequency[i]) && frequency[i] > 0.0, fmt::format("component {} frequency [rad/s]", i),
            frequency[i], "> 0");
    require_synthesis(std::isfinite(amplitude[i]) && amplitude[i] >= 0.0, fmt::format("component {} amplitude [m]", i),
            amplitude[i], ">= 0");
    require_synthesis(std::isfinite(phase[i]), fmt::format("component {} phase [rad]", i), phase[i], "finite");
    if (frequency_step > 0.0) {
      const double n = frequency[i] / frequency_step;
      require_synthesis(std::abs(n - std::round(n)) <= 1e-9 * n, fmt::format("component {} frequency / step", i), n,
              "a whole number (the components must lie on the grid n * step)");
    }
  }
  return WaveComponents{std::move(frequency), std::move(amplitude), std::move(phase), heading, frequency_step};
}

SeaRealisation synthesize(const WaveSpectrum& spectrum, const SynthesisOptions& options) {
  require_synthesis(std::isfinite(options.record_length) && options.record_length > 0.0, "record length [s]",
          options.record_length, "> 0");
  const double step = options.frequency_step > 0.0 ? options.frequency_step : kTwoPi / options.record_length;
  require_synthesis(std::isfinite(step) && step > 0.0, "frequency step [rad/s]", options.frequency_step, ">= 0");
  const FrequencyBand band = synthesis_band(spectrum, options.omega_min, options.omega_max, 1.0 - options.tail_fraction);
  const double lo = band.lower, hi = band.upper;
  require_synthesis(std::isfinite(lo) && lo >= 0.0, "lowest frequency [rad/s]", lo, ">= 0");
  require_synthesis(std::isfinite(hi) && hi > lo, "highest frequency [rad/s]", hi, fmt::format("> the lowest ({})", lo));
  const double first = std::max(1.0, std::ceil(lo / step)), last = std::floor(hi / step);
  require_synthesis(last >= first, "number of components", last - first + 1.0,
          fmt::format(">= 1 (band [{}, {}] rad/s, step {} rad/s)", lo, hi, step));
  require_synthesis(last - first + 1.0 <= kMaxComponents, "number of components", last - first + 1.0,
          fmt::format("<= {} (make the band narrower or the record shorter)", kMaxComponents));

  SeaRealisation result;
  auto& c = result.components;
  c.heading = options.heading;
  c.frequency_step = step;
  const RandomStream stream(options.seed, options.realisation);
  for (double n = first; n <= last; n += 1.0) {
    const double omega = n * step;
    const double density = spectral_density(spectrum, omega);
    const auto index = static_cast<std::uint64_t>(n);
    double energy = 2.0 * density * step;
    if (options.random_amplitudes) energy *= stream.exponential(2 * index + 1);
    c.frequency.push_back(omega);
    c.amplitude.push_back(std::sqrt(energy));
    c.phase.push_back(kTwoPi * stream.uniform(2 * index));
    result.band_m0 += density * step;
  }
  result.spectrum_m0 = spectral_moment(spectrum, 0);
  result.repeat_period = kTwoPi / step;
  if (result.repeat_period < options.record_length * (1.0 - 1e-12)) {
    result.repeats_within_record = true;
    result.warning = fmt::format(
        "the synthesized sea repeats after {:.6g} s (2 pi / frequency step {:.6g} rad/s), shorter than the record "
        "{:.6g} s: statistics over the record count the same waves again; use a frequency step <= {:.6g} rad/s",
        result.repeat_period, step, options.record_length, kTwoPi / options.record_length);
  }
  return result;
}

double elevation(const WaveComponents& c, double t) {
  double sum = 0.0;
  for (std::size_t n = 0; n < c.size(); ++n) sum += c.amplitude[n] * std::cos(c.frequency[n] * t + c.phase[n]);
  return sum;
}

namespace {

// The FFT's length when the components lie on a harmonic grid n Δω and 2π/Δω is a whole number of
// steps dt (within 10⁻⁹ of a step; the sums are then sampled exactly), else 0.
std::size_t harmonic_fft_size(const WaveComponents& c, double dt) {
  if (!(c.frequency_step > 0.0) || !(dt > 0.0) || c.size() == 0) return 0;
  const double steps = kTwoPi / c.frequency_step / dt;
  const double whole = std::round(steps);
  if (!(whole >= 1.0) || std::abs(steps - whole) > 1e-9 * whole || whole > 1e9) return 0;
  for (const double w : c.frequency)
    if (std::abs(w / c.frequency_step - std::round(w / c.frequency_step)) > 1e-6) return 0;
  return static_cast<std::size_t>(whole);
}

std::vector<double> elevation_by_fft(const WaveComponents& c, double t0, std::size_t n, std::size_t count) {
  std::unique_ptr<fftw_complex, FftwFree> buffer(fftw_alloc_complex(n));
  auto* bins = reinterpret_cast<std::complex<double>*>(buffer.get());
  std::fill(bins, bins + n, std::complex<double>(0.0));
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto harmonic = static_cast<std::size_t>(std::llround(c.frequency[i] / c.frequency_step));
    bins[harmonic % n] += std::polar(c.amplitude[i], c.frequency[i] * t0 + c.phase[i]);
  }
  fftw_plan plan = nullptr;
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    plan = fftw_plan_dft_1d(static_cast<int>(n), buffer.get(), buffer.get(), FFTW_BACKWARD, FFTW_ESTIMATE);
  }
  if (plan == nullptr) throw std::runtime_error(fmt::format("elevation record: FFTW could not plan a transform of {} samples", n));
  fftw_execute(plan);
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
  std::vector<double> eta(count);
  for (std::size_t k = 0; k < count; ++k) eta[k] = bins[k % n].real();
  return eta;
}

}  // namespace

std::vector<double> elevation_record(const WaveComponents& c, double t0, double dt, std::size_t count) {
  if (const std::size_t n = harmonic_fft_size(c, dt); n > 0) return elevation_by_fft(c, t0, n, count);
  constexpr std::size_t kAnchor = 1024;
  std::vector<double> eta(count, 0.0);
  for (std::size_t n = 0; n < c.size(); ++n) {
    const std::complex<double> rotation = std::polar(1.0, c.frequency[n] * dt);
    std::complex<double> phasor;
    for (std::size_t k = 0; k < count; ++k) {
      if (k % kAnchor == 0) phasor = std::polar(c.amplitude[n], c.frequency[n] * (t0 + static_cast<double>(k) * dt) + c.phase[n]);
      eta[k] += phasor.real();
      phasor *= rotation;
    }
  }
  return eta;
}

}  // namespace ffrf::hydro
