// Regression baselines (study/baseline.hpp, study/baseline_check.hpp) against independent facts:
//  * Determinism: the same program re-running the same model reproduces every quantity bit for bit,
//    so a round trip passes with differences of exactly zero.
//  * E × 1.01: K ∝ E (EA and EI alike) with M unchanged, so every boom frequency moves by exactly
//    √1.01 − 1 = 0.4988 %; the static tip deflection of the linear boom, K q = Q with Q the
//    deflection-independent weight and wire loads, moves by 1/1.01 − 1 (up to the O(1e-5) change of
//    Q with the hull's trim); the check names each of them and the judged outputs that moved.
//  * The tolerance rule |Δ| ≤ relative × std + absolute at its boundary, on hand-made changes.
//  * Mean and standard deviation of a sampled sine: 0 and 1/√2 over whole periods.
//  * The history decimation from the scene's periods, computed by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "study/baseline.hpp"
#include "study/baseline_check.hpp"
#include "study/output_series.hpp"
#include "study_test_support.hpp"

namespace baseline_test {

using namespace ffrf;

constexpr int kElements = 4;          // 12 free DOFs: the six modes of a baseline
constexpr double kDuration = 25.0;    // past the wave ramp (2 × 10 s): a statistics window of 5 s

multibody::RunSettings short_run(const scene::Scene& scene) {
  study::DynamicsRequest request;
  request.duration = kDuration;
  return study::integrator_settings(scene, request);
}

study::BaselineRequest crane_request(const scene::Scene& scene, std::vector<std::string> outputs = {}) {
  study::BaselineRequest request;
  request.choice = {scene::BoomKind::nodal, kElements};
  request.settings = short_run(scene);
  request.outputs = std::move(outputs);
  return request;
}

const study::Deviation& find(const study::BaselineCheck& check, const std::string& channel, const std::string& quantity) {
  const auto found = std::find_if(check.deviations.begin(), check.deviations.end(), [&](const study::Deviation& d) {
    return d.channel == channel && d.quantity == quantity;
  });
  if (found == check.deviations.end()) throw std::out_of_range(channel + " " + quantity + " not judged");
  return *found;
}

class CraneBaseline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new scene::Scene(test::scene_file("paper_floating_crane.toml"));
    baseline_ = new study::Baseline(study::record_baseline(*scene_, crane_request(*scene_, outputs())));
  }
  static void TearDownTestSuite() {
    delete baseline_;
    delete scene_;
  }
  // The judged outputs and the tip deflection, whose static value the E × 1.01 test predicts.
  static std::vector<std::string> outputs() {
    return {"cargo_heave", "cargo_pitch", "crane_heave", "crane_pitch", "wire_tension", "joint_moment", "tip_transverse_m"};
  }
  static scene::Scene* scene_;
  static study::Baseline* baseline_;
};
scene::Scene* CraneBaseline::scene_ = nullptr;
study::Baseline* CraneBaseline::baseline_ = nullptr;

TEST_F(CraneBaseline, RecordsTheModelFrequenciesStatisticsAndHistories) {
  const study::Baseline& b = *baseline_;
  EXPECT_EQ(b.model.choice.kind, scene::BoomKind::nodal);
  EXPECT_EQ(b.model.choice.elements, kElements);
  ASSERT_TRUE(b.model.choice.stiffening.has_value()) << "the scene's stiffening is written out";
  EXPECT_EQ(b.model.duration, kDuration);
  ASSERT_EQ(b.boom_frequencies.size(), 6u);
  EXPECT_EQ(b.boom_frequencies[0].kind, "bending");
  // The coupled crane's lowest modes, as `ffrf rao` finds them: the moored surge first.
  ASSERT_EQ(b.coupled_modes.size(), 8u);
  EXPECT_EQ(b.coupled_modes[0].dominant, "hull surge");
  for (std::size_t j = 1; j < b.coupled_modes.size(); ++j) EXPECT_GE(b.coupled_modes[j].hz, b.coupled_modes[j - 1].hz);
  ASSERT_EQ(b.channels.size(), 7u);
  EXPECT_EQ(b.channels[0].name, "cargo_heave_m");
  EXPECT_EQ(b.channels[6].name, "tip_transverse_m");
  EXPECT_TRUE(b.window_after_ramp);
  EXPECT_NEAR(b.window_start, 20.05, 1e-9);  // the first sample after the 2 × 10 s ramp
  ASSERT_TRUE(b.wire_amplification.has_value());
  EXPECT_GT(*b.wire_amplification, 1.0);
  // Wire bounce 2π√(1.3e6 kg / 2e8 N/m) = 0.507 s is the shortest period: 20 points need 0.025 s,
  // finer than the output interval 0.05 s, so every sample is kept.
  EXPECT_EQ(b.decimation, 1);
  EXPECT_EQ(b.history_time.size(), 501u);
  for (const study::ChannelBaseline& c : b.channels) {
    EXPECT_EQ(c.history.size(), b.history_time.size()) << c.name;
    EXPECT_LE(c.min, c.mean) << c.name;
    EXPECT_LE(c.mean, c.max) << c.name;
    // RMS about r, std about the mean: rms² = std² + (mean − r)² over the same samples.
    const double reference = c.about_static ? 0.0 : c.static_value;
    EXPECT_NEAR(c.rms * c.rms, c.standard_deviation * c.standard_deviation + (c.mean - reference) * (c.mean - reference),
                1e-9 * c.rms * c.rms + 1e-300)
        << c.name;
  }
}

