// One physics across commands: compare, sweep and recommend on the same scene use the same reference
// (same stiffening — what recommend's reasoning decides —, same levels, the same samples), the same
// error window, the same judged outputs, and give the same error for the same model (the reference
// scene at 25 s: the window is the 5 s after the 20 s wave ramp, two levels). And one verdict across
// commands: `sweep --quick`, `recommend`, `compare` and operability's model for a one-cell grid name
// the same cheapest model that passes (study::cheapest_passing: least solver work at the model-choice
// rtol), on the reference scene in its regular wave and in an irregular sea.
#include <gtest/gtest.h>

#include "report/sweep_csv.hpp"
#include "report/sweep_report.hpp"
#include "study/compare.hpp"
#include "study/operability.hpp"
#include "study/recommend.hpp"
#include "study/sweep.hpp"
#include "../study/study_test_support.hpp"

namespace {

using namespace ffrf;

bool same_model(const scene::BoomChoice& a, const scene::BoomChoice& b, scene::Stiffening modelled) {
  return a.kind == b.kind && (a.kind == scene::BoomKind::rigid || a.elements == b.elements) &&
         (a.kind != scene::BoomKind::modal || (a.modes == b.modes && a.static_modes == b.static_modes && a.mode_set == b.mode_set)) &&
         a.stiffening.value_or(modelled) == b.stiffening.value_or(modelled);
}

void expect_same_reference(const study::ConvergedReference& a, const study::ConvergedReference& b, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.choice.label(), b.choice.label());
  EXPECT_EQ(a.settings.relative_tolerance, b.settings.relative_tolerance);
  ASSERT_EQ(a.levels.size(), b.levels.size());
  for (std::size_t i = 0; i < a.levels.size(); ++i) EXPECT_EQ(a.levels[i].change, b.levels[i].change) << "level " << i;
  EXPECT_EQ(a.window_start, b.window_start);
  ASSERT_EQ(a.run.result.samples.size(), b.run.result.samples.size());
  for (std::size_t i = 0; i < a.run.result.samples.size(); ++i) {
    EXPECT_EQ(a.run.result.samples[i].cargo.y(), b.run.result.samples[i].cargo.y()) << i;
    EXPECT_EQ(a.run.result.samples[i].wire_tension, b.run.result.samples[i].wire_tension) << i;
  }
}

TEST(Agreement, CompareSweepAndRecommendMeasureTheSameModelAlike) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const double duration = 25.0;
  study::ReferenceOptions reference;
  reference.max_levels = 2;

  study::RecommendRequest recommend_request;
  recommend_request.duration = duration;
  recommend_request.reference = reference;
  const study::Recommendation rec = study::recommend(scene, recommend_request);
  ASSERT_TRUE(rec.chosen);
  const study::Candidate& chosen = rec.candidates[*rec.chosen];
  const scene::Stiffening stiffening = rec.reference_scene.boom.stiffening;
  EXPECT_EQ(stiffening, scene::Stiffening::static_load) << "5 % of the Euler load: the physics needs static stiffening";

  // Compare at the candidates' tolerance and integrator.
  study::DynamicsRequest dynamics;
  dynamics.integrator = chosen.integrator;
  dynamics.relative_tolerance = dynamics.absolute_tolerance = rec.reasoning.relative_tolerance;
  dynamics.duration = duration;
  study::CompareRequest compare_request;
  compare_request.settings = study::integrator_settings(scene, dynamics);
  compare_request.reference = reference;
  const study::Comparison comparison = study::compare(scene, compare_request);

  // The sweep's reference, and the chosen model run as a sweep configuration against it.
  study::SweepRequest sweep_request;
  sweep_request.duration = duration;
  sweep_request.reference = reference;
  sweep_request.shard = {0, 1'000'000};  // configuration 0 only: the reference is what is compared
  const study::SweepStudy sweep = study::sweep(scene, sweep_request);
  scene::Scene modelled = scene;
  modelled.boom.stiffening = sweep.stiffening;
  const study::SweepSetup setup{&modelled, &sweep.reference, sweep.window_start, sweep.judged, duration, 2'000'000, nullptr};
  const study::SweepResult configured = study::run_configuration(
      setup, {0, chosen.choice, chosen.integrator, rec.reasoning.relative_tolerance, 0.0, 0.0, std::nullopt});
  ASSERT_EQ(configured.status, study::RunStatus::ok) << configured.reason;

  // Same reference physics, window and judged outputs.
  EXPECT_EQ(comparison.stiffening, stiffening);
  EXPECT_EQ(sweep.stiffening, stiffening);
  expect_same_reference(comparison.reference, rec.reference, "compare vs recommend");
  expect_same_reference(sweep.reference, rec.reference, "sweep vs recommend");
  EXPECT_EQ(comparison.window_start, rec.reference.window_start);
  EXPECT_EQ(sweep.window_start, rec.reference.window_start);
  EXPECT_EQ(comparison.judged, rec.outputs);
  EXPECT_EQ(sweep.judged, rec.outputs);
  EXPECT_GT(rec.reference.window_start, 0.0) << "errors after the wave ramp";

  // The same error for the same model.
  EXPECT_EQ(configured.worst.error, chosen.error) << chosen.label();
  EXPECT_EQ(std::string(multibody::channel_name(configured.worst.channel)), chosen.worst_output);
  bool found = false;
  for (std::size_t m = 0; m < comparison.runs.size(); ++m) {
    if (!same_model(comparison.runs[m].choice, chosen.choice, stiffening)) continue;
    found = true;
    EXPECT_EQ(comparison.worst[m].error, chosen.error) << chosen.label();
  }
  EXPECT_TRUE(found) << "compare's models include the recommended " << chosen.label();
}

