// Pierson–Moskowitz, JONSWAP and tabulated wave spectra (see wave_spectrum.hpp).
#include "hydro/wave_spectrum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hydro/constants.hpp"
#include "hydro/gauss_legendre.hpp"

namespace ffrf::hydro {

namespace {

constexpr double kPeakHalfWidthSigmas = 12.0;  // γ^exp(−x²/2) − 1 < 1e-31 (γ − 1) beyond 12 σ

void require_spectrum(bool ok, std::string_view what, double value, std::string_view range) {
  if (!ok) throw std::invalid_argument(fmt::format("wave spectrum: {} = {} is invalid; valid range {}", what, value, range));
}

// PM shape for Hs, ωp; exactly 0 where the exponential underflows (ω < ~0.2 ωp).
double pierson_moskowitz_density(double hs, double wp, double w) {
  if (w <= 0.0) return 0.0;
  const double ratio4 = std::pow(wp / w, 4);
  const double exponent = 1.25 * ratio4;
  if (exponent > 700.0) return 0.0;
  return 0.3125 * hs * hs * ratio4 / w * std::exp(-exponent);
}

double peak_enhancement_factor(const WaveSpectrum& s, double wp, double w) {
  const double sigma = w <= wp ? s.sigma_below : s.sigma_above;
  const double x = (w - wp) / (sigma * wp);
  return std::pow(s.peak_enhancement, std::exp(-0.5 * x * x));
}

// ∫ ω^n S_PM (γ^r − 1) dω over the peak region, without A_γ: what JONSWAP adds to PM.
double peak_excess_moment(const WaveSpectrum& s, int order) {
  const double wp = s.peak_frequency();
  const double lo = wp * (1.0 - kPeakHalfWidthSigmas * s.sigma_below);
  const double hi = wp * (1.0 + kPeakHalfWidthSigmas * s.sigma_above);
  auto f = [&](double w) {
    return std::pow(w, order) * pierson_moskowitz_density(s.significant_height, wp, w) * (peak_enhancement_factor(s, wp, w) - 1.0);
  };
  // Split at ωp (the σ switch makes the integrand's second derivative jump there).
  return integrate_panels(f, std::max(lo, 0.0), wp, 400) + integrate_panels(f, wp, hi, 400);
}

// Closed-form PM moment over the whole axis: m_n = (Hs²/16) ωp^n (5/4)^(n/4) Γ(1 − n/4), n < 4.
double pierson_moskowitz_moment(double hs, double wp, int order) {
  return hs * hs / 16.0 * std::pow(wp, order) * std::pow(1.25, order / 4.0) * std::tgamma(1.0 - order / 4.0);
}

double tabulated_density(const WaveSpectrum& s, double w) {
  const auto& x = s.table_frequency;
  if (w < x.front() || w > x.back()) return 0.0;
  const auto it = std::upper_bound(x.begin(), x.end(), w);
  if (it == x.end()) return s.table_density.back();
  const auto i = static_cast<std::size_t>(it - x.begin());
  const double t = (w - x[i - 1]) / (x[i] - x[i - 1]);
  return (1.0 - t) * s.table_density[i - 1] + t * s.table_density[i];
}

}  // namespace

std::string_view to_string(SpectrumKind kind) {
  switch (kind) {
    case SpectrumKind::pierson_moskowitz: return "pierson-moskowitz";
    case SpectrumKind::jonswap: return "jonswap";
    case SpectrumKind::tabulated: return "tabulated";
  }
  return "?";
}

std::string_view to_string(JonswapNormalisation normalisation) {
  return normalisation == JonswapNormalisation::exact ? "exact" : "dnv";
}

double WaveSpectrum::peak_frequency() const {
  if (kind != SpectrumKind::tabulated) return kTwoPi / peak_period;
  const auto it = std::max_element(table_density.begin(), table_density.end());
  return table_frequency[static_cast<std::size_t>(it - table_density.begin())];
}

WaveSpectrum pierson_moskowitz(double significant_height, double peak_period) {
  require_spectrum(std::isfinite(significant_height) && significant_height > 0.0, "significant wave height Hs [m]",
          significant_height, "> 0");
  require_spectrum(std::isfinite(peak_period) && peak_period > 0.0, "peak period Tp [s]", peak_period, "> 0");
  WaveSpectrum s;
  s.kind = SpectrumKind::pierson_moskowitz;
  s.significant_height = significant_height;
  s.peak_period = peak_period;
  return s;
}

double dnv_jonswap_normalisation(double peak_enhancement) { return 1.0 - 0.287 * std::log(peak_enhancement); }

WaveSpectrum jonswap(double significant_height, double peak_period, double peak_enhancement,
                     JonswapNormalisation normalisation, double sigma_below, double sigma_above) {
  WaveSpectrum s = pierson_moskowitz(significant_height, peak_period);
  require_spectrum(std::isfinite(peak_enhancement) && peak_enhancement >= 1.0 && peak_enhancement <= 10.0,
          "peak enhancement factor gamma", peak_enhancement, "[1, 10]");
  require_spectrum(std::isfinite(sigma_below) && sigma_below > 0.0 && sigma_below <= 0.5, "sigma below the peak",
          sigma_below, "(0, 0.5]");
  require_spectrum(std::isfinite(sigma_above) && sigma_above > 0.0 && sigma_above <= 0.5, "sigma above the peak",
          sigma_above, "(0, 0.5]");
  s.kind = SpectrumKind::jonswap;
  s.peak_enhancement = peak_enhancement;
  s.sigma_below = sigma_below;
  s.sigma_above = sigma_above;
  s.normalisation = normalisation;
  if (normalisation == JonswapNormalisation::dnv) {
    s.normalisation_factor = dnv_jonswap_normalisation(peak_enhancement);
  } else {
    const double m0_target = significant_height * significant_height / 16.0;
    s.normalisation_factor = m0_target / (m0_target + peak_excess_moment(s, 0));
  }
  return s;
}

WaveSpectrum tabulated_spectrum(std::vector<double> frequency, std::vector<double> density) {
  if (frequency.size() != density.size() || frequency.size() < 2)
    throw std::invalid_argument(fmt::format(
        "wave spectrum: table has {} frequencies and {} densities; valid: equal sizes, at least 2", frequency.size(),
        density.size()));
  for (std::size_t i = 0; i < frequency.size(); ++i) {
    require_spectrum(std::isfinite(frequency[i]) && frequency[i] >= 0.0, fmt::format("table frequency [{}] [rad/s]", i),
            frequency[i], ">= 0");
    require_spectrum(i == 0 || frequency[i] > frequency[i - 1], fmt::format("table frequency [{}] [rad/s]", i), frequency[i],
            fmt::format("> the previous one ({})", i == 0 ? 0.0 : frequency[i - 1]));
    require_spectrum(std::isfinite(density[i]) && density[i] >= 0.0, fmt::format("table density [{}] [m^2 s/rad]", i),
            density[i], ">= 0");
  }
  WaveSpectrum s;
  s.kind = SpectrumKind::tabulated;
  s.table_frequency = std::move(frequency);
  s.table_density = std::move(density);
  return s;
}

double spectral_density(const WaveSpectrum& s, double omega) {
  if (omega <= 0.0) return 0.0;
  if (s.kind == SpectrumKind::tabulated) return tabulated_density(s, omega);
  const double wp = s.peak_frequency();
  const double pm = pierson_moskowitz_density(s.significant_height, wp, omega);
  if (s.kind == SpectrumKind::pierson_moskowitz) return pm;
  return s.normalisation_factor * pm * peak_enhancement_factor(s, wp, omega);
}

double spectral_moment(const WaveSpectrum& s, int order) {
  if (order < 0) throw std::invalid_argument(fmt::format("spectral moment: order {} < 0", order));
  if (s.kind == SpectrumKind::tabulated)
    return spectral_moment(s, order, s.table_frequency.front(), s.table_frequency.back());
  if (order >= 4)
    throw std::domain_error(fmt::format(
        "spectral moment m{} of a {} spectrum is infinite (ω^-5 tail); give an upper frequency", order, to_string(s.kind)));
  const double wp = s.peak_frequency();
  const double pm = pierson_moskowitz_moment(s.significant_height, wp, order);
  if (s.kind == SpectrumKind::pierson_moskowitz) return pm;
  return s.normalisation_factor * (pm + peak_excess_moment(s, order));
}

double spectral_moment(const WaveSpectrum& s, int order, double omega_lo, double omega_hi) {
  if (!(omega_hi > omega_lo) || omega_lo < 0.0)
    throw std::invalid_argument(fmt::format("spectral moment: range [{}, {}] rad/s; valid 0 <= lo < hi", omega_lo, omega_hi));
  auto f = [&](double w) { return std::pow(w, order) * spectral_density(s, w); };
  if (s.kind == SpectrumKind::tabulated) {
    double sum = 0.0;  // piecewise linear times ω^n: 8 points per segment are exact for n ≤ 14
    const auto& x = s.table_frequency;
    for (std::size_t i = 1; i < x.size(); ++i) {
      const double a = std::max(x[i - 1], omega_lo), b = std::min(x[i], omega_hi);
      if (b > a) sum += integrate_panels(f, a, b, 1);
    }
    return sum;
  }
  // Panels of at most ωp σa / 4 near the peak resolve it; the smooth tails take wider panels.
  const double wp = s.peak_frequency();
  const double fine = 0.25 * wp * std::min(s.sigma_below, s.sigma_above);
  const double peak_lo = std::clamp(wp * 0.5, omega_lo, omega_hi), peak_hi = std::clamp(wp * 2.0, omega_lo, omega_hi);
  auto panels = [](double a, double b, double width) { return std::max(1, static_cast<int>(std::ceil((b - a) / width))); };
  double sum = 0.0;
  if (peak_lo > omega_lo) sum += integrate_panels(f, omega_lo, peak_lo, panels(omega_lo, peak_lo, 0.05 * wp));
  // Split at ωp: the σ switch makes S'' jump there, which a panel across it would not resolve.
  const double split = std::clamp(wp, peak_lo, peak_hi);
  if (split > peak_lo) sum += integrate_panels(f, peak_lo, split, panels(peak_lo, split, fine));
  if (peak_hi > split) sum += integrate_panels(f, split, peak_hi, panels(split, peak_hi, fine));
  if (omega_hi > peak_hi) sum += integrate_panels(f, peak_hi, omega_hi, panels(peak_hi, omega_hi, 0.1 * wp));
  return sum;
}

FrequencyBand energy_band(const WaveSpectrum& s, double tail_fraction) {
  require_spectrum(tail_fraction > 0.0 && tail_fraction < 0.5, "energy band tail fraction", tail_fraction, "(0, 0.5)");
  const double wp = s.peak_frequency();
  const double top = s.kind == SpectrumKind::tabulated ? s.table_frequency.back() : 200.0 * wp;
  const double bottom = s.kind == SpectrumKind::tabulated ? s.table_frequency.front() : 0.0;
  // The whole axis' m0 (parametric: PM's closed form plus the peak's quadrature), not the integral up
  // to `top`: the high edge sits where S is small, so 1e-9 of m0 left out would move it by ~1e-6 ωp.
  const double m0 = s.kind == SpectrumKind::tabulated ? spectral_moment(s, 0, bottom, top) : spectral_moment(s, 0);
  auto solve = [&](double target) {  // cumulative(ω) = target by bisection
    double lo = bottom, hi = top;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (mid > bottom && spectral_moment(s, 0, bottom, mid) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  return {solve(0.5 * tail_fraction * m0), solve((1.0 - 0.5 * tail_fraction) * m0)};
}

FrequencyBand variance_band(const WaveSpectrum& s, double variance_share) {
  require_spectrum(variance_share > 0.5 && variance_share < 1.0, "variance share of the band", variance_share, "(0.5, 1)");
  return energy_band(s, 1.0 - variance_share);
}

FrequencyBand synthesis_band(const WaveSpectrum& s, double omega_min, double omega_max, double variance_share) {
  if (omega_min == 0.0 && omega_max == 0.0) return variance_band(s, variance_share);
  return {omega_min, omega_max};
}

}  // namespace ffrf::hydro
