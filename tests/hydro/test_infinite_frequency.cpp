// A∞ of a table without it (hydro/infinite_frequency.hpp). Independent references: the Lorentzian
// pair's closed form (A(ω) − A∞ = −ab/(a² + ω²) for B = ba²/(a² + ω²)), and the WAMIT fixture, which
// HAS A∞ (its PER = 0 rows, computed by WAMIT directly): the estimates from its A(ω), B(ω) alone must
// reproduce it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hydro/infinite_frequency.hpp"
#include "hydro/wamit_reader.hpp"
#include "kernel_pairs.hpp"

namespace {

using namespace ffrf::hydro;
const std::string kData = std::string(FFRF_SOURCE_DIR "/tests/hydro/data/");

// The Lorentzian heave table with its exact A(ω), B(ω) sampled every dω to 40 rad/s. The estimates
// differ from A∞ only by the linear interpolation of B, which is second order in dω: measured worst
// per-frequency error (at the lowest ω) 5085, 1251, 309 kg at dω = 0.05, 0.025, 0.0125 rad/s
// (2.0·10⁻³ of b/a = |A(0) − A∞| at 0.05); the median over the frequencies 0.004 kg.
double worst_error(const PlanarRadiation& r, double a_inf) {
  double worst = 0.0;
  for (const PlanarMatrix& m : kramers_kronig_estimates(r)) worst = std::max(worst, std::abs(m(1, 1) - a_inf));
  return worst;
}

PlanarRadiation lorentzian_table(double d_omega, double a_inf) {
  const test::Lorentzian pair;
  PlanarRadiation r = test::heave_only(pair, d_omega, 40.0, a_inf);
  for (std::size_t k = 0; k < r.frequency.size(); ++k) r.added_mass[k](1, 1) = a_inf + pair.added_mass_change(r.frequency[k]);
  r.has_infinite_frequency = false;
  return r;
}

TEST(InfiniteFrequency, KramersKronigOfTheLorentzianConvergesToItsAInfinity) {
  const test::Lorentzian pair;
  const double a_inf = 3.0e6, scale = pair.b / pair.a;  // |A(0) − A∞| = b/a
  const PlanarRadiation r = lorentzian_table(0.05, a_inf);
  ASSERT_EQ(kramers_kronig_estimates(r).size(), r.frequency.size() - 2);  // ω = 0 and the last frequency give none
  const double coarse = worst_error(r, a_inf), fine = worst_error(lorentzian_table(0.025, a_inf), a_inf);
  EXPECT_LT(coarse, 2.5e-3 * scale);
  EXPECT_NEAR(coarse / fine, 4.0, 0.5);  // second order: the interpolation of B
  const InfiniteFrequencyEstimate e = estimate_infinite_frequency_added_mass(r, InfiniteFrequencyMethod::kramers_kronig);
  EXPECT_NEAR(e.added_mass(1, 1), a_inf, 1e-5 * scale);
  EXPECT_EQ(e.added_mass(0, 0), 0.0);  // no damping, no added mass: nothing invented
  // The high-frequency end: A = A∞ − ab/(a² + ω²) ≈ A∞ − ab/ω² near 40 rad/s, which A∞ + c/ω² fits.
  EXPECT_NEAR(e.high_frequency(1, 1), a_inf, 1e-4 * scale);
  const PlanarRadiation with = with_infinite_frequency(r, e);
  EXPECT_TRUE(with.has_infinite_frequency);
  EXPECT_EQ(with.infinite_frequency_added_mass(1, 1), e.added_mass(1, 1));
}

// The WAMIT barge (275 frequencies, 0.042–6.98 rad/s) with its A∞ hidden. Measured: Kramers–Kronig
// (median of 274 estimates) within 0.13 % (surge), 1.4·10⁻⁶ (heave), 6.5·10⁻⁵ (pitch), 0.016 % (the
// surge–pitch coupling A15) and 0.14 % (A51) of the file's A∞; the high-frequency end (A∞ + c/ω² over
// the last 5 frequencies) within 1.3 %, 0.03 %, 0.02 % and 0.3 %.
TEST(InfiniteFrequency, EstimatesFromTheWamitBargesDampingReproduceItsAInfinity) {
  PlanarRadiation r = read_wamit_radiation(kData + "barge.1", {1.0, 1000.0, 9.81});
  ASSERT_TRUE(r.has_infinite_frequency);
  const PlanarMatrix file = r.infinite_frequency_added_mass;
  r.has_infinite_frequency = false;
  r.infinite_frequency_added_mass.setZero();
  const InfiniteFrequencyEstimate kk = estimate_infinite_frequency_added_mass(r, InfiniteFrequencyMethod::kramers_kronig);
  EXPECT_EQ(kk.method, InfiniteFrequencyMethod::kramers_kronig);
  EXPECT_EQ(kk.added_mass, kk.kramers_kronig);
  const double kk_bound[3][3] = {{3e-3, 0, 1e-3}, {0, 1e-5, 0}, {3e-3, 0, 2e-4}};
  const double hf_bound[3][3] = {{2.5e-2, 0, 1e-2}, {0, 1e-3, 0}, {1e-2, 0, 1e-3}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (file(i, j) == 0.0) continue;  // heave couplings: zero by the barge's symmetry
      EXPECT_NEAR(kk.added_mass(i, j), file(i, j), kk_bound[i][j] * std::abs(file(i, j))) << i << j;
      EXPECT_NEAR(kk.high_frequency(i, j), file(i, j), hf_bound[i][j] * std::abs(file(i, j))) << i << j;
    }
  const InfiniteFrequencyEstimate hf = estimate_infinite_frequency_added_mass(r, InfiniteFrequencyMethod::high_frequency);
  EXPECT_EQ(hf.added_mass, hf.high_frequency);
  EXPECT_EQ(hf.high_frequency_points, 5);
}

TEST(InfiniteFrequency, TooShortATableIsRefused) {
  PlanarRadiation r = test::heave_only(test::Lorentzian{}, 1.0, 1.0);  // ω = 0 and 1 only
  EXPECT_THROW(kramers_kronig_estimates(r), std::invalid_argument);
}

}  // namespace
