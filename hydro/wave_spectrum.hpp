// One-sided wave spectra S(ω) [m² s/rad] in angular frequency ω [rad/s] (docs/hydrodynamics.md §2):
//   Pierson–Moskowitz / two-parameter Bretschneider (DNV-RP-C205 §3.5.5):
//     S_PM(ω) = (5/16) Hs² ωp⁴ ω⁻⁵ exp(−(5/4)(ω/ωp)⁻⁴),  ωp = 2π/Tp,  ∫₀^∞ S_PM dω = Hs²/16 exactly;
//   JONSWAP (Hasselmann et al. 1973; DNV-RP-C205 §3.5.5):
//     S_J(ω) = A_γ S_PM(ω) γ^exp(−(ω − ωp)² / (2 σ² ωp²)),  σ = σa (ω ≤ ωp), σb (ω > ωp),
//     with A_γ the normalisation: `exact` makes ∫ S_J dω = Hs²/16 (A_γ from a numerical integral,
//     relative accuracy < 1e-12), `dnv` takes DNV-RP-C205's A_γ = 1 − 0.287 ln γ (m0 within a few
//     per cent of Hs²/16; docs give the measured error);
//   tabulated: a user table (ω_i, S_i), linear between points, zero outside.
// Both parametric spectra peak exactly at ωp (the PM factor and the peak-enhancement exponent are
// both stationary there). Spectral moments m_n = ∫ ω^n S dω.
#pragma once

#include <string_view>
#include <vector>

namespace ffrf::hydro {

enum class SpectrumKind { pierson_moskowitz, jonswap, tabulated };
enum class JonswapNormalisation { exact, dnv };

std::string_view to_string(SpectrumKind kind);
std::string_view to_string(JonswapNormalisation normalisation);

struct WaveSpectrum {
  SpectrumKind kind = SpectrumKind::pierson_moskowitz;
  double significant_height = 0.0;  // Hs [m] (parametric kinds)
  double peak_period = 0.0;         // Tp [s] (parametric kinds)
  double peak_enhancement = 1.0;    // γ (JONSWAP)
  double sigma_below = 0.07;        // σa, ω ≤ ωp (JONSWAP)
  double sigma_above = 0.09;        // σb, ω > ωp (JONSWAP)
  JonswapNormalisation normalisation = JonswapNormalisation::exact;
  double normalisation_factor = 1.0;  // A_γ actually used
  std::vector<double> table_frequency;  // tabulated: ω_i [rad/s], strictly increasing, ≥ 0
  std::vector<double> table_density;    // tabulated: S_i [m² s/rad], ≥ 0

  double peak_frequency() const;  // ωp [rad/s] (tabulated: the table's largest S)
};

// Throw std::invalid_argument naming the parameter, its value and the valid range:
// Hs > 0, Tp > 0, 1 ≤ γ ≤ 20, 0 < σ ≤ 0.5; table sizes equal, ≥ 2, ω increasing and ≥ 0, S ≥ 0.
WaveSpectrum pierson_moskowitz(double significant_height, double peak_period);
WaveSpectrum jonswap(double significant_height, double peak_period, double peak_enhancement,
                     JonswapNormalisation normalisation = JonswapNormalisation::exact, double sigma_below = 0.07,
                     double sigma_above = 0.09);
WaveSpectrum tabulated_spectrum(std::vector<double> frequency, std::vector<double> density);

double dnv_jonswap_normalisation(double peak_enhancement);  // 1 − 0.287 ln γ

double spectral_density(const WaveSpectrum& spectrum, double omega);  // S(ω), 0 for ω ≤ 0

// m_n = ∫_{ω_lo}^{ω_hi} ω^n S(ω) dω by composite 8-point Gauss–Legendre on panels that resolve the
// peak (parametric) or the table's segments (tabulated). Default range: the whole axis (parametric
// spectra: the PM tails beyond [0.2 ωp, 20 ωp] are added in closed form for n = 0; for n ≥ 1 the
// range is cut at 40 ωp, where the ω^(n−5) tail is below 1e-6 m_n for n ≤ 2; m_4 of PM/JONSWAP
// diverges logarithmically and is cut there too).
double spectral_moment(const WaveSpectrum& spectrum, int order);
double spectral_moment(const WaveSpectrum& spectrum, int order, double omega_lo, double omega_hi);

// Frequencies below/above which a fraction `tail_fraction`/2 of m0 lies (bisection on the cumulative
// integral): the band a synthesis keeps. tail_fraction in (0, 0.5).
struct FrequencyBand {
  double lower = 0.0, upper = 0.0;
};
FrequencyBand energy_band(const WaveSpectrum& spectrum, double tail_fraction);

// The band rule of a synthesized sea: the band that holds `variance_share` of m0, the rest split
// equally between the low and the high tail (energy_band with tail 1 − share: the cumulative m0 by
// Gauss–Legendre quadrature, each edge by bisection). The default 99.5 % keeps the band's Hs within
// 0.25 % of the spectrum's — well inside the seed-to-seed spread of a most probable maximum — while
// its high edge stays at 4.7 ωp (Pierson–Moskowitz; JONSWAP γ = 3.3: 4.3 ωp) instead of 6.4–7.1 ωp
// for 99.9 %, where short waves cost solver steps and wave components.
inline constexpr double default_variance_share = 0.995;
// variance_share in (0.5, 1). Throws std::invalid_argument naming the share and its valid range.
FrequencyBand variance_band(const WaveSpectrum& spectrum, double variance_share = default_variance_share);
// The band a synthesis uses: [omega_min, omega_max] when given (an explicit band from a scene: both
// non-zero), else variance_band(spectrum, variance_share).
FrequencyBand synthesis_band(const WaveSpectrum& spectrum, double omega_min, double omega_max,
                             double variance_share = default_variance_share);

}  // namespace ffrf::hydro
