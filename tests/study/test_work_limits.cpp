// Work and memory limits (study/work_limits.hpp) against the models they guard: the elastic
// coordinate count and state size estimates against the built crane, the memory limit's edge, the
// output-sample and fixed-step limits of the integrator settings, the reference's finest level;
// and a run whose cargo dips into the sea is named by the monitor (multibody/run_monitor.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "study/reference.hpp"
#include "study/run_pipeline.hpp"
#include "study/work_limits.hpp"
#include "study_test_support.hpp"

namespace ffrf::study {
namespace {

TEST(WorkLimits, EstimatesCoverTheBuiltModel) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  for (const scene::BoomChoice choice : {scene::BoomChoice{scene::BoomKind::nodal, 4},
                                         scene::BoomChoice{scene::BoomKind::modal, 8, 2, true},
                                         scene::BoomChoice{scene::BoomKind::rigid, 1}}) {
    const PreparedRun prepared = prepare_run(scene, choice);
    const int elastic = prepared.equations->elastic_size();
    if (choice.kind == scene::BoomKind::nodal) {
      EXPECT_EQ(elastic_coordinates(choice), elastic) << choice.label();
    } else {
      EXPECT_GE(elastic_coordinates(choice), elastic) << choice.label();
    }
    // The estimate's state (the full-coordinate DAE) is at least the minimal-coordinate ODE's.
    const double state = std::sqrt(newton_matrix_bytes(elastic_coordinates(choice)) / (3.0 * sizeof(double)));
    EXPECT_GE(state, prepared.state_size()) << choice.label();
  }
}

TEST(WorkLimits, MemoryLimitEdge) {
  const int largest = max_nodal_elements();
  EXPECT_LE(newton_matrix_bytes(3 * largest), memory_limit_bytes);
  EXPECT_GT(newton_matrix_bytes(3 * (largest + 1)), memory_limit_bytes);
  EXPECT_NO_THROW(check_run_memory({scene::BoomKind::nodal, largest}));
  try {
    check_run_memory({scene::BoomKind::nodal, 10000});
    FAIL() << "10000 nodal elements passed";
  } catch (const SettingError& error) {
    EXPECT_EQ(error.setting(), Setting::elements);
    EXPECT_EQ(error.value(), "10000");
    EXPECT_NE(error.problem().find("valid range [1, " + std::to_string(largest) + "]"), std::string::npos) << error.problem();
  }
  EXPECT_NO_THROW(check_run_memory({scene::BoomKind::modal, 10000, 12, true}));  // a few coordinates on any mesh
}

TEST(WorkLimits, OutputSamplesAndFixedStepsAreLimitedBeforeAnyRun) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");  // output every 0.05 s
  DynamicsRequest request;
  request.duration = 50001.0;  // 1 000 020 samples
  try {
    (void)integrator_settings(scene, request);
    FAIL();
  } catch (const SettingError& error) {
    EXPECT_EQ(error.setting(), Setting::duration);
    EXPECT_NE(error.problem().find("valid range [0.05, 50000] s"), std::string::npos) << error.problem();
  }
  request.duration = 100.0;
  request.integrator = solve::Integrator::generalized_alpha;
  request.fixed_step = 1e-6;  // 1e8 steps
  try {
    (void)integrator_settings(scene, request);
    FAIL();
  } catch (const SettingError& error) {
    EXPECT_EQ(error.setting(), Setting::fixed_step);
    EXPECT_NE(error.problem().find("valid range [1e-05, 0.05] s"), std::string::npos) << error.problem();
  }
  request.relative_tolerance = 1e-13;
  request.fixed_step = 0.01;
  EXPECT_THROW((void)integrator_settings(scene, request), SettingError);
}

TEST(WorkLimits, ReferenceFinestLevelWithinTheLimits) {
  ReferenceOptions options;  // 8 elements, 3 levels: 32 at the finest
  EXPECT_NO_THROW(validate(options));
  options.start_elements = max_nodal_elements() / 4 + 1;
  EXPECT_THROW(validate(options), SettingError);
  options = {};
  options.max_levels = 6;
  options.start_relative_tolerance = 1e-8;  // 1e-13 at the finest
  EXPECT_THROW(validate(options), SettingError);
}

TEST(WaterDetection, CargoOnALongWireDipsIntoTheWave) {
  // The reference crane with the cargo 1.6 m above still water at rest (a 102 m wire): the 1 m wave
  // heaves it by more than a metre, so it dips; the monitor names it with its time and depth.
  scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  scene.wire->unstretched_length = 102.0;
  DynamicsRequest request;
  request.duration = 40.0;
  const ModelRun run = run_model(scene, {scene::BoomKind::rigid, 1}, integrator_settings(scene, request));
  const auto found = std::find_if(run.result.detections.begin(), run.result.detections.end(),
                                  [](const solve::Detection& d) { return d.kind == solve::FailureKind::cargo_in_water; });
  ASSERT_NE(found, run.result.detections.end());
  EXPECT_GT(found->time, 0.0);
  EXPECT_GT(found->value, 0.0);
  // The same scene with the 20 m wire stays dry.
  scene.wire->unstretched_length = 20.0;
  const ModelRun dry = run_model(scene, {scene::BoomKind::rigid, 1}, integrator_settings(scene, request));
  for (const solve::Detection& d : dry.result.detections) EXPECT_NE(d.kind, solve::FailureKind::cargo_in_water);
}

}  // namespace
}  // namespace ffrf::study