TEST_F(CraneBaseline, RoundTripPassesWithZeroDifferences) {
  const study::BaselineCheck check =
      study::check_baseline(*scene_, *baseline_, baseline_->model.choice, short_run(*scene_), {});
  EXPECT_TRUE(check.passed());
  EXPECT_TRUE(check.model_differences.empty());
  // 6 boom frequencies, 8 coupled modes × (frequency, damping ratio), 7 channels × (6 statistics +
  // history), the wire amplification.
  EXPECT_EQ(check.deviations.size(), 6u + 8u * 2u + 7u * 7u + 1u);
  for (const study::Deviation& d : check.deviations) EXPECT_EQ(d.difference, 0.0) << d.channel << " " << d.quantity;
  ASSERT_TRUE(baseline_->integration_error.has_value());
  const study::IntegrationError& error = *baseline_->integration_error;
  ASSERT_TRUE(error.measured()) << error.problem;
  EXPECT_EQ(error.relative_tolerance, 1e-8);  // 1/100 of the run's
  EXPECT_GT(error.largest, 0.0);
  EXPECT_EQ(check.response_tolerance, std::max(100.0 * 1e-6, 10.0 * error.largest));
  EXPECT_EQ(check.frequency_tolerance, 1e-6);
}

// The integration error recorded (the run against itself at 1/100 of the tolerances) is the run's
// error: a third run, at 1/10⁴ of the tolerances, differs from the recorded one by the same amount
// (to the tighter run's own error, ~1 %).
TEST_F(CraneBaseline, IntegrationErrorAgreesWithAMuchTighterRun) {
  multibody::RunSettings tight = short_run(*scene_);
  tight.relative_tolerance = tight.absolute_tolerance = 1e-10;
  study::BaselineTolerances exact;
  exact.relative = 0.0;
  const study::BaselineCheck check = study::check_baseline(*scene_, *baseline_, baseline_->model.choice, tight, exact);
  const study::IntegrationError& error = *baseline_->integration_error;
  const study::Deviation& same = find(check, error.channel, error.quantity);
  EXPECT_NEAR(same.normalized(), error.largest, 0.05 * error.largest) << error.channel << " " << error.quantity;
}

