// The sea of an operability cell and a table's plan, against independent facts: Pierson–Moskowitz's
// closed-form cumulative variance (band edges) and its band-limited m2 through the error function
// (Tz), the repeat period 2πK/band of K components by hand, DNV-RP-C205's steepness limit by hand
// (λp = g Tp²/2π), a 3 × 3 grid with one breaking cell planned and run with that cell named not
// physical and given no record, and a record's simulated time followed while it runs.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>

#include "../distributed/scratch_directory.hpp"
#include "distributed/session.hpp"
#include "scene/irregular_sea.hpp"
#include "study/operability.hpp"
#include "study_test_support.hpp"

namespace ffrf::study {
namespace operability_sea_test {

constexpr double pi = std::numbers::pi;

// PM over [a, b] with u = 1.25 (ωp/ω)⁴: m0 = (Hs²/16)(e^(−u_b) − e^(−u_a)) and
// m2 = (Hs²/16) ωp² √1.25 √π (erf √u_a − erf √u_b).
struct PmBand {
  double m0, m2;
};
PmBand pm_band_moments(double hs, double wp, double a, double b) {
  const double ua = 1.25 * std::pow(wp / a, 4), ub = 1.25 * std::pow(wp / b, 4);
  return {hs * hs / 16.0 * (std::exp(-ub) - std::exp(-ua)),
          hs * hs / 16.0 * wp * wp * std::sqrt(1.25 * pi) * (std::erf(std::sqrt(ua)) - std::erf(std::sqrt(ub)))};
}

TEST(OperabilitySea, KComponentsRepeatAfterTwoPiKOverTheBand) {
  const double hs = 2.0, tp = 8.0, wp = 2 * pi / tp, record = 10800.0, ramp = 16.0;
  const CellSea sea = cell_sea(hydro::pierson_moskowitz(hs, tp), 9.81, record, ramp, 40, 0.995);
  // The band: PM's closed-form quantiles of its variance, 0.25 % below and above.
  const double lo = wp * std::pow(1.25 / std::log(2.0 / 0.005), 0.25), hi = wp * std::pow(1.25 / std::log(2.0 / 1.995), 0.25);
  EXPECT_NEAR(sea.band.lower, lo, 1e-7 * wp);
  EXPECT_NEAR(sea.band.upper, hi, 1e-7 * wp);
  EXPECT_NEAR(sea.variance_share, 0.995, 1e-8);
  EXPECT_NEAR(sea.repeat_period, 2 * pi * 40 / (hi - lo), 1e-6 * sea.repeat_period);
  EXPECT_NEAR(sea.record_repeats, record / (2 * pi * 40 / (hi - lo)), 1e-6 * sea.record_repeats);
  EXPECT_TRUE(sea.repeats());
  EXPECT_GE(sea.components, 40u);
  EXPECT_LE(sea.components, 41u);  // n Δω from ⌈lo/Δω⌉ to ⌊hi/Δω⌋
  const PmBand m = pm_band_moments(hs, wp, sea.band.lower, sea.band.upper);
  const double tz = 2 * pi * std::sqrt(m.m0 / m.m2);
  EXPECT_NEAR(sea.zero_crossing_period, tz, 1e-6 * tz);
  EXPECT_NEAR(sea.independent_wave_cycles, sea.repeat_period / tz, 1e-5 * sea.independent_wave_cycles);
  EXPECT_TRUE(sea.physical());  // Sp = 2 / 99.9 = 0.020 < 1/15
}

TEST(OperabilitySea, ComponentsEveryTwoPiOverTheRecordNeverRepeat) {
  const double tp = 8.0, record = 1200.0, ramp = 16.0;
  const CellSea sea = cell_sea(hydro::jonswap(2.0, tp, 3.3), 9.81, record, ramp, 0, 0.995);
  EXPECT_NEAR(sea.repeat_period, record, 1e-9 * record);
  EXPECT_FALSE(sea.repeats());
  EXPECT_NEAR(sea.independent_wave_cycles, (record - ramp) / sea.zero_crossing_period, 1e-9 * sea.independent_wave_cycles);
  // Δω = 2π/record over the band: ⌊hi/Δω⌋ − ⌈lo/Δω⌉ + 1 components.
  const double step = 2 * pi / record;
  EXPECT_EQ(sea.components, static_cast<std::size_t>(std::floor(sea.band.upper / step) - std::ceil(sea.band.lower / step) + 1));
}

TEST(OperabilitySea, ASeaSteeperThanDnvsLimitIsNotPhysical) {
  // Tp = 5 s: λp = 9.81 · 25 / 2π = 39.03 m; Hs ≤ λp / 15 = 2.60 m.
  const CellSea steep = cell_sea(hydro::jonswap(3.0, 5.0, 3.3), 9.81, 600.0, 10.0, 0, 0.995);
  EXPECT_FALSE(steep.physical());
  EXPECT_TRUE(cell_sea(hydro::jonswap(2.5, 5.0, 3.3), 9.81, 600.0, 10.0, 0, 0.995).physical());
  const std::string why = not_physical_reason(3.0, 5.0, steep.steepness);
  EXPECT_NE(why.find("Hs = 3 m at Tp = 5 s"), std::string::npos) << why;
  EXPECT_NE(why.find("Hs ≤ 2.6 m"), std::string::npos) << why;
}

OperabilityRequest three_by_three(int components) {
  OperabilityRequest request;
  request.significant_heights = {1.0, 2.0, 3.0};
  request.peak_periods = {5.0, 6.0, 7.0};
  request.seeds = 1;
  request.duration = 100.0;
  request.components = components;
  request.verify_cells = 1;
  request.criteria.cargo_motion_limit = 3.0;
  return request;
}

TEST(OperabilityPlan, OneBreakingCellOfAThreeByThreeGridGetsNoRecordAndTheRepetitionIsNamed) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  modal::ModeCache modes;
  const OperabilityPlan plan = plan_operability(scene, three_by_three(20), &modes);
  ASSERT_EQ(plan.cells.size(), 9u);
  for (std::size_t c = 0; c < plan.cells.size(); ++c) {
    // Only Hs = 3 m at Tp = 5 s lies above Hs/λp = 1/15 (2.60 m at 5 s, 3.75 m at 6 s, 5.10 m at 7 s).
    const bool breaking = plan.cells[c].significant_height == 3.0 && plan.cells[c].peak_period == 5.0;
    EXPECT_EQ(plan.seas[c].physical(), !breaking) << plan.cells[c].key();
  }
  EXPECT_EQ(plan.physical_cells(), 8u);
  EXPECT_EQ(plan.records(1), 9u);  // 8 cells and one verified
  EXPECT_TRUE(plan.seas[plan.verified.front()].physical());
  // 20 components over a Tp = 5 s band of ~4.5 rad/s repeat within 28 s: the 100-s record repeats.
  ASSERT_EQ(plan.warnings.size(), 1u);
  EXPECT_NE(plan.warnings[0].find("repeats within the 100-s record in 8 of 8 cells"), std::string::npos) << plan.warnings[0];
  EXPECT_TRUE(repetition_warning(plan_operability(scene, three_by_three(0), &modes), three_by_three(0)).empty());
}

TEST(OperabilityPlan, EachCellsRecordsKeepItsOwnBandNotTheScenes) {
  const scene::Scene scene = test::scene_file("irregular_sea_crane.toml");
  ASSERT_TRUE(scene.sea && scene.sea->frequency_max > 0.0);  // the scene's band belongs to its Tp = 8 s
  OperabilityRequest request = three_by_three(0);
  const SeaCell cell{1.0, 5.0, hydro::WaveHeading::following};
  const scene::Scene record = record_scene(scene, cell, 7, request);
  const hydro::FrequencyBand own = hydro::variance_band(cell_spectrum(scene, cell, request), request.variance_share);
  EXPECT_EQ(record.sea->frequency_min, own.lower);
  EXPECT_EQ(record.sea->frequency_max, own.upper);
  EXPECT_NEAR(own.lower / (2 * pi / 5.0), 0.7, 0.05);  // about 0.7 ωp and 4.3 ωp (JONSWAP γ = 3.3)
  modal::ModeCache modes;
  request.significant_heights = {1.0};
  request.peak_periods = {5.0};
  const OperabilityPlan plan = plan_operability(scene, request, &modes);
  ASSERT_EQ(plan.warnings.size(), 1u);
  EXPECT_NE(plan.warnings[0].find("belongs to its own sea (Tp = 8 s) and is not used"), std::string::npos) << plan.warnings[0];
}

TEST(OperabilityRun, TheBreakingCellIsNotPhysicalNotFailedAndARecordsTimeIsFollowed) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  OperabilityRequest request = three_by_three(0);
  request.significant_heights = {1.0, 3.0};
  request.peak_periods = {5.0};
  request.duration = 80.0;
  request.verify_cells = 0;
  test::ScratchDirectory dir;
  distributed::Session session;
  distributed::FarmOptions farm;
  farm.output_directory = dir.path();
  farm.threads = 1;
  const OperabilityStudy study = run_operability(session, scene, request, farm);
  ASSERT_EQ(study.cells.size(), 2u);
  EXPECT_EQ(study.cells[0].status(), CellStatus::ok) << study.cells[0].failure;
  EXPECT_EQ(study.cells[1].status(), CellStatus::not_physical);
  EXPECT_NE(study.cells[1].failure.find("steeper than a sea can be"), std::string::npos) << study.cells[1].failure;
  EXPECT_EQ(study.farm.computed, 1u);  // the breaking cell ran nothing
  EXPECT_EQ(study.farm.failed, 0u);
  // The integrator's simulated time reaches the record's end through the sink.
  std::atomic<double> reached{0.0};
  const SeedExtremes again = run_record(scene, study.cells[0].cell, 0, study.cells[0].model, request, nullptr, &reached);
  EXPECT_DOUBLE_EQ(reached.load(), request.duration);
  EXPECT_DOUBLE_EQ(again.tension_mpm, study.cells[0].statistics.tension_mpm.mean);  // one seed: its own MPM
}

}  // namespace operability_sea_test
}  // namespace ffrf::study
