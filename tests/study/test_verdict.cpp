// The verdict of compare and sweep (study/verdict.hpp) against hand-computed cases: which models
// pass a tolerance, the speed-ups as the reference's wall time and work over the model's, the
// cheapest passing model by solver work (not by wall time), ties, failures and a tolerance out of range.
#include <gtest/gtest.h>

#include <cmath>

#include "study/run_pipeline.hpp"
#include "study/verdict.hpp"

namespace {

using ffrf::study::judge;
using ffrf::study::MeasuredModel;

MeasuredModel model(const char* label, double error, double wall, double work) {
  MeasuredModel m;
  m.label = label;
  m.error = error;
  m.worst_output = "cargo_heave";
  m.wall_seconds = wall;
  m.work = work;
  return m;
}

TEST(Verdict, HandComputedPassFailSpeedUpsAndCheapestByWork) {
  // Reference: 10 s of wall time, work 1200 (RHS evaluations × state size). τ = 1 %.
  MeasuredModel not_run = model("D", NAN, 0.0, 0.0);
  not_run.ran = false;
  not_run.reason = "failed";
  const std::vector<MeasuredModel> models{model("A", 0.02, 1.0, 100.0),   // too inaccurate
                                          model("B", 0.005, 2.0, 300.0),  // passes: 5× wall, 4× work
                                          model("C", 0.001, 0.5, 400.0),  // passes: 20× wall, 3× work
                                          not_run};
  const auto v = judge(models, 10.0, 1200.0, 0.01);
  ASSERT_EQ(v.models.size(), 4u);
  EXPECT_FALSE(v.models[0].passed);
  EXPECT_TRUE(v.models[1].passed);
  EXPECT_TRUE(v.models[2].passed);
  EXPECT_FALSE(v.models[3].passed);
  EXPECT_DOUBLE_EQ(v.models[0].wall_speedup, 10.0);
  EXPECT_DOUBLE_EQ(v.models[0].work_speedup, 12.0);
  EXPECT_DOUBLE_EQ(v.models[1].wall_speedup, 5.0);
  EXPECT_DOUBLE_EQ(v.models[1].work_speedup, 4.0);
  EXPECT_DOUBLE_EQ(v.models[2].wall_speedup, 20.0);
  EXPECT_DOUBLE_EQ(v.models[2].work_speedup, 3.0);
  EXPECT_TRUE(std::isnan(v.models[3].wall_speedup)) << "a run that did not finish has no speed-up";
  // B is the cheapest by solver work (300 < 400) although C is faster on the wall clock.
  ASSERT_TRUE(v.cheapest.has_value());
  EXPECT_EQ(*v.cheapest, 1u);
  ASSERT_TRUE(v.most_accurate.has_value());
  EXPECT_EQ(*v.most_accurate, 2u);
  EXPECT_EQ(v.failed, (std::vector<std::size_t>{0, 3}));
  EXPECT_EQ(v.passed_count(), 2u);
}

TEST(Verdict, ErrorEqualToTheTolerancePassesAndEqualWorkIsDecidedByWallTime) {
  const std::vector<MeasuredModel> models{model("slow", 0.01, 3.0, 500.0), model("fast", 0.002, 1.0, 500.0)};
  const auto v = judge(models, 6.0, 1000.0, 0.01);
  EXPECT_TRUE(v.models[0].passed) << "error = τ is within τ";
  ASSERT_TRUE(v.cheapest.has_value());
  EXPECT_EQ(*v.cheapest, 1u);
  EXPECT_TRUE(v.failed.empty());
}

TEST(Verdict, NothingPassesThenTheMostAccurateIsNamedAndANonFiniteErrorFails) {
  const std::vector<MeasuredModel> models{model("rigid", 2.6, 0.1, 10.0), model("diverged", INFINITY, 0.1, 10.0),
                                          model("modal k=1", 0.061, 0.2, 40.0)};
  const auto v = judge(models, 1.0, 100.0, 0.01);
  EXPECT_FALSE(v.cheapest.has_value());
  ASSERT_TRUE(v.most_accurate.has_value());
  EXPECT_EQ(*v.most_accurate, 2u);
  EXPECT_EQ(v.failed.size(), 3u);
  EXPECT_FALSE(v.models[1].passed);
  // A looser tolerance lets modal k=1 pass; rigid still fails.
  const auto loose = judge(models, 1.0, 100.0, 0.1);
  ASSERT_TRUE(loose.cheapest.has_value());
  EXPECT_EQ(*loose.cheapest, 2u);
}

TEST(Verdict, ToleranceOutOfRangeIsASettingError) {
  for (const double tau : {0.0, 1.0, -0.01, static_cast<double>(NAN)}) {
    EXPECT_THROW(judge({}, 1.0, 1.0, tau), ffrf::study::SettingError) << tau;
  }
  try {
    judge({}, 1.0, 1.0, 1.5);
  } catch (const ffrf::study::SettingError& error) {
    EXPECT_EQ(error.setting(), ffrf::study::Setting::tolerance);
  }
}

// The model-choice rtol: the decade at or below τ/10⁴, by hand.
TEST(Verdict, ModelChoiceRtolIsTheDecadeAtOrBelowTauOverTenThousand) {
  EXPECT_DOUBLE_EQ(ffrf::study::model_choice_rtol(0.01), 1e-6);
  EXPECT_DOUBLE_EQ(ffrf::study::model_choice_rtol(0.05), 1e-6);
  EXPECT_DOUBLE_EQ(ffrf::study::model_choice_rtol(0.1), 1e-5);
  EXPECT_DOUBLE_EQ(ffrf::study::model_choice_rtol(0.001), 1e-7);
  EXPECT_DOUBLE_EQ(ffrf::study::solver_work(1500, 18), 27000.0);
}

// Only models run at the model-choice rtol compete for the cheapest: a cheaper pass at another rtol
// is a pass, not the verdict's model.
TEST(Verdict, TheCheapestIsNamedAmongRunsAtTheModelChoiceRtolOnly) {
  MeasuredModel loose = model("N=1 rtol 1e-4", 0.009, 0.5, 100.0);
  loose.at_choice_rtol = false;
  const std::vector<MeasuredModel> models{loose, model("N=1 rtol 1e-6", 0.002, 0.8, 150.0), model("k=4", 0.004, 0.7, 170.0)};
  const auto v = judge(models, 10.0, 1200.0, 0.01);
  EXPECT_TRUE(v.models[0].passed);
  ASSERT_TRUE(v.cheapest.has_value());
  EXPECT_EQ(*v.cheapest, 1u);
  EXPECT_TRUE(ffrf::study::cheapest_passing(models, 0.01) == v.cheapest);
}

}  // namespace