TEST_F(CraneBaseline, StifferBoomFailsNamingEveryFrequencyAndTheChannelsThatMoved) {
  scene::Scene stiffer = *scene_;
  stiffer.boom.mesh.section.youngs_modulus *= 1.01;
  const study::BaselineCheck check = study::check_baseline(stiffer, *baseline_, baseline_->model.choice, short_run(stiffer), {});
  EXPECT_FALSE(check.passed());
  EXPECT_TRUE(check.model_differences.empty()) << "the scene changed, not the model";
  const double ratio = std::sqrt(1.01);  // ω ∝ √(E/ρA): 0.4988 % higher
  for (std::size_t j = 0; j < 6; ++j) {
    const study::Deviation& d = find(check, "boom", "f" + std::to_string(j + 1));
    EXPECT_FALSE(d.passed) << d.quantity;
    EXPECT_NEAR(d.value / d.baseline, ratio, 1e-10) << d.quantity;
    EXPECT_NEAR(d.normalized(), ratio - 1.0, 1e-10) << d.quantity << ": the reported relative deviation";
    EXPECT_EQ(d.allowed, 1e-6 * d.baseline);
  }
  // The coupled crane's modes: the first boom mode rises by most of √1.01 (measured +4.2e-3: the
  // hull and cargo share little of its energy), the moored surge by less than 1 % of that (+7.6e-6).
  const study::Deviation& surge = find(check, "coupled", "f1");
  EXPECT_EQ(surge.detail, "hull surge");
  const auto boom_mode = std::find_if(baseline_->coupled_modes.begin(), baseline_->coupled_modes.end(),
                                      [](const study::CoupledFrequency& m) { return m.dominant == "boom"; });
  ASSERT_NE(boom_mode, baseline_->coupled_modes.end());
  const study::Deviation& boom = find(check, "coupled", "f" + std::to_string(boom_mode - baseline_->coupled_modes.begin() + 1));
  EXPECT_FALSE(boom.passed);
  EXPECT_GT(boom.value / boom.baseline, 1.0 + 0.5 * (ratio - 1.0));
  EXPECT_LT(boom.value / boom.baseline, ratio + 1e-9);
  EXPECT_LT(surge.normalized(), 0.01 * boom.normalized());
  // Static tip deflection of the linear boom ∝ 1/E; Q changes with the hull's trim (measured: 2.4e-5 off 1/1.01).
  const study::Deviation& tip = find(check, "tip_transverse_m", "static");
  EXPECT_FALSE(tip.passed);
  EXPECT_NEAR(tip.value / tip.baseline, 1.0 / 1.01, 1e-4);
  // The judged outputs that move with the boom's stiffness fail: their histories differ by more than
  // the recorded run's integration error allows (10× it). The crane's pitch moves too (by more than
  // the integration error), but by less than that margin: the hull hardly feels a 1 % stiffer boom.
  for (const char* channel : {"cargo_heave_m", "joint_moment_Nm", "wire_tension_N"}) {
    const study::Deviation& history = find(check, channel, "history");
    EXPECT_FALSE(history.passed) << channel << ": " << history.normalized() << " against " << history.allowed / history.scale;
  }
  const study::Deviation& pitch = find(check, "crane_pitch_deg", "history");
  EXPECT_GT(pitch.normalized(), baseline_->integration_error->largest);
  // The cargo hangs below the tip: its static height rises with the tip (by the vertical part of the
  // tip's deflection change at the boom angle of 60°, and the hull's trim change acting on the arm).
  const study::Deviation& cargo = find(check, "cargo_heave_m", "static");
  EXPECT_FALSE(cargo.passed);
  EXPECT_GT(cargo.value - cargo.baseline, 0.0);
  EXPECT_NEAR(cargo.value - cargo.baseline, (tip.value - tip.baseline) * std::cos(std::numbers::pi / 3.0),
              0.2 * std::abs(tip.value - tip.baseline));
}

TEST_F(CraneBaseline, OtherModelReportsTheDifferenceAndItsDeviations) {
  scene::BoomChoice modal = baseline_->model.choice;
  modal.kind = scene::BoomKind::modal;
  modal.modes = 1;
  modal.static_modes = false;  // misses the static deflection: the responses move
  const study::BaselineCheck check = study::check_baseline(*scene_, *baseline_, modal, short_run(*scene_), {});
  ASSERT_FALSE(check.model_differences.empty());
  EXPECT_EQ(check.model_differences[0].setting, "boom model");
  EXPECT_EQ(check.model_differences[0].baseline, "nodal");
  EXPECT_EQ(check.model_differences[0].run, "modal");
  // Same mesh: the boom's frequencies are the same; the missing static deflection moves the tip.
  EXPECT_TRUE(find(check, "boom", "f1").passed);
  EXPECT_FALSE(find(check, "tip_transverse_m", "static").passed);
  for (const study::Deviation& d : check.deviations) EXPECT_TRUE(std::isfinite(d.difference)) << d.channel << " " << d.quantity;

  scene::BoomChoice finer = baseline_->model.choice;
  finer.elements = 8;  // twice the elements: the FE frequencies converge from above
  const study::BaselineCheck refined = study::check_baseline(*scene_, *baseline_, finer, short_run(*scene_), {});
  ASSERT_EQ(refined.model_differences.size(), 1u);
  EXPECT_EQ(refined.model_differences[0].setting, "elements");
  const study::Deviation& f3 = find(refined, "boom", "f3");
  EXPECT_LT(f3.value, f3.baseline);
}

TEST_F(CraneBaseline, ToleranceIsRelativeTimesTheChannelsStdPlusAbsolute) {
  study::Baseline run = *baseline_;
  study::ChannelBaseline& heave = run.channels[0];
  const double std_heave = baseline_->channels[0].standard_deviation;
  const double relative = 1e-3, absolute = 1e-5;  // [m]
  const double allowed = relative * std_heave + absolute;
  study::BaselineTolerances tolerances;
  tolerances.relative = relative;
  tolerances.absolute = absolute;
  heave.max += 0.99 * allowed;
  heave.min -= 1.01 * allowed;
  for (double& v : heave.history) v += 0.99 * allowed;  // RMS of the difference: 0.99 × allowed
  const study::BaselineCheck check = study::compare_baseline(*baseline_, run, tolerances);
  EXPECT_TRUE(find(check, "cargo_heave_m", "max").passed);
  EXPECT_FALSE(find(check, "cargo_heave_m", "min").passed);
  EXPECT_TRUE(find(check, "cargo_heave_m", "history").passed);
  EXPECT_NEAR(find(check, "cargo_heave_m", "min").allowed, allowed, 1e-15);
  EXPECT_EQ(check.failures(), 1);

  tolerances.per_name["cargo_heave_m"] = 2.0 * relative;  // allowed 2 × 1e-3 × std + 1e-5 > 1.01 × allowed
  EXPECT_TRUE(study::compare_baseline(*baseline_, run, tolerances).passed()) << "a per-channel tolerance overrides";

  tolerances.per_name["cargo_heave"] = 1e-3;  // not a column of the baseline
  EXPECT_THROW(study::compare_baseline(*baseline_, run, tolerances), study::ToleranceError);
}