// The quick sweep's verdict as `ffrf sweep` gives it (report::sweep_verdict on the CSV rows): the
// index of the cheapest passing configuration.
std::optional<std::size_t> sweep_cheapest(const study::SweepStudy& sweep) {
  std::string csv = report::sweep_csv_header();
  for (const study::SweepResult& r : sweep.results) csv += report::sweep_csv_line(r);
  const std::vector<report::SweepRow> rows = report::read_sweep_csv(csv, "sweep.csv");
  report::SweepFacts facts;
  facts.tolerance = sweep.tolerance;
  facts.reference_wall_seconds = sweep.reference.run.result.stats.wall_seconds;
  facts.reference_work = sweep.reference.run.work();
  return report::sweep_verdict(rows, facts).cheapest;
}

study::SweepStudy quick_sweep(const scene::Scene& scene, double duration) {
  study::SweepRequest request;
  request.duration = duration;
  request.jobs = 2;
  return study::sweep(scene, request);
}

// recommend, the quick sweep and compare on one scene name the same model, at the same rtol.
void expect_one_cheapest(const scene::Scene& scene, double duration, const study::Recommendation& rec) {
  ASSERT_TRUE(rec.chosen) << "recommend names a model";
  const study::Candidate& chosen = rec.candidates[*rec.chosen];
  const scene::Stiffening stiffening = rec.reference_scene.boom.stiffening;
  EXPECT_EQ(rec.reasoning.relative_tolerance, study::model_choice_rtol(0.01));
  EXPECT_EQ(chosen.integrator, solve::Integrator::cvode) << chosen.label();
  // No candidate that recommend ran and saw pass did less solver work than the one it names.
  for (const study::Candidate& c : rec.candidates) {
    if (c.status == study::CandidateStatus::passed) { EXPECT_GE(c.work(), chosen.work()) << c.label(); }
  }

  const study::SweepStudy sweep = quick_sweep(scene, duration);
  EXPECT_EQ(sweep.stiffening, stiffening);
  const std::optional<std::size_t> cheapest = sweep_cheapest(sweep);
  ASSERT_TRUE(cheapest) << "the quick sweep names a configuration";
  const study::SweepConfig& config = sweep.results[*cheapest].config;
  EXPECT_TRUE(same_model(config.choice, chosen.choice, stiffening))
      << "sweep --quick: " << config.choice.label() << "; recommend: " << chosen.label();
  EXPECT_EQ(config.integrator, chosen.integrator);
  EXPECT_EQ(config.rtol, rec.reasoning.relative_tolerance) << "judged at the same rtol";

  study::DynamicsRequest dynamics;
  dynamics.relative_tolerance = dynamics.absolute_tolerance = study::model_choice_rtol(0.01);
  dynamics.duration = duration;
  study::CompareRequest compare_request;
  compare_request.settings = study::integrator_settings(scene, dynamics);
  const study::Comparison comparison = study::compare(scene, compare_request);
  ASSERT_TRUE(comparison.verdict.cheapest);
  const scene::BoomChoice& compared = comparison.runs[*comparison.verdict.cheapest].choice;
  EXPECT_TRUE(same_model(compared, chosen.choice, stiffening)) << "compare: " << compared.label() << "; recommend: " << chosen.label();
}

TEST(Agreement, RecommendSweepAndCompareNameOneCheapestModelOnTheReferenceScene) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const double duration = 40.0;
  study::RecommendRequest request;
  request.duration = duration;
  const study::Recommendation rec = study::recommend(scene, request);
  expect_one_cheapest(scene, duration, rec);
}

TEST(Agreement, OperabilityCellModelIsTheCheapestThatRecommendAndSweepNameInThatSea) {
  // A one-cell operability grid on the reference crane: JONSWAP Hs 1 m, Tp 6 s, following.
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  study::OperabilityRequest request;
  request.significant_heights = {1.0};
  request.peak_periods = {6.0};
  request.seeds = 1;
  request.duration = 1800.0;
  const std::vector<study::SeaCell> cells = study::sea_cells(request);
  ASSERT_EQ(cells.size(), 1u);
  const study::CellModel model = study::recommended_model(scene, cells[0], request, nullptr);

  // The cell's sea as its probe record: what recommend and the sweep run on.
  const double probe = study::probe_duration(cells[0], request);
  EXPECT_EQ(probe, 20.0 * 6.0);
  study::OperabilityRequest probe_request = request;
  probe_request.duration = probe;
  const scene::Scene sea = study::record_scene(scene, cells[0], study::record_seed(cells[0], 0), probe_request);
  study::RecommendRequest recommend_request;
  recommend_request.duration = probe;
  const study::Recommendation rec = study::recommend(sea, recommend_request);
  ASSERT_TRUE(rec.chosen);
  const study::Candidate& chosen = rec.candidates[*rec.chosen];
  EXPECT_TRUE(same_model(model.choice, chosen.choice, rec.reference_scene.boom.stiffening))
      << "operability: " << model.label() << "; recommend: " << chosen.label();
  EXPECT_EQ(model.integrator, chosen.integrator);
  EXPECT_EQ(model.relative_tolerance, rec.reasoning.relative_tolerance) << "its records run at the rtol it was chosen at";
  expect_one_cheapest(sea, probe, rec);
}

}  // namespace
