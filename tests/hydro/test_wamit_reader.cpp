// Reading the WAMIT fixture (tests/hydro/data: the 80 m × 10 m × 5 m draft barge of
// WEC-Sim_Applications, README there). Expected values are computed here from the literal file
// lines quoted below and the WAMIT manual's scaling (ch. 4: A = ρ L^k Ā, B = ρ ω L^k B̄ with k = 3, 4,
// 5 for 0, 1, 2 rotational indices; C = ρ g L^(k−1) C̄; X = ρ g L^m X̄ with m = 2 translation, 3
// rotation), and ffrf's pitch sign (WAMIT mode 5 is bow-down: its couplings with surge and heave
// change sign). The run used ρ = 1000 kg/m³, g = 9.81 m/s², ULEN = 1 m (barge.out: "Gravity: 9.81000
// Length scale: 1.00000 ... Water density: 1000.00000"); reading it again with ULEN = 2 checks the
// powers of L.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "hydro/wamit_reader.hpp"

namespace {

using namespace ffrf::hydro;
const std::string kData = std::string(FFRF_SOURCE_DIR "/tests/hydro/data/");

std::size_t index_of(const std::vector<double>& omega, double value) {
  for (std::size_t i = 0; i < omega.size(); ++i)
    if (std::abs(omega[i] - value) < 1e-12 * value) return i;
  return omega.size();
}

TEST(WamitReader, RadiationValuesAreTheFileNumbersTimesTheScaling) {
  const double rho = 1000.0;
  for (double L : {1.0, 2.0}) {
    const auto r = read_wamit_radiation(kData + "barge.1", {L, rho, 9.81});
    ASSERT_TRUE(r.has_zero_frequency);
    ASSERT_TRUE(r.has_infinite_frequency);
    // " -1.000000E+00     1     1  3.557943E+02" ... "5     5  2.403868E+06", " -1.000000E+00     1     5  6.435159E+03"
    EXPECT_DOUBLE_EQ(r.zero_frequency_added_mass(0, 0), 3.557943E+02 * rho * std::pow(L, 3));
    EXPECT_DOUBLE_EQ(r.zero_frequency_added_mass(2, 2), 2.403868E+06 * rho * std::pow(L, 5));
    EXPECT_DOUBLE_EQ(r.zero_frequency_added_mass(0, 2), -6.435159E+03 * rho * std::pow(L, 4));
    EXPECT_DOUBLE_EQ(r.zero_frequency_added_mass(2, 0), -6.435094E+03 * rho * std::pow(L, 4));
    // "  0.000000E+00     3     3  4.334658E+03", "  0.000000E+00     5     1  1.642150E+03"
    EXPECT_DOUBLE_EQ(r.infinite_frequency_added_mass(1, 1), 4.334658E+03 * rho * std::pow(L, 3));
    EXPECT_DOUBLE_EQ(r.infinite_frequency_added_mass(2, 0), -1.642150E+03 * rho * std::pow(L, 4));
    EXPECT_EQ(r.infinite_frequency_added_mass(1, 2), 0.0);  // absent (1,3), (3,5): zero by symmetry
    EXPECT_EQ(r.infinite_frequency_added_mass(0, 1), 0.0);
    // "  6.000002E+00     3     3  3.177641E+03  1.236651E+03"
    // "  6.000002E+00     1     5 -4.948301E+02  3.812040E+03"
    // "  6.000002E+00     5     5  1.574752E+06  5.721268E+05"
    const double omega = 2 * std::numbers::pi / 6.000002;
    const std::size_t i = index_of(r.frequency, omega);
    ASSERT_LT(i, r.frequency.size());
    EXPECT_DOUBLE_EQ(r.added_mass[i](1, 1), 3.177641E+03 * rho * std::pow(L, 3));
    EXPECT_DOUBLE_EQ(r.damping[i](1, 1), 1.236651E+03 * rho * omega * std::pow(L, 3));
    EXPECT_DOUBLE_EQ(r.added_mass[i](0, 2), +4.948301E+02 * rho * std::pow(L, 4));
    EXPECT_DOUBLE_EQ(r.damping[i](0, 2), -3.812040E+03 * rho * omega * std::pow(L, 4));
    EXPECT_DOUBLE_EQ(r.damping[i](2, 2), 5.721268E+05 * rho * omega * std::pow(L, 5));
  }
}

TEST(WamitReader, FrequenciesAscendFromTheLongestPeriod) {
  const auto r = read_wamit_radiation(kData + "barge.1", {1.0, 1000.0, 9.81});
  // 277 finite periods: 0.90 to 30.0 s every 0.15 s, then every 1.5 s to 150 s (README).
  ASSERT_EQ(r.frequency.size(), 275u);
  EXPECT_NEAR(r.frequency.front(), 2 * std::numbers::pi / 1.500000E+02, 1e-15);
  EXPECT_NEAR(r.frequency.back(), 2 * std::numbers::pi / 9.000000E-01, 1e-12);
  for (std::size_t i = 1; i < r.frequency.size(); ++i) EXPECT_GT(r.frequency[i], r.frequency[i - 1]);
  // "  1.500000E+02     5     5  2.405670E+06  2.523773E-01": the longest period is the first ω.
  EXPECT_DOUBLE_EQ(r.damping.front()(2, 2), 2.523773E-01 * 1000.0 * 2 * std::numbers::pi / 150.0);
}

TEST(WamitReader, ExcitationIsTheFileNumbersTimesRhoGLm) {
  for (double L : {1.0, 2.0}) {
    const auto x = read_wamit_excitation(kData + "barge.3", {L, 1000.0, 9.81});
    ASSERT_EQ(x.heading_degrees, std::vector<double>{0.0});
    const std::size_t i = index_of(x.frequency, 2 * std::numbers::pi / 6.000002);
    ASSERT_LT(i, x.frequency.size());
    const double rg = 1000.0 * 9.81;
    // "  6.000002E+00  0.000000E+00     1  7.401694E+01 -8.555367E+01  5.738186E+00 -7.379417E+01"
    EXPECT_DOUBLE_EQ(x.force[0][i](0).real(), 5.738186E+00 * rg * L * L);
    EXPECT_DOUBLE_EQ(x.force[0][i](0).imag(), -7.379417E+01 * rg * L * L);
    // "  6.000002E+00  0.000000E+00     3  5.719780E+01 -1.547127E+02 -5.171697E+01 -2.443243E+01"
    EXPECT_DOUBLE_EQ(x.force[0][i](1).real(), -5.171697E+01 * rg * L * L);
    // "  6.000002E+00  0.000000E+00     5  5.658259E+02 -1.726781E+02 -5.612120E+02 -7.211127E+01"
    EXPECT_DOUBLE_EQ(x.force[0][i](2).real(), +5.612120E+02 * rg * L * L * L);
    EXPECT_DOUBLE_EQ(x.force[0][i](2).imag(), +7.211127E+01 * rg * L * L * L);
  }
}

TEST(WamitReader, HydrostaticsAreTheFileNumbersTimesRhoGLk) {
  for (double L : {1.0, 2.0}) {
    const auto c = read_wamit_hydrostatics(kData + "barge.hst", {L, 1000.0, 9.81});
    // "     3     3   8.000000E+02", "     5     5   4.166521E+05"
    EXPECT_DOUBLE_EQ(c(1, 1), 8.000000E+02 * 1000.0 * 9.81 * L * L);
    EXPECT_DOUBLE_EQ(c(2, 2), 4.166521E+05 * 1000.0 * 9.81 * std::pow(L, 4));
    EXPECT_EQ(c(0, 0), 0.0);
    EXPECT_EQ(c(1, 2), 0.0);
  }
  // Second method: the box's waterplane, C33 = ρ g L B = ρ g 80 × 10, and C55 = ρ g (B L³/12 + V (z_B − z_G))
  // with V = 4000 m³, z_B = −2.5 m, z_G = 0 (barge.out): WAMIT's panel integration within 0.01 %.
  const auto c = read_wamit_hydrostatics(kData + "barge.hst", {1.0, 1000.0, 9.81});
  EXPECT_NEAR(c(1, 1), 1000.0 * 9.81 * 800.0, 1e-4 * c(1, 1));
  EXPECT_NEAR(c(2, 2), 1000.0 * 9.81 * (10.0 * 80.0 * 80.0 * 80.0 / 12.0 - 4000.0 * 2.5), 1e-4 * c(2, 2));
}

// ---- bad files --------------------------------------------------------------------------------

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(path) << text;
  return path.string();
}

