// The incident sea recorded once per record on patches around the hull's sides: Taylor polynomials
// of H = ∫∫F in z = y + i x whose coefficients are FFT-sampled harmonic sums, and sampled elevation
// and slope bounds over the hull's x range (see incident_wave_record.hpp).
#include "coupling/incident_wave_record.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "coupling/component_phasors.hpp"

namespace ffrf::coupling {

namespace {

using Complex = std::complex<double>;
constexpr std::size_t largest_degree = 60;

void check_options(const std::vector<WavePatch>& patches, const IncidentWaveRecordOptions& options) {
  if (patches.empty()) throw std::invalid_argument("incident wave record: no patch; valid: at least one");
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const WavePatch& patch = patches[p];
    if (!(patch.radius > 0.0) || !std::isfinite(patch.radius) || !std::isfinite(patch.x) || !std::isfinite(patch.y))
      throw std::invalid_argument(fmt::format("incident wave record: patch {} at ({}, {}) m with radius {} m; valid: finite, radius > 0",
                                              p, patch.x, patch.y, patch.radius));
  }
  if (!(options.duration > 0.0) || !std::isfinite(options.duration))
    throw std::invalid_argument(fmt::format("incident wave record: duration {} s; valid range > 0, finite", options.duration));
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
    throw std::invalid_argument(fmt::format("incident wave record: tolerance {} m; valid range > 0, finite", options.tolerance));
  if (!(options.x_max > options.x_min) || !std::isfinite(options.x_max - options.x_min))
    throw std::invalid_argument(fmt::format("incident wave record: x range [{}, {}] m; valid: finite, x_min < x_max",
                                            options.x_min, options.x_max));
}

// Why the field cannot be recorded, or empty.
std::string unsupported(const WaveField& wave) {
  if (wave.components().empty()) return "calm water";
  if (!wave.deep()) return "finite water depth (the recorded sums are those of deep water)";
  if (!wave.harmonic_grid().active) return "the components are not on a harmonic grid ω_n = n Δω";
  for (const WaveComponent& c : wave.components())
    if (!(c.wave_number > 0.0)) return "a component of zero frequency";
  return {};
}

// R_M(x) = Σ_{m>M} x^m/m! summed term by term (the terms fall once m > x).
double taylor_tail(double x, std::size_t degree) {
  double term = 1.0;
  for (std::size_t m = 1; m <= degree; ++m) term *= x / static_cast<double>(m);
  double tail = 0.0;
  for (std::size_t m = degree + 1; m < degree + 400; ++m) {
    term *= x / static_cast<double>(m);
    tail += term;
    if (term < 1e-18 * tail) break;
  }
  return tail;
}

// The smallest degree M whose remainder bound Σ |A_n| e^{k_n y_c} R_M(k_n ρ) is within `budget`, in
// every patch; and the bound at that degree.
std::size_t taylor_degree(const WaveField& wave, const std::vector<WavePatch>& patches, double budget, double& bound) {
  for (std::size_t degree = 4; degree <= largest_degree; ++degree) {
    bound = 0.0;
    for (const WavePatch& patch : patches) {
      double patch_bound = 0.0;
      for (const WaveComponent& c : wave.components())
        patch_bound += c.amplitude * std::exp(c.wave_number * patch.y) * taylor_tail(c.wave_number * patch.radius, degree);
      bound = std::max(bound, patch_bound);
    }
    if (bound <= budget) return degree;
  }
  throw std::invalid_argument(fmt::format("incident wave record: the patches are too large for the shortest waves (a Taylor "
                                          "polynomial of degree {} leaves {:.3g} m > {:.3g} m); valid: smaller patches or a "
                                          "narrower band", largest_degree, bound, budget));
}

// Channels of one patch: η_0 = Σ A e^{kc}/(kρ)², η_1 = Σ A e^{kc}/(kρ), then f̂_j = Σ A e^{kc}(kρ)^j/j!
// (j = 0 … M), all in elevation units; time factor e^{−iδωt}.
void add_patch_channels(const WaveField& wave, const WavePatch& patch, std::size_t degree, hydro::HarmonicSums& sums) {
  const std::size_t count = wave.components().size();
  const std::size_t first = sums.coefficients.size();
  sums.coefficients.resize(first + degree + 3, std::vector<Complex>(count));
  for (std::size_t n = 0; n < count; ++n) {
    const WaveComponent& c = wave.components()[n];
    const double k_rho = c.wave_number * patch.radius;
    const Complex base = wave.complex_amplitudes()[n] * std::exp(Complex(c.wave_number * patch.y, c.wave_number * patch.x));
    sums.coefficients[first][n] = base / (k_rho * k_rho);
    sums.coefficients[first + 1][n] = base / k_rho;
    Complex term = base;
    for (std::size_t j = 0; j <= degree; ++j) {
      if (j > 0) term *= k_rho / static_cast<double>(j);
      sums.coefficients[first + 2 + j][n] = term;
    }
  }
}

hydro::HarmonicSums empty_sums(const WaveField& wave) {
  hydro::HarmonicSums sums;
  sums.frequency_step = wave.harmonic_grid().frequency_step;
  sums.first_harmonic = static_cast<std::int64_t>(wave.harmonic_grid().first_harmonic);
  sums.time_sign = wave.direction() > 0.0 ? -1 : 1;  // e^{−iδωt}
  return sums;
}

constexpr double bound_window = 5.0;  // [s]

// |ζ| and |∂ζ/∂x| over [x_min, x_max] × [0, duration], sampled every tenth of the shortest wavelength
// and (by the record's own step) in time, the largest per window of bound_window seconds (a sample
// within one time step of a window's edge counts for both windows); the values between samples
// exceed the sampled largest by at most (k_max Δx)²/8 of it for one component (1/cos(k Δx/2) − 1):
// a margin of 10 % covers that (1.3 % at Δx = λ_min/10) and the time interpolation's.
void sample_bounds(const WaveField& wave, const IncidentWaveRecordOptions& options, std::vector<double>& elevation,
                   std::vector<double>& slope) {
  const double shortest = 2.0 * std::numbers::pi / wave.max_wave_number();
  const double span = options.x_max - options.x_min;
  const auto points = static_cast<std::size_t>(std::ceil(span / (0.1 * shortest))) + 1;
  hydro::HarmonicRecordOptions record_options;
  record_options.duration = options.duration;
  record_options.tolerance = 0.01 * options.tolerance;
  record_options.memory_limit = options.memory_limit;
  const auto windows = static_cast<std::size_t>(std::ceil(options.duration / bound_window)) + 1;
  elevation.assign(windows, 0.0);
  slope.assign(windows, 0.0);
  std::vector<Complex> value(2);
  for (std::size_t i = 0; i < points; ++i) {
    const double x = options.x_min + span * static_cast<double>(i) / static_cast<double>(points - 1);
    hydro::HarmonicSums sums = empty_sums(wave);
    sums.coefficients.assign(2, std::vector<Complex>(wave.components().size()));
    for (std::size_t n = 0; n < wave.components().size(); ++n) {
      const double k = wave.components()[n].wave_number;
      const Complex at_x = wave.complex_amplitudes()[n] * std::polar(1.0, k * x);
      sums.coefficients[0][n] = at_x;
      sums.coefficients[1][n] = Complex(0.0, k) * at_x;  // ∂/∂x
    }
    const hydro::HarmonicRecord record = hydro::HarmonicRecord::build(sums, record_options);
    const double step = record.time_step();
    for (std::size_t j = 0; j < record.samples(); ++j) {
      const double t = static_cast<double>(j) * step;
      record.evaluate(t, value.data());
      const auto first = static_cast<std::size_t>(std::max(t - step, 0.0) / bound_window);
      const auto last = std::min(static_cast<std::size_t>((t + step) / bound_window), windows - 1);
      for (std::size_t w = first; w <= last; ++w) {
        elevation[w] = std::max(elevation[w], std::abs(value[0].real()));
        slope[w] = std::max(slope[w], std::abs(value[1].real()));
      }
    }
  }
  for (std::size_t w = 0; w < windows; ++w) {
    elevation[w] = 1.1 * elevation[w] + options.tolerance;
    slope[w] = 1.1 * slope[w] + options.tolerance;
  }
}

}  // namespace