TEST_F(CraneBaseline, HistoriesAtOtherTimesAreNotComparedAndFail) {
  study::Baseline run = *baseline_;
  for (double& t : run.history_time) t *= 1.5;  // another output interval
  const study::BaselineCheck check = study::compare_baseline(*baseline_, run, {});
  const study::Deviation& history = find(check, "wire_tension_N", "history");
  EXPECT_FALSE(history.compared);
  EXPECT_FALSE(history.passed);
  EXPECT_NE(history.problem.find("other times"), std::string::npos) << history.problem;
}

TEST(BaselineModel, DifferencesAreListedSettingBySetting) {
  study::BaselineModel a;
  a.choice = {scene::BoomKind::modal, 16, 2, true};
  a.choice.stiffening = scene::Stiffening::none;
  study::BaselineModel b = a;
  EXPECT_TRUE(study::model_differences(a, b).empty());
  b.choice.modes = 4;
  b.choice.static_modes = false;
  b.choice.stiffening = scene::Stiffening::static_load;
  b.integrator = solve::Integrator::ida;
  b.duration = 60.0;
  const std::vector<study::SettingDifference> d = study::model_differences(a, b);
  ASSERT_EQ(d.size(), 5u);
  EXPECT_EQ(d[0].setting, "vibration modes");
  EXPECT_EQ(d[0].baseline, "2");
  EXPECT_EQ(d[0].run, "4");
  EXPECT_EQ(d[1].setting, "static correction modes");
  EXPECT_EQ(d[2].setting, "geometric stiffening");
  EXPECT_EQ(d[2].run, "static");
  EXPECT_EQ(d[3].setting, "integrator");
  EXPECT_EQ(d[4].setting, "duration");
  EXPECT_EQ(d[4].run, "60 s");
}

TEST(BaselineStatistics, MeanAndStandardDeviationOfASineOverWholePeriods) {
  std::vector<multibody::CraneOutputs> samples(400);
  multibody::CraneOutputs statics;
  statics.hull = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] = statics;
    samples[i].hull.y() = 3.0 + 2.0 * std::sin(2.0 * std::numbers::pi * static_cast<double>(i) / 100.0);  // 4 periods
  }
  const std::vector<study::SeriesStats> stats = study::series_stats(samples, statics, {});
  const study::SeriesStats& heave = stats[study::series_index("crane_heave_m")];
  EXPECT_NEAR(heave.mean, 3.0, 1e-12);
  EXPECT_NEAR(heave.standard_deviation, 2.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(heave.rms, std::sqrt(9.0 + 2.0), 1e-12);  // about the static value 0: √(mean² + std²)
}

TEST(BaselineDecimation, KeepsTwentyPointsInTheShortestPeriod) {
  const scene::Scene crane = test::scene_file("paper_floating_crane.toml");
  // Shortest: the cargo's bounce on the wire 2π√(1.3e6/2e8) = 0.5066 s; 20 points at 0.05 s: k = 1.
  EXPECT_EQ(study::history_decimation(crane, 0.05, 0.6), 1);
  // The same at an output interval of 0.002 s: ⌊0.5066 / 0.04⌋ = 12.
  EXPECT_EQ(study::history_decimation(crane, 0.002, 0.6), 12);
  // Without wire and wave (the cantilever): the boom's first period 1/0.835 Hz; ⌊1.1976 / 0.02⌋ = 59.
  const scene::Scene beam = test::scene_file("cantilever.toml");
  EXPECT_EQ(study::history_decimation(beam, 0.001, 0.835), 59);
  EXPECT_EQ(study::history_decimation(beam, 0.001, 0.0), 1) << "no period known: keep every sample";
}

TEST(BaselineOutputs, ColumnsAndJudgedChannelsAreAcceptedOthersAreNot) {
  EXPECT_EQ(study::output_column("wire_tension"), "wire_tension_N");
  EXPECT_EQ(study::output_column("tip_deflection"), "tip_transverse_m");
  EXPECT_EQ(study::output_column("kinetic_energy_J"), "kinetic_energy_J");
  EXPECT_FALSE(study::output_column("wire_tension_kN").has_value());
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  study::BaselineRequest request = crane_request(scene, {"wire_tension_kN"});
  EXPECT_THROW(study::record_baseline(scene, request), std::invalid_argument);
}

}  // namespace baseline_test
