// The floating hull's water detectors (multibody/run_monitor.hpp) against hand geometry: a deck
// edge at (x, y_deck) in the hull frame lies at y_G1 + x sin θ + y_deck cos θ; a box of half
// extents (a, b) turned by θ reaches y_G2 − a |sin θ| − b |cos θ|; both are "under water" below the
// lowest wave trough −ζ_a. Capsize (|θ| ≥ 90°) stops the run.
#include <gtest/gtest.h>

#include <cmath>

#include "solve/failure.hpp"
#include "multibody/run_monitor.hpp"
#include "multibody/crane_run.hpp"

namespace ffrf::multibody {
namespace water_detectors_test {

// The reference hull (90 m box, G1 13 m aft of mid-length, 6 m above the keel, 8 m deep) and cargo
// (20 m × 10 m) in a 1 m wave.
MonitorLimits reference_limits() {
  MonitorLimits limits;
  limits.water = {true, 13.0 - 45.0, 13.0 + 45.0, 8.0 - 6.0, 10.0, 5.0, 0.5};
  return limits;
}

CraneOutputs sample(double hull_y, double pitch, double cargo_y, double cargo_pitch) {
  CraneOutputs s;
  s.hull = Eigen::Vector3d(0.0, hull_y, pitch);
  s.cargo = Eigen::Vector3d(80.0, cargo_y, cargo_pitch);
  return s;
}

const Detection* find(const std::vector<Detection>& found, FailureKind kind) {
  for (const Detection& d : found) {
    if (d.kind == kind) return &d;
  }
  return nullptr;
}

TEST(WaterDetectors, DryRunHasNoDetection) {
  RunResult run;
  run.time = {0.0, 1.0};
  run.samples = {sample(-1.0, 0.0, 90.0, 0.0), sample(-1.2, 0.01, 89.0, 0.05)};
  const auto found = post_run_detections(run, reference_limits());
  EXPECT_EQ(find(found, FailureKind::deck_submerged), nullptr);
  EXPECT_EQ(find(found, FailureKind::cargo_in_water), nullptr);
}

TEST(WaterDetectors, BowDeckUnderWaterAtTheFirstSampleBelowTheTrough) {
  RunResult run;
  run.time = {0.0, 1.0, 2.0, 3.0};
  const double pitch = -0.05;  // bow down
  run.samples = {sample(-1.0, 0.0, 90.0, 0.0), sample(-1.0, -0.01, 90.0, 0.0), sample(-1.0, pitch, 90.0, 0.0),
                 sample(-1.0, 0.0, 90.0, 0.0)};
  const auto found = post_run_detections(run, reference_limits());
  const Detection* deck = find(found, FailureKind::deck_submerged);
  ASSERT_NE(deck, nullptr);
  // Bow deck edge: −1 + 58 sin(−0.05) + 2 cos(−0.05) = −1.9017 m, 1.4017 m below the trough −0.5 m;
  // at θ = −0.01: −1 − 0.58 + 2.0 = +0.42: dry.
  EXPECT_EQ(deck->time, 2.0);
  EXPECT_NEAR(deck->value, -0.5 + 1.0 + 58.0 * std::sin(0.05) - 2.0 * std::cos(0.05), 1e-12);
  EXPECT_FALSE(deck->fatal);
  EXPECT_NE(deck->cause.find("the bow deck edge"), std::string::npos) << deck->cause;
  EXPECT_FALSE(deck->remedy.empty());
}

TEST(WaterDetectors, CargoCornerDipsWhenTurned) {
  RunResult run;
  run.time = {0.0, 1.0, 2.0};
  // Level: the bottom 5 m below G2; turned 90°: the 10 m half length hangs down.
  run.samples = {sample(-1.0, 0.0, 6.0, 0.0), sample(-1.0, 0.0, 9.0, 1.5707963267948966), sample(-1.0, 0.0, 4.0, 0.0)};
  const auto found = post_run_detections(run, reference_limits());
  const Detection* cargo = find(found, FailureKind::cargo_in_water);
  ASSERT_NE(cargo, nullptr);
  EXPECT_EQ(cargo->time, 1.0);                           // 9 − 10 = −1 < −0.5 (level at 6: 6 − 5 = 1 > −0.5)
  EXPECT_NEAR(cargo->value, -0.5 - (9.0 - 10.0), 1e-9);  // the deepest: 0.5 m at t = 1 and at t = 2 (4 − 5)
  EXPECT_NE(cargo->cause.find("no water forces on the cargo"), std::string::npos);
}

TEST(WaterDetectors, CargoPitchedPastNinetyDegreesIsNamedWithWhenAndHowFar) {
  // The cargo hangs below its hook; turned past 90° its centre rises above the hook's level. The
  // detection gives the first sample beyond the limit and the largest |pitch| (here 341°: over the top).
  RunResult run;
  run.time = {0.0, 1.0, 2.0, 3.0, 4.0};
  const double degree = std::acos(-1.0) / 180.0;
  run.samples = {sample(-1.0, 0.0, 90.0, 0.0), sample(-1.0, 0.0, 90.0, -89.0 * degree),
                 sample(-1.0, 0.0, 90.0, -91.0 * degree), sample(-1.0, 0.0, 90.0, 341.0 * degree),
                 sample(-1.0, 0.0, 90.0, 10.0 * degree)};
  const auto found = post_run_detections(run, reference_limits());
  const Detection* over = find(found, FailureKind::cargo_overturned);
  ASSERT_NE(over, nullptr);
  EXPECT_EQ(over->time, 2.0);
  EXPECT_NEAR(over->value, 341.0 * degree, 1e-12);
  EXPECT_FALSE(over->fatal);
  EXPECT_NE(over->cause.find("over the top of the hook"), std::string::npos) << over->cause;
  EXPECT_FALSE(over->remedy.empty());
  // 89° is within the limit: no detection.
  run.samples = {sample(-1.0, 0.0, 90.0, 0.0), sample(-1.0, 0.0, 90.0, 89.0 * degree)};
  run.time = {0.0, 1.0};
  EXPECT_EQ(find(post_run_detections(run, reference_limits()), FailureKind::cargo_overturned), nullptr);
}

TEST(WaterDetectors, CapsizeStopsTheRun) {
  DivergenceWatch watch(reference_limits(), "TEST");
  EXPECT_NO_THROW(watch.observe(0.0, sample(-1.0, 1.5, 90.0, 0.0)));  // 86°: not yet (the deck check is post-run)
  try {
    watch.observe(1.0, sample(-1.0, -1.6, 90.0, 0.0));
    FAIL() << "a hull at -91.7 deg was not named";
  } catch (const SolverFailure& failure) {
    EXPECT_EQ(failure.kind(), FailureKind::capsize);
    EXPECT_EQ(to_string(failure.kind()), "capsize");
    EXPECT_NEAR(failure.value(), -1.6 * 180.0 / 3.14159265358979323846, 1e-9);
    EXPECT_EQ(failure.time(), 1.0);
  }
}

TEST(WaterDetectors, HubHasNoWater) {
  MonitorLimits limits;  // water.floating = false
  DivergenceWatch watch(limits, "TEST");
  EXPECT_NO_THROW(watch.observe(0.0, sample(-100.0, 3.0, -100.0, 0.0)));
  RunResult run;
  run.time = {0.0};
  run.samples = {sample(-100.0, 3.0, -100.0, 0.0)};
  EXPECT_TRUE(post_run_detections(run, limits).empty());
}

}  // namespace water_detectors_test
}  // namespace ffrf::multibody