std::size_t IncidentWaveRecord::predicted_memory(const WaveField& wave, const std::vector<WavePatch>& patches,
                                                 const IncidentWaveRecordOptions& options) {
  check_options(patches, options);
  if (!unsupported(wave).empty()) return 0;
  double bound = 0.0;
  const std::size_t degree = taylor_degree(wave, patches, 0.25 * options.tolerance, bound);
  hydro::HarmonicSums sums = empty_sums(wave);
  for (const WavePatch& patch : patches) add_patch_channels(wave, patch, degree, sums);
  hydro::HarmonicRecordOptions record_options;
  record_options.duration = options.duration;
  record_options.tolerance = 0.25 * options.tolerance / static_cast<double>(degree + 3);
  return hydro::HarmonicRecord::predicted_memory(sums, record_options);
}

std::optional<IncidentWaveRecord> IncidentWaveRecord::build(const WaveField& wave, const std::vector<WavePatch>& patches,
                                                            const IncidentWaveRecordOptions& options, std::string* why) {
  check_options(patches, options);
  if (const std::string reason = unsupported(wave); !reason.empty()) {
    if (why) *why = reason;
    return std::nullopt;
  }
  const auto start = std::chrono::steady_clock::now();
  IncidentWaveRecord out;
  out.patches_ = patches;
  out.x_min_ = options.x_min;
  out.x_max_ = options.x_max;
  double truncation = 0.0;
  out.degree_ = taylor_degree(wave, patches, 0.25 * options.tolerance, truncation);
  hydro::HarmonicSums sums = empty_sums(wave);
  for (const WavePatch& patch : patches) add_patch_channels(wave, patch, out.degree_, sums);
  hydro::HarmonicRecordOptions record_options;
  record_options.duration = options.duration;
  record_options.tolerance = 0.25 * options.tolerance / static_cast<double>(out.degree_ + 3);
  record_options.memory_limit = options.memory_limit;
  out.record_ = hydro::HarmonicRecord::build(sums, record_options);
  out.channel_scale_.assign(out.degree_ + 3, 1.0);
  for (std::size_t m = 2; m < out.degree_ + 3; ++m) out.channel_scale_[m] = 1.0 / static_cast<double>(m * (m - 1));

  IncidentWaveRecordStats& stats = out.stats_;
  stats.patches = patches.size();
  stats.degree = out.degree_;
  stats.channels = out.record_.channels();
  stats.samples = out.record_.samples();
  stats.components = wave.components().size();
  stats.time_step = out.record_.time_step();
  stats.truncation_bound = truncation;
  stats.interpolation_error = static_cast<double>(out.degree_ + 3) * out.record_.midpoint_error();
  stats.memory_bytes = static_cast<double>(out.record_.memory_bytes());
  sample_bounds(wave, options, out.window_elevation_, out.window_slope_);
  stats.bound_window = bound_window;
  stats.elevation_bound = *std::max_element(out.window_elevation_.begin(), out.window_elevation_.end());
  stats.slope_bound = *std::max_element(out.window_slope_.begin(), out.window_slope_.end());
  stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void IncidentWaveRecord::at(double t, double ramp, WavePolynomials& out) const {
  const std::size_t per_patch = degree_ + 3, channels = per_patch * patches_.size();
  out.potential.resize(channels);
  out.elevation.resize((degree_ + 1) * patches_.size());
  out.ramp = ramp;
  out.time = t;
  record_.evaluate(t, out.potential.data());
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    Complex* potential = &out.potential[p * per_patch];
    Complex* elevation = &out.elevation[p * (degree_ + 1)];
    for (std::size_t j = 0; j <= degree_; ++j) elevation[j] = potential[j + 2];
    for (std::size_t m = 2; m < per_patch; ++m) potential[m] *= channel_scale_[m];
  }
}

