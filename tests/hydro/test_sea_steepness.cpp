// The significant steepness of a sea state against hand values: λp = g Tp²/(2π), DNV-RP-C205's
// limit 1/15 up to Tp = 8 s, 1/25 from 15 s, linear between (its midpoint at 11.5 s is the mean).
#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>

#include "hydro/sea_steepness.hpp"

namespace {

using ffrf::hydro::sea_steepness;

TEST(SeaSteepness, AStormOfShortPeriodBreaksAndALongerOneDoesNot) {
  // Tp = 5 s: λp = 9.81 · 25 / (2π) = 39.033 m; Hs = 3 m is Sp = 0.0769 > 1/15: breaking; at most 2.602 m.
  const auto short_sea = sea_steepness(3.0, 5.0, 9.81);
  EXPECT_NEAR(short_sea.peak_wavelength, 9.81 * 25.0 / (2.0 * std::numbers::pi), 1e-12);
  EXPECT_NEAR(short_sea.steepness, 3.0 / 39.0329, 1e-5);
  EXPECT_DOUBLE_EQ(short_sea.limit, 1.0 / 15.0);
  EXPECT_TRUE(short_sea.breaking());
  EXPECT_NEAR(short_sea.largest_height(), 39.0329 / 15.0, 1e-4);
  EXPECT_FALSE(sea_steepness(3.0, 7.0, 9.81).breaking());  // λp = 76.5 m: Sp = 0.039
  EXPECT_NEAR(sea_steepness(1.0, 11.5, 9.81).limit, 0.5 * (1.0 / 15.0 + 1.0 / 25.0), 1e-15);
  EXPECT_DOUBLE_EQ(sea_steepness(1.0, 20.0, 9.81).limit, 1.0 / 25.0);
  EXPECT_THROW(sea_steepness(1.0, 0.0, 9.81), std::invalid_argument);
}

}  // namespace
