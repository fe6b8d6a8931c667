// The added mass made symmetric where BEM files are read (hydro/added_mass_symmetry.hpp), on the
// asymmetric fixture (tests/hydro/data/asymmetric: the WAMIT barge with A15 × 0.9 and A51 × 1.1,
// README there) and on the WAMIT file itself. The expected worst asymmetry is found here from the
// file's own lines (the relative difference of a pair is the same nondimensional or dimensional, and
// the pitch sign flip changes both entries of the pair alike).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "hydro/added_mass_symmetry.hpp"
#include "hydro/wamit_reader.hpp"

namespace {

using namespace ffrf::hydro;
const std::string kData = std::string(FFRF_SOURCE_DIR "/tests/hydro/data/");

struct Worst {
  double relative = 0.0, period = 0.0, a15 = 0.0, a51 = 0.0;
};

// The largest |A15 − A51| / max(|A15|, |A51|) over the rows of a .1 file where the pair is at least
// 5 % of its largest magnitude in the file (A13 and A35 are absent in the fixture: zero).
Worst worst_surge_pitch_asymmetry(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::map<double, std::pair<double, double>> pairs;  // period → (A15, A51)
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    double period = 0.0, value = 0.0;
    int i = 0, j = 0;
    fields >> period >> i >> j >> value;
    if (i == 1 && j == 5) pairs[period].first = value;
    if (i == 5 && j == 1) pairs[period].second = value;
  }
  double largest = 0.0;
  for (const auto& [period, pair] : pairs) largest = std::max({largest, std::abs(pair.first), std::abs(pair.second)});
  Worst worst;
  for (const auto& [period, pair] : pairs) {
    const double size = std::max(std::abs(pair.first), std::abs(pair.second));
    if (size < 0.05 * largest) continue;
    const double relative = std::abs(pair.first - pair.second) / size;
    if (relative > worst.relative) worst = {relative, period, pair.first, pair.second};
  }
  return worst;
}

TEST(AddedMassSymmetry, TheSymmetricPartReplacesEveryAddedMassAndTheWorstPairIsNamed) {
  const WamitScaling scaling{1.0, 1025.0, 9.81};
  const PlanarRadiation read = read_wamit_radiation(kData + "asymmetric/barge.1", scaling);
  PlanarRadiation radiation = read;
  const AddedMassAsymmetry asymmetry = symmetrise_added_mass(radiation);

  const Worst expected = worst_surge_pitch_asymmetry(kData + "asymmetric/barge.1");
  ASSERT_GT(expected.relative, 0.15);  // the fixture's A15 × 0.9 against A51 × 1.1
  EXPECT_NEAR(asymmetry.relative, expected.relative, 1e-9);
  EXPECT_EQ(asymmetry.row, 0);
  EXPECT_EQ(asymmetry.column, 2);
  // ffrf's pitch is bow up (WAMIT's mode 5 bow down): both entries change sign.
  EXPECT_NEAR(asymmetry.upper, -1025.0 * expected.a15, 1e-9 * std::abs(1025.0 * expected.a15));
  EXPECT_NEAR(asymmetry.lower, -1025.0 * expected.a51, 1e-9 * std::abs(1025.0 * expected.a51));
  if (expected.period > 0.0) {
    EXPECT_EQ(asymmetry.where, TableRow::frequency);
    EXPECT_NEAR(asymmetry.angular_frequency, 2.0 * std::numbers::pi / expected.period, 1e-12);
  } else {
    EXPECT_EQ(asymmetry.where, expected.period == 0.0 ? TableRow::infinite_frequency : TableRow::zero_frequency);
  }
  const std::string text = asymmetry.describe();
  EXPECT_NE(text.find("A15"), std::string::npos) << text;
  EXPECT_NE(text.find("A51"), std::string::npos) << text;
  char percent[32];
  std::snprintf(percent, sizeof percent, "(%.3g %%)", 100.0 * asymmetry.relative);
  EXPECT_NE(text.find(percent), std::string::npos) << text;

  const auto expect_symmetric_part = [](const PlanarMatrix& before, const PlanarMatrix& after) {
    EXPECT_TRUE(after.isApprox(after.transpose(), 0.0)) << after;
    EXPECT_TRUE(after.isApprox(0.5 * (before + before.transpose()), 1e-15)) << after;
  };
  expect_symmetric_part(read.zero_frequency_added_mass, radiation.zero_frequency_added_mass);
  expect_symmetric_part(read.infinite_frequency_added_mass, radiation.infinite_frequency_added_mass);
  ASSERT_EQ(radiation.added_mass.size(), read.added_mass.size());
  for (std::size_t k = 0; k < read.added_mass.size(); ++k) {
    expect_symmetric_part(read.added_mass[k], radiation.added_mass[k]);
    EXPECT_EQ(radiation.damping[k], read.damping[k]);  // the damping is left as read
  }
}

TEST(AddedMassSymmetry, TheWamitFileIsSymmetricWithinTheWarningThreshold) {
  PlanarRadiation radiation = read_wamit_radiation(kData + "barge.1", {1.0, 1000.0, 9.81});
  const AddedMassAsymmetry asymmetry = symmetrise_added_mass(radiation);
  const Worst expected = worst_surge_pitch_asymmetry(kData + "barge.1");
  EXPECT_NEAR(asymmetry.relative, expected.relative, 1e-9);
  EXPECT_GT(asymmetry.relative, 0.0);
  EXPECT_LT(asymmetry.relative, asymmetry_warning);  // WAMIT's file: no warning for the shipped scenes
}

}  // namespace