void expect_error(const std::string& path, int line, const std::string& fragment, char kind = '1') {
  try {
    if (kind == '1') read_wamit_radiation(path, {1.0, 1000.0, 9.81});
    if (kind == '3') read_wamit_excitation(path, {1.0, 1000.0, 9.81});
    if (kind == 'h') read_wamit_hydrostatics(path, {1.0, 1000.0, 9.81});
    FAIL() << "no error for " << path;
  } catch (const WamitFileError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

const std::string kLimits =
    " -1.0 1 1 1.0\n -1.0 3 3 1.0\n -1.0 5 5 1.0\n"
    "  0.0 1 1 1.0\n  0.0 3 3 1.0\n  0.0 5 5 1.0\n";
std::string period_block(const std::string& per) {
  return per + " 1 1 1.0 0.1\n" + per + " 3 3 1.0 0.1\n" + per + " 5 5 1.0 0.1\n";
}

TEST(WamitReader, ReadsAMinimalFileWithoutHeader) {
  const auto r = read_wamit_radiation(write_file("ok.1", kLimits + period_block("5.0") + period_block("6.0")), {1.0, 1000.0, 9.81});
  EXPECT_EQ(r.frequency.size(), 2u);
  EXPECT_NEAR(r.frequency[0], 2 * std::numbers::pi / 6.0, 1e-15);
}

TEST(WamitReader, NamesNonNumericAndNonFiniteFields) {
  expect_error(write_file("text.1", kLimits + "5.0 1 1 abc 0.1\n"), 7, "field 4 'abc' is not a number");
  expect_error(write_file("nan.1", kLimits + "5.0 1 1 1.0 NaN\n"), 7, "field 5 'NaN' is not a finite number");
  expect_error(write_file("count.1", kLimits + "5.0 1 1 1.0\n"), 7, "4 numbers where 5 are expected");
  expect_error(write_file("mode.1", kLimits + "5.0 1.5 1 1.0 0.1\n"), 7, "mode I (field 2) = 1.5 is not a mode index");
}

TEST(WamitReader, NamesDuplicateAndNonMonotonicPeriods) {
  expect_error(write_file("dup.1", kLimits + period_block("5.0") + period_block("6.0") + period_block("5.0")), 13,
               "period 5 s appears again (its block began at line 7)");
  expect_error(write_file("order.1", kLimits + period_block("5.0") + period_block("6.0") + period_block("5.5")), 13,
               "period 5.5 s follows 6 s: the periods are not monotonic");
  expect_error(write_file("duprow.1", kLimits + period_block("5.0") + "5.0 3 3 1.0 0.1\n"), 10, "entry (3, 3) repeats the one at line 8");
}

TEST(WamitReader, NamesMissingModesAndTheMissingInfiniteFrequencyLimit) {
  expect_error(write_file("nopitch.1", kLimits + "5.0 1 1 1.0 0.1\n5.0 3 3 1.0 0.1\n"), 7,
               "period 5 s: no diagonal entry for mode 5 (pitch)");
  expect_error(write_file("noinf.1", " -1.0 1 1 1.0\n -1.0 3 3 1.0\n -1.0 5 5 1.0\n" + period_block("5.0")), 0,
               "no infinite-frequency limit (rows with PER = 0)");
  const auto r = read_wamit_radiation(write_file("noinf_ok.1", period_block("5.0")), {1.0, 1000.0, 9.81},
                                      WamitRadiationOptions{.require_infinite_frequency = false});
  EXPECT_FALSE(r.has_infinite_frequency);
  expect_error(write_file("nohst.hst", "1 1 0.0\n3 3 1.0\n"), 0, "no diagonal entry for mode 5 (pitch)", 'h');
  expect_error("/nonexistent/barge.1", 0, "cannot open the WAMIT .1 added-mass and damping file");
  expect_error(write_file("header_only.1", " WAMIT Numeric Output -- Filename  x.1\n"), 0, "no data rows");
}

TEST(WamitReader, NamesExcitationInconsistenciesAndMissingHeadings) {
  const std::string good = "5.0 0.0 1 1.0 90.0 0.0 1.0\n5.0 0.0 3 2.0 0.0 2.0 0.0\n5.0 0.0 5 1.0 180.0 -1.0 0.0\n";
  EXPECT_NO_THROW(read_wamit_excitation(write_file("good.3", good), {1.0, 1000.0, 9.81}));
  expect_error(write_file("polar.3", "5.0 0.0 1 1.0 90.0 1.0 0.0\n"), 1, "modulus/phase (1, 90 deg) and Re/Im (1, 0) disagree", '3');
  expect_error(write_file("heading.3", good + "6.0 0.0 1 1.0 90.0 0.0 1.0\n6.0 0.0 3 1.0 0.0 1.0 0.0\n"), 4,
               "period 6 s, heading 0 deg: no row for mode 5 (pitch)", '3');
  expect_error(write_file("limit.3", "0.0 0.0 1 1.0 90.0 0.0 1.0\n"), 1, "excitation is defined at finite periods only", '3');
}

}  // namespace
