// The incident sea recorded once per record on patches around the hull's sides: Taylor polynomials
// of H = ∫∫F in z = y + i x whose coefficients are FFT-sampled harmonic sums, and sampled elevation
// and slope bounds over the hull's x range (see incident_wave_record.hpp).
#include "sea/incident_wave_record.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sea/component_phasors.hpp"

namespace ffrf::sea {

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

// |J_d(k_n L/2)| for every component n and d = 0 … largest: the Jacobi–Anger weights, computed once
// for the degree's bound and the channels both.
struct BesselTable {
  std::size_t largest = 0;
  std::vector<double> values;  // [n × (largest + 1) + d] = J_d(k_n L/2)
  double at(std::size_t n, std::size_t d) const { return values[n * (largest + 1) + d]; }
};

BesselTable bessel_table(const WaveField& wave, double half_length) {
  BesselTable table;
  table.largest = static_cast<std::size_t>(std::ceil(wave.max_wave_number() * half_length)) + 80;
  const std::size_t count = wave.components().size();
  table.values.resize(count * (table.largest + 1));
  for (std::size_t n = 0; n < count; ++n) {
    const double a = wave.components()[n].wave_number * half_length;
    for (std::size_t d = 0; d <= table.largest; ++d)
      table.values[n * (table.largest + 1) + d] = std::cyl_bessel_j(static_cast<double>(d), a);
  }
  return table;
}

// The Chebyshev degree D along still water: the smallest with Σ_n |A_n| Σ_{d>D} 2|J_d(k_n L/2)| within
// `budget`; the bound at that degree.
std::size_t line_degree(const WaveField& wave, const BesselTable& bessel, double budget, double& bound) {
  const std::size_t largest = bessel.largest;
  std::vector<double> tail(largest + 2, 0.0);  // tail[D] = Σ_n |A_n| Σ_{d>D} 2|J_d|
  for (std::size_t n = 0; n < wave.components().size(); ++n) {
    const double amplitude = wave.components()[n].amplitude;
    double above = 0.0;
    for (std::size_t d = largest + 1; d-- > 0;) {
      tail[d] += amplitude * above;
      above += 2.0 * std::abs(bessel.at(n, d));
    }
  }
  for (std::size_t d = 0; d <= largest; ++d) {
    if (tail[d] <= budget) {
      bound = tail[d];
      return d;
    }
  }
  throw std::invalid_argument(fmt::format("incident wave record: the hull's x range is too long for the shortest waves (a "
                                          "Chebyshev series of degree {} leaves {:.3g} m > {:.3g} m)", largest, tail[largest],
                                          budget));
}

// Channels of the line, recorded by their real parts: c_d = Re Σ A e^{ik x_c} ε_d i^d J_d(k L/2) e^{−iδωt}.
void add_line_channels(const WaveField& wave, const BesselTable& bessel, double centre, std::size_t degree,
                       hydro::HarmonicSums& sums) {
  const std::size_t count = wave.components().size();
  const std::size_t first = sums.real_parts.size();
  sums.real_parts.resize(first + degree + 1, std::vector<Complex>(count));
  for (std::size_t n = 0; n < count; ++n) {
    const double k = wave.components()[n].wave_number;
    const Complex base = wave.complex_amplitudes()[n] * std::polar(1.0, k * centre);
    Complex power(1.0, 0.0);  // i^d
    for (std::size_t d = 0; d <= degree; ++d) {
      const double weight = (d == 0 ? 1.0 : 2.0) * bessel.at(n, d);
      sums.real_parts[first + d][n] = base * power * weight;
      power *= Complex(0.0, 1.0);
    }
  }
}

// Chebyshev series: derivative (size kept: the top coefficient 0) and antiderivative (one longer).
void chebyshev_derivative(const std::vector<double>& c, std::vector<double>& out) {
  const std::size_t n = c.size();
  out.assign(n, 0.0);
  double next = 0.0, next2 = 0.0;  // c'_{d+1}, c'_{d+2}
  for (std::size_t d = n - 1; d >= 1; --d) {
    const double value = next2 + 2.0 * static_cast<double>(d) * c[d];  // c'_{d−1}
    out[d - 1] = value;
    next2 = next;
    next = value;
  }
  out[0] *= 0.5;
}

void chebyshev_integral(const std::vector<double>& c, std::vector<double>& out) {
  const std::size_t n = c.size();
  out.assign(n + 1, 0.0);
  const auto at = [&](std::size_t d) { return d < n ? c[d] : 0.0; };
  out[1] = at(0) - 0.5 * at(2);
  for (std::size_t d = 2; d <= n; ++d) out[d] = (at(d - 1) - at(d + 1)) / (2.0 * static_cast<double>(d));
}

double clenshaw(const std::vector<double>& c, double x) {
  double b1 = 0.0, b2 = 0.0;
  for (std::size_t d = c.size(); d-- > 1;) {
    const double b0 = 2.0 * x * b1 - b2 + c[d];
    b2 = b1;
    b1 = b0;
  }
  return x * b1 - b2 + c[0];
}

hydro::HarmonicSums empty_sums(const WaveField& wave) {
  hydro::HarmonicSums sums;
  sums.frequency_step = wave.harmonic_grid().frequency_step;
  sums.first_harmonic = static_cast<std::int64_t>(wave.harmonic_grid().first_harmonic);
  sums.time_sign = wave.direction() > 0.0 ? -1 : 1;  // e^{−iδωt}
  return sums;
}

constexpr double bound_window = 5.0;  // [s]

// |ζ| and its x-derivatives over [x_min, x_max] × [0, duration], sampled every sixth of the shortest
// wavelength and at most every twelfth of the shortest period (exactly, by FFT: two real channels per
// transform), the largest per window of bound_window seconds (a sample within one time step of a
// window's edge counts for both windows). Between samples a component's value exceeds the sampled
// largest by at most the factor 1/(cos(k Δx/2) cos(ω Δt/2)) (its crest halfway between two samples in
// x and in t), largest for the shortest component: that factor (1.20 at these spacings) is the margin,
// plus 10⁻¹² Σ|a| per derivative for the transforms' round-off.
void sample_bounds(const WaveField& wave, const IncidentWaveRecordOptions& options, std::vector<double>& elevation,
                   std::vector<double>& slope, std::vector<double>& curvature, std::vector<double>& third) {
  const double shortest = 2.0 * std::numbers::pi / wave.max_wave_number();
  const double span = options.x_max - options.x_min;
  const auto points = static_cast<std::size_t>(std::ceil(span / (shortest / 6.0))) + 1;
  const double spacing = span / static_cast<double>(points - 1);
  double highest_frequency = 0.0;
  for (const WaveComponent& c : wave.components()) highest_frequency = std::max(highest_frequency, c.angular_frequency);
  const auto windows = static_cast<std::size_t>(std::ceil(options.duration / bound_window)) + 1;
  std::array<std::vector<double>*, 4> bounds{&elevation, &slope, &curvature, &third};
  for (std::vector<double>* b : bounds) b->assign(windows, 0.0);
  std::array<double, 4> round_off{};
  double time_step = 0.0;
  hydro::HarmonicSums sums = empty_sums(wave);
  sums.real_parts.assign(4, std::vector<Complex>(wave.components().size()));
  for (std::size_t i = 0; i < points; ++i) {
    const double x = options.x_min + span * static_cast<double>(i) / static_cast<double>(points - 1);
    for (std::size_t n = 0; n < wave.components().size(); ++n) {
      const double k = wave.components()[n].wave_number;
      const Complex at_x = wave.complex_amplitudes()[n] * std::polar(1.0, k * x);
      sums.real_parts[0][n] = at_x;
      sums.real_parts[1][n] = Complex(0.0, k) * at_x;        // ∂/∂x
      sums.real_parts[2][n] = -k * k * at_x;                 // ∂²/∂x²
      sums.real_parts[3][n] = Complex(0.0, -k * k * k) * at_x;  // ∂³/∂x³
    }
    const hydro::HarmonicSamples sampled = hydro::sample_real_parts(sums, std::numbers::pi / (6.0 * highest_frequency));
    time_step = sampled.time_step;
    const std::size_t period = sampled.channels[0].size();
    const auto steps = static_cast<std::size_t>(std::ceil(options.duration / time_step));
    for (std::size_t j = 0; j <= steps; ++j) {
      const double t = static_cast<double>(j) * time_step;
      const auto first = static_cast<std::size_t>(std::max(t - time_step, 0.0) / bound_window);
      const auto last = std::min(static_cast<std::size_t>((t + time_step) / bound_window), windows - 1);
      for (std::size_t d = 0; d < 4; ++d) {
        const double value = std::abs(sampled.channels[d][j % period]);
        for (std::size_t w = first; w <= last; ++w) (*bounds[d])[w] = std::max((*bounds[d])[w], value);
      }
    }
    for (std::size_t d = 0; d < 4; ++d) round_off[d] = std::max(round_off[d], 1e-12 * sampled.magnitude_sums[d]);
  }
  const double margin = 1.0 / (std::cos(0.5 * wave.max_wave_number() * spacing) * std::cos(0.5 * highest_frequency * time_step));
  for (std::size_t d = 0; d < 4; ++d)
    for (double& b : *bounds[d]) b = margin * b + round_off[d];
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
  const double centre = 0.5 * (options.x_min + options.x_max), half_length = 0.5 * (options.x_max - options.x_min);
  double line_bound = 0.0;
  const BesselTable bessel = bessel_table(wave, half_length);
  const std::size_t line = line_degree(wave, bessel, 0.25 * options.tolerance, line_bound);
  add_line_channels(wave, bessel, centre, line, sums);
  hydro::HarmonicRecordOptions record_options;
  record_options.duration = options.duration;
  record_options.tolerance = 0.25 * options.tolerance / static_cast<double>(std::max(degree + 3, line + 1));
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
  const double centre = 0.5 * (options.x_min + options.x_max), half_length = 0.5 * (options.x_max - options.x_min);
  double line_bound = 0.0;
  {
    const BesselTable bessel = bessel_table(wave, half_length);
    out.line_degree_ = line_degree(wave, bessel, 0.25 * options.tolerance, line_bound);
    add_line_channels(wave, bessel, centre, out.line_degree_, sums);
  }
  out.max_wave_number_ = wave.max_wave_number();
  out.period_ = 2.0 * std::numbers::pi / wave.harmonic_grid().frequency_step;
  const std::size_t widest = std::max(out.degree_ + 3, out.line_degree_ + 1);
  hydro::HarmonicRecordOptions record_options;
  record_options.duration = options.duration;
  record_options.tolerance = 0.25 * options.tolerance / static_cast<double>(widest);
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
  stats.interpolation_error = static_cast<double>(widest) * out.record_.midpoint_error();
  stats.line_degree = out.line_degree_;
  stats.line_truncation_bound = line_bound;
  stats.memory_bytes = static_cast<double>(out.record_.memory_bytes());
  sample_bounds(wave, options, out.window_elevation_, out.window_slope_, out.window_curvature_, out.window_third_);
  stats.bound_window = bound_window;
  stats.elevation_bound = *std::max_element(out.window_elevation_.begin(), out.window_elevation_.end());
  stats.slope_bound = *std::max_element(out.window_slope_.begin(), out.window_slope_.end());
  stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void IncidentWaveRecord::at(double t, double ramp, WavePolynomials& out) const {
  const std::size_t per_patch = degree_ + 3;
  out.potential.resize(record_.channels());
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
  out.line.resize(line_degree_ + 1);
  for (std::size_t d = 0; d <= line_degree_; ++d) out.line[d] = ramp * record_.real_channel(out.potential.data(), d);
  chebyshev_derivative(out.line, out.line_rate);
  chebyshev_derivative(out.line_rate, out.line_curvature);
  chebyshev_integral(out.line, out.line_integral);
  chebyshev_integral(out.line_integral, out.line_second_integral);
}

void IncidentWaveRecord::line_elevation(const WavePolynomials& p, double x, double& zeta, double& slope, double& curvature) const {
  const double half_length = 0.5 * (x_max_ - x_min_), scaled = (x - 0.5 * (x_min_ + x_max_)) / half_length;
  zeta = clenshaw(p.line, scaled);
  slope = clenshaw(p.line_rate, scaled) / half_length;
  curvature = clenshaw(p.line_curvature, scaled) / (half_length * half_length);
}

void IncidentWaveRecord::line_elevation(const WavePolynomials& p, double x, double& zeta, double& slope) const {
  const double half_length = 0.5 * (x_max_ - x_min_), scaled = (x - 0.5 * (x_min_ + x_max_)) / half_length;
  zeta = clenshaw(p.line, scaled);
  slope = clenshaw(p.line_rate, scaled) / half_length;
}

void IncidentWaveRecord::line_antiderivatives(const WavePolynomials& p, double x, double& first, double& second) const {
  const double half_length = 0.5 * (x_max_ - x_min_), scaled = (x - 0.5 * (x_min_ + x_max_)) / half_length;
  first = clenshaw(p.line_integral, scaled) * half_length;
  second = clenshaw(p.line_second_integral, scaled) * half_length * half_length;
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

}  // namespace ffrf::sea
