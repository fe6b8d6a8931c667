// Counter-based streams: SplitMix64's published outputs for seed 0 (Vigna's reference
// implementation: the n-th output is mix(n · 0x9E3779B97F4A7C15)), uniform moments and a χ² test of
// the phases, and independence of neighbouring realisations.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "hydro/random_stream.hpp"

namespace {

using namespace ffrf::hydro;

TEST(RandomStream, MixReproducesTheReferenceSplitMix64Sequence) {
  constexpr std::uint64_t gamma = 0x9E3779B97F4A7C15ULL;
  EXPECT_EQ(splitmix64_mix(1 * gamma), 0xE220A8397B1DCDAFULL);
  EXPECT_EQ(splitmix64_mix(2 * gamma), 0x6E789E6AA1B965F4ULL);
  EXPECT_EQ(splitmix64_mix(3 * gamma), 0x06C45D188009454FULL);
}

TEST(RandomStream, UniformDrawsHaveUniformMomentsAndPassChiSquare) {
  const RandomStream stream(42, 7);
  constexpr int n = 200000, bins = 20;
  std::array<int, bins> counts{};
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = stream.uniform(static_cast<std::uint64_t>(i));
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum_sq += u * u;
    ++counts[static_cast<std::size_t>(u * bins)];
  }
  // Mean 1/2 with standard error sqrt(1/12 / n); variance 1/12.
  EXPECT_NEAR(sum / n, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(sum_sq / n - (sum / n) * (sum / n), 1.0 / 12.0, 1e-3);
  double chi2 = 0.0;
  for (int c : counts) chi2 += (c - n / bins) * (c - n / bins) / static_cast<double>(n / bins);
  EXPECT_LT(chi2, 43.8);  // χ²(19 dof) 99.9 % quantile
}

TEST(RandomStream, NeighbouringRealisationsAndSeedsAreUncorrelated) {
  constexpr int n = 100000;
  auto correlation = [&](const RandomStream& a, const RandomStream& b) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += (a.uniform(static_cast<std::uint64_t>(i)) - 0.5) * (b.uniform(static_cast<std::uint64_t>(i)) - 0.5);
    return sum / n * 12.0;  // correlation coefficient, standard error 1/sqrt(n)
  };
  EXPECT_LT(std::abs(correlation(RandomStream(1, 0), RandomStream(1, 1))), 4.0 / std::sqrt(n));
  EXPECT_LT(std::abs(correlation(RandomStream(1, 0), RandomStream(2, 0))), 4.0 / std::sqrt(n));
  EXPECT_NE(RandomStream(1, 2).key(), RandomStream(2, 1).key());
}

TEST(RandomStream, ExponentialDrawsHaveUnitMeanAndAreFinite) {
  const RandomStream stream(3, 0);
  constexpr int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double e = stream.exponential(static_cast<std::uint64_t>(i));
    ASSERT_TRUE(std::isfinite(e));
    sum += e;
  }
  EXPECT_NEAR(sum / n, 1.0, 4.0 / std::sqrt(n));
}

}  // namespace
