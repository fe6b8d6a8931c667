// The operability chart's limit contour against fields whose level lines are known: a field linear
// in x and y (linear interpolation along the edges is exact, so every end point lies on the line),
// a missing value (its squares are left out), and a saddle (two segments, paired by the centre).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "report/operability_chart.hpp"

namespace ffrf::report {
namespace {

TEST(OperabilityChart, TheLimitContourOfALinearFieldLiesOnItsLevelLine) {
  const std::vector<double> x{5.0, 6.0, 7.0, 8.0}, y{0.5, 1.0, 1.5};
  std::vector<double> u;
  for (double yj : y) {
    for (double xi : x) u.push_back(0.1 * xi + 0.4 * yj + 0.013);  // u = 1 on 0.1 x + 0.4 y = 0.987
  }
  const auto segments = level_contour(x, y, u, 1.0);
  ASSERT_FALSE(segments.empty());
  for (const ContourSegment& s : segments) {
    EXPECT_NEAR(0.1 * s.x0 + 0.4 * s.y0, 0.987, 1e-14);
    EXPECT_NEAR(0.1 * s.x1 + 0.4 * s.y1, 0.987, 1e-14);
  }
  // The line runs from (7.87, 0.5) to (5.87, 1) through three squares of the lower row, then from
  // (5.87, 1) to the edge x = 5 at y = 1.2175 in one square of the upper row: a segment per square.
  EXPECT_EQ(segments.size(), 4u);
}

TEST(OperabilityChart, SquaresWithAMissingCellAreLeftOutAndASaddleGivesTwoSegments) {
  const std::vector<double> x{0.0, 1.0}, y{0.0, 1.0};
  EXPECT_TRUE(level_contour(x, y, {0.5, 2.0, std::nan(""), 2.0}, 1.0).empty());
  // (0, 0) and (1, 1) above, (1, 0) and (0, 1) below; the centre (mean 1.25) is above: each low corner is cut off.
  const auto saddle = level_contour(x, y, {2.0, 0.5, 0.5, 2.0}, 1.0);  // (0,0), (1,0), (0,1), (1,1)
  ASSERT_EQ(saddle.size(), 2u);
  for (const ContourSegment& s : saddle) {
    // Each segment cuts off one of the low corners (1, 0) or (0, 1): both its ends are 1/3 from it.
    const bool near_corner1 = std::abs(s.x0 - 1.0) < 0.5 && std::abs(s.x1 - 1.0) < 0.5;
    const double cx = near_corner1 ? 1.0 : 0.0, cy = near_corner1 ? 0.0 : 1.0;
    EXPECT_NEAR(std::hypot(s.x0 - cx, s.y0 - cy), 1.0 / 3.0, 1e-14);
    EXPECT_NEAR(std::hypot(s.x1 - cx, s.y1 - cy), 1.0 / 3.0, 1e-14);
  }
}

}  // namespace
}  // namespace ffrf::report