int IncidentWaveRecord::patch_of(double x, double y) const {
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    const double dx = x - patches_[p].x, dy = y - patches_[p].y;
    if (dx * dx + dy * dy <= patches_[p].radius * patches_[p].radius) return static_cast<int>(p);
  }
  return -1;
}

void IncidentWaveRecord::elevation_terms(const WavePolynomials& p, int patch, double x, double y, Complex& f,
                                         Complex& f_rate) const {
  const WavePatch& disc = patches_[static_cast<std::size_t>(patch)];
  const Complex w((y - disc.y) / disc.radius, (x - disc.x) / disc.radius);
  const Complex* c = &p.elevation[static_cast<std::size_t>(patch) * (degree_ + 1)];
  Complex value = c[degree_], rate = 0.0;
  for (std::size_t j = degree_; j-- > 0;) {
    rate = times(rate, w) + value;
    value = times(value, w) + c[j];
  }
  f = value;
  f_rate = rate / disc.radius;
}

void IncidentWaveRecord::antiderivatives(const WavePolynomials& p, int patch, double x, double y, Complex& g, Complex& h) const {
  const WavePatch& disc = patches_[static_cast<std::size_t>(patch)];
  const Complex w((y - disc.y) / disc.radius, (x - disc.x) / disc.radius);
  const std::size_t per_patch = degree_ + 3;
  const Complex* c = &p.potential[static_cast<std::size_t>(patch) * per_patch];
  Complex value = c[per_patch - 1], rate = 0.0;
  for (std::size_t m = per_patch - 1; m-- > 0;) {
    rate = times(rate, w) + value;
    value = times(value, w) + c[m];
  }
  h = disc.radius * disc.radius * value;
  g = disc.radius * rate;
}

}  // namespace ffrf::coupling
