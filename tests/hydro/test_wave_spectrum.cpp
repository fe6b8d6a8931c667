// Wave spectra against their definitions: ∫S dω = Hs²/16 by an independent Simpson rule on the
// substitution u = (ωp/ω)⁴ (which maps the ω⁻⁵ tail onto a finite interval), the peak at ωp by a
// golden-section search on S, PM moments against Γ-function closed forms, DNV's A_γ error; the band
// rule against PM's closed-form cumulative variance and JONSWAP's Hs²/16 by Simpson's rule.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hydro/wave_spectrum.hpp"

namespace {

using namespace ffrf::hydro;

// ∫₀^∞ ω^n S(ω) dω split at ωp: above, ω = ωp / w (w ∈ (0, 1], dω = ωp w⁻² dw, so the ω⁻⁵ tail
// becomes the smooth w^(3−n)); below, ω = ωp v. Composite Simpson with many points on each side.
double independent_moment(const WaveSpectrum& s, int n) {
  const double wp = 2 * std::numbers::pi / s.peak_period;
  auto above = [&](double w) {
    if (w <= 0) return 0.0;  // the limit of ωp^(n+1) w^(n−2) S(ωp/w) for n ≤ 2
    const double omega = wp / w;
    return std::pow(omega, n) * spectral_density(s, omega) * wp / (w * w);
  };
  auto below = [&](double v) { return std::pow(wp * v, n) * spectral_density(s, wp * v) * wp; };
  auto simpson = [](auto f, int m) {
    const double h = 1.0 / m;
    double sum = f(0.0) + f(1.0);
    for (int i = 1; i < m; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
    return sum * h / 3.0;
  };
  return simpson(above, 200000) + simpson(below, 200000);
}

double golden_section_peak(const WaveSpectrum& s, double a, double b) {
  const double r = (std::sqrt(5.0) - 1) / 2;
  double c = b - r * (b - a), d = a + r * (b - a);
  for (int i = 0; i < 200 && b - a > 1e-13; ++i) {
    if (spectral_density(s, c) > spectral_density(s, d)) b = d; else a = c;
    c = b - r * (b - a);
    d = a + r * (b - a);
  }
  return 0.5 * (a + b);
}

TEST(WaveSpectrum, PiersonMoskowitzIntegratesToHsSquaredOver16) {
  const auto s = pierson_moskowitz(2.0, 8.0);
  EXPECT_NEAR(independent_moment(s, 0), 0.25, 0.25 * 1e-9);
  EXPECT_NEAR(spectral_moment(s, 0), 0.25, 0.25 * 1e-14);
}

TEST(WaveSpectrum, ExactJonswapIntegratesToHsSquaredOver16) {
  for (double gamma : {1.0, 2.0, 3.3, 5.0, 7.0}) {
    const auto s = jonswap(3.0, 10.0, gamma);
    const double target = 9.0 / 16.0;
    EXPECT_NEAR(independent_moment(s, 0), target, target * 1e-8) << "gamma " << gamma;
    EXPECT_NEAR(spectral_moment(s, 0), target, target * 1e-12) << "gamma " << gamma;
  }
}

TEST(WaveSpectrum, DnvNormalisationErrorIsTheDocumentedFewPercent) {
  // DNV-RP-C205: A_γ = 1 − 0.287 ln γ is an approximation; its m0 error is measured here.
  for (double gamma : {1.0, 2.0, 3.3, 5.0, 7.0}) {
    const auto dnv = jonswap(3.0, 10.0, gamma, JonswapNormalisation::dnv);
    const auto exact = jonswap(3.0, 10.0, gamma, JonswapNormalisation::exact);
    const double relative = independent_moment(dnv, 0) / (9.0 / 16.0) - 1.0;
    EXPECT_LT(std::abs(relative), 0.02) << "gamma " << gamma;
    EXPECT_NEAR(dnv.normalisation_factor / exact.normalisation_factor - 1.0, relative, 1e-7) << "gamma " << gamma;
    if (gamma == 1.0) {
      EXPECT_NEAR(relative, 0.0, 1e-9);  // γ = 1: both are PM
    }
  }
}

TEST(WaveSpectrum, PeakIsAtTheGivenPeriod) {
  for (double gamma : {1.0, 3.3, 7.0}) {
    const auto s = jonswap(2.0, 8.0, gamma);
    const double wp = 2 * std::numbers::pi / 8.0;
    EXPECT_NEAR(golden_section_peak(s, 0.5 * wp, 2.0 * wp), wp, 1e-6 * wp) << "gamma " << gamma;
  }
}

TEST(WaveSpectrum, PiersonMoskowitzMomentsMatchTheGammaFunctionClosedForm) {
  // m_n = (Hs²/16) ωp^n (5/4)^(n/4) Γ(1 − n/4): derived by the substitution u = (5/4)(ωp/ω)⁴.
  const auto s = pierson_moskowitz(2.0, 8.0);
  const double wp = 2 * std::numbers::pi / 8.0;
  const double m1 = 0.25 * wp * std::pow(1.25, 0.25) * std::tgamma(0.75);
  const double m2 = 0.25 * wp * wp * std::sqrt(1.25) * std::sqrt(std::numbers::pi);
  EXPECT_NEAR(independent_moment(s, 1), m1, m1 * 1e-8);
  EXPECT_NEAR(independent_moment(s, 2), m2, m2 * 1e-6);
  // Zero-crossing period Tz = 2π sqrt(m0/m2) = Tp / sqrt(sqrt(5π)/2) = 0.7104 Tp (DNV-RP-C205 for γ = 1).
  EXPECT_NEAR(2 * std::numbers::pi * std::sqrt(spectral_moment(s, 0) / spectral_moment(s, 2)) / 8.0, 0.71033, 1e-4);
}

TEST(WaveSpectrum, JonswapMomentsAgreeWithTheIndependentIntegral) {
  const auto s = jonswap(2.0, 8.0, 3.3);
  for (int n : {1, 2}) {
    const double independent = independent_moment(s, n);
    EXPECT_NEAR(spectral_moment(s, n), independent, independent * 1e-6) << "m" << n;
  }
  EXPECT_THROW(spectral_moment(s, 4), std::domain_error);
}

TEST(WaveSpectrum, EnergyBandLeavesTheRequestedTails) {
  const auto s = jonswap(2.0, 8.0, 3.3);
  const auto band = energy_band(s, 1e-3);
  const double m0 = spectral_moment(s, 0);
  EXPECT_NEAR(spectral_moment(s, 0, 0.0, band.lower) / m0, 5e-4, 1e-6);
  EXPECT_NEAR(spectral_moment(s, 0, band.upper, 200 * s.peak_frequency()) / m0, 5e-4, 1e-6);
}

// Simpson's rule of S over [a, b] with m (even) intervals: the band's variance, independent of
// ffrf's Gauss–Legendre panels.
double simpson_variance(const WaveSpectrum& s, double a, double b, int m) {
  const double h = (b - a) / m;
  double sum = spectral_density(s, a) + spectral_density(s, b);
  for (int i = 1; i < m; ++i) sum += (i % 2 ? 4.0 : 2.0) * spectral_density(s, a + i * h);
  return sum * h / 3.0;
}

TEST(WaveSpectrum, VarianceBandOfPiersonMoskowitzIsItsClosedFormQuantiles) {
  // PM's cumulative variance is m0 exp(−(5/4)(ωp/ω)⁴), so the band holding a share p with the rest
  // split equally has the edges ωp (1.25 / ln(2/(1−p)))^¼ and ωp (1.25 / ln(2/(1+p)))^¼.
  for (double tp : {6.0, 12.0}) {
    const auto s = pierson_moskowitz(2.5, tp);
    const double wp = 2 * std::numbers::pi / tp;
    for (double share : {0.99, 0.995, 0.999}) {
      const auto band = variance_band(s, share);
      EXPECT_NEAR(band.lower, wp * std::pow(1.25 / std::log(2.0 / (1.0 - share)), 0.25), 1e-7 * wp) << tp << " " << share;
      EXPECT_NEAR(band.upper, wp * std::pow(1.25 / std::log(2.0 / (1.0 + share)), 0.25), 1e-7 * wp) << tp << " " << share;
    }
  }
  // The default share's high edge: 4.73 ωp (99.9 %: 7.07 ωp).
  EXPECT_NEAR(variance_band(pierson_moskowitz(2.5, 8.0)).upper / (2 * std::numbers::pi / 8.0), 4.727, 1e-3);
  EXPECT_THROW(variance_band(pierson_moskowitz(2.5, 8.0), 0.4), std::invalid_argument);
  EXPECT_THROW(variance_band(pierson_moskowitz(2.5, 8.0), 1.0), std::invalid_argument);
}

TEST(WaveSpectrum, VarianceBandOfJonswapHoldsTheShareOfHsSquaredOver16) {
  // The exact normalisation makes m0 = Hs²/16; Simpson's rule over the band and over the low tail
  // (independent of the quadrature that chose the edges) holds the share and half the rest.
  for (double gamma : {1.0, 3.3, 7.0}) {
    const auto s = jonswap(2.0, 9.0, gamma);
    const double m0 = 2.0 * 2.0 / 16.0;
    const auto band = variance_band(s, 0.995);
    EXPECT_NEAR(simpson_variance(s, band.lower, band.upper, 400000) / m0, 0.995, 1e-7) << gamma;
    EXPECT_NEAR(simpson_variance(s, 1e-9, band.lower, 400000) / m0, 0.0025, 1e-7) << gamma;
  }
  // JONSWAP γ = 3.3 concentrates the variance at the peak: its band ends at 4.3 ωp, not PM's 4.73.
  EXPECT_NEAR(variance_band(jonswap(2.0, 9.0, 3.3)).upper / (2 * std::numbers::pi / 9.0), 4.3, 0.05);
}

TEST(WaveSpectrum, AnExplicitSynthesisBandOverridesTheRule) {
  const auto s = jonswap(2.0, 9.0, 3.3);
  const auto given = synthesis_band(s, 0.3, 2.0);
  EXPECT_EQ(given.lower, 0.3);
  EXPECT_EQ(given.upper, 2.0);
  const auto rule = synthesis_band(s, 0.0, 0.0, 0.99);
  EXPECT_EQ(rule.lower, variance_band(s, 0.99).lower);
  EXPECT_EQ(rule.upper, variance_band(s, 0.99).upper);
}

TEST(WaveSpectrum, TabulatedSpectrumInterpolatesLinearly) {
  const auto s = tabulated_spectrum({0.5, 1.0, 1.5}, {0.0, 2.0, 0.0});
  EXPECT_DOUBLE_EQ(spectral_density(s, 0.75), 1.0);
  EXPECT_DOUBLE_EQ(spectral_density(s, 2.0), 0.0);
  EXPECT_NEAR(spectral_moment(s, 0), 1.0, 1e-14);  // triangle of base 1, height 2
  EXPECT_DOUBLE_EQ(s.peak_frequency(), 1.0);
}

TEST(WaveSpectrum, BadParametersNameTheValueAndRange) {
  try {
    jonswap(2.0, -8.0, 3.3);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("peak period Tp [s] = -8"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("> 0"), std::string::npos);
  }
  EXPECT_THROW(jonswap(2.0, 8.0, 0.5), std::invalid_argument);
  EXPECT_THROW(pierson_moskowitz(std::nan(""), 8.0), std::invalid_argument);
  EXPECT_THROW(tabulated_spectrum({1.0, 0.5}, {1.0, 1.0}), std::invalid_argument);
}

}  // namespace
