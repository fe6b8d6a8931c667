// The superposed wave field against independent references: the regular wave is its one-component
// case; elevation and dynamic pressure are sums of the components' (linearity); the kinematics satisfy
// the linearized equations the field claims to solve — continuity ∂u/∂x + ∂v/∂y = 0, Euler
// ρ ∂u/∂t = −∇p_dynamic, the kinematic free-surface condition v(y = 0) = ∂ζ/∂t — checked by central
// differences of the field's own elevation and pressure; bad components are named.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "sea/wave_field.hpp"

namespace wave_field_test {

using namespace ffrf::sea;
constexpr double rho = 1025.0, g = 9.81, pi = std::numbers::pi;
const double deep = std::numeric_limits<double>::infinity();

// A small irregular sea: five components between 0.4 and 1.6 rad/s with arbitrary phases.
std::vector<ComponentSpec> sea() {
  return {{0.4, 0.3, 0.1}, {0.62, 0.8, 2.0}, {0.9, 0.5, -1.3}, {1.2, 0.2, 4.0}, {1.6, 0.05, 0.7}};
}

TEST(WaveField, RegularWaveIsTheOneComponentField) {
  for (const double d : {deep, 25.0}) {
    const auto regular = WaveField::regular(1.4, 9.0, -1.0, 2.0, d, g);
    const auto field = WaveField::from_components({{2.0 * pi / 9.0, 0.7, 0.0}}, -1.0, 18.0, d, g);
    ASSERT_EQ(regular.components().size(), 1u);
    for (const double t : {3.0, 20.0, 41.3}) {
      for (const double x : {-30.0, 4.0, 77.0}) {
        EXPECT_EQ(regular.elevation(x, t), field.elevation(x, t));
        for (const double y : {-12.0, -0.3, 0.2}) EXPECT_EQ(regular.pressure(x, y, t, rho), field.pressure(x, y, t, rho));
      }
    }
  }
}

TEST(WaveField, ElevationAndDynamicPressureAreSumsOfTheComponents) {
  for (const double d : {deep, 30.0}) {
    const auto all = WaveField::from_components(sea(), 1.0, 0.0, d, g);
    double zeta_sum = 0.0, dynamic_sum = 0.0;
    const double x = 13.0, y = -6.0, t = 57.0;
    for (const ComponentSpec& c : sea()) {
      const auto one = WaveField::from_components({c}, 1.0, 0.0, d, g);
      zeta_sum += one.elevation(x, t);
      dynamic_sum += one.pressure(x, y, t, rho) - rho * g * (-y);  // wet at y = −6 for every component
    }
    EXPECT_NEAR(all.elevation(x, t), zeta_sum, 1e-14);
    EXPECT_NEAR(all.pressure(x, y, t, rho) - rho * g * (-y), dynamic_sum, 1e-9);
    // Above still water under a crest: the hydrostatic extension of the total elevation.
    const double x_high = [&] {
      double best = 0.0, top = -1e9;
      for (double s = -100.0; s <= 100.0; s += 0.25) {
        if (all.elevation(s, t) > top) top = all.elevation(s, t), best = s;
      }
      return best;
    }();
    const double zeta = all.elevation(x_high, t);
    ASSERT_GT(zeta, 0.2);
    EXPECT_NEAR(all.pressure(x_high, 0.5 * zeta, t, rho), rho * g * 0.5 * zeta, 1e-9);
    EXPECT_EQ(all.pressure(x_high, zeta + 1e-9, t, rho), 0.0);
    EXPECT_GE(all.elevation_bound(t), std::abs(zeta));
  }
}

TEST(WaveField, KinematicsSolveTheLinearizedEquations) {
  const double t = 80.0, h = 1e-4;
  for (const double d : {deep, 40.0}) {
    for (const double direction : {1.0, -1.0}) {
      const auto w = WaveField::from_components(sea(), direction, 10.0, d, g);
      const auto dynamic = [&](double x, double y) { return w.pressure(x, y, t, rho) + rho * g * y; };
      for (const double x : {-21.0, 3.0, 46.0}) {
        for (const double y : {-2.0, -9.0, -25.0}) {
          const Eigen::Vector2d v = w.velocity(x, y, t), a = w.acceleration(x, y, t);
          const double scale = 1.0;  // velocities of order 1 m/s
          const double divergence = (w.velocity(x + h, y, t).x() - w.velocity(x - h, y, t).x()) / (2 * h) +
                                    (w.velocity(x, y + h, t).y() - w.velocity(x, y - h, t).y()) / (2 * h);
          EXPECT_NEAR(divergence, 0.0, 1e-7 * scale) << d << " " << direction;
          const Eigen::Vector2d grad((dynamic(x + h, y) - dynamic(x - h, y)) / (2 * h),
                                     (dynamic(x, y + h) - dynamic(x, y - h)) / (2 * h));
          EXPECT_NEAR(rho * a.x(), -grad.x(), 1e-5 * rho) << x << " " << y;
          EXPECT_NEAR(rho * a.y(), -grad.y(), 1e-5 * rho) << x << " " << y;
          const Eigen::Vector2d rate = (w.velocity(x, y, t + h) - w.velocity(x, y, t - h)) / (2 * h);
          EXPECT_NEAR(a.x(), rate.x(), 1e-7);
          EXPECT_NEAR(a.y(), rate.y(), 1e-7);
          EXPECT_GT(v.norm(), 0.0);
        }
        const double zeta_rate = (w.elevation(x, t + h) - w.elevation(x, t - h)) / (2 * h);
        EXPECT_NEAR(w.velocity(x, 0.0, t).y(), zeta_rate, 1e-8);
        if (!std::isinf(d)) {
          EXPECT_NEAR(w.velocity(x, -d, t).y(), 0.0, 1e-12);  // no flow through the bed
        }
      }
    }
  }
}

TEST(WaveField, NamesTheBadComponent) {
  try {
    WaveField::from_components({{0.5, 1.0, 0.0}, {0.8, -0.2, 0.0}}, 1.0, 0.0, deep, g);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("component 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("amplitude"), std::string::npos) << e.what();
  }
  EXPECT_THROW(WaveField::from_components({{std::nan(""), 1.0, 0.0}}, 1.0, 0.0, deep, g), std::invalid_argument);
  EXPECT_THROW(WaveField::from_components({{0.5, 1.0, deep}}, 1.0, 0.0, deep, g), std::invalid_argument);
  EXPECT_THROW(WaveField::from_components(sea(), 0.0, 0.0, deep, g), std::invalid_argument);
  const WaveField calm;
  EXPECT_EQ(calm.elevation(3.0, 4.0), 0.0);
  EXPECT_EQ(calm.pressure(3.0, -2.0, 4.0, rho), rho * g * 2.0);
}

}  // namespace wave_field_test
