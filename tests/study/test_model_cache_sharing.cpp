// What the sweep's model cache (scene/crane_model_cache.hpp) shares beyond the boom models of
// test_sweep_sharing.cpp, each checked by counting builds against the distinct models counted
// independently (labels), and by rows equal (==) to the path without sharing (each configuration
// builds its own model from its own scene and solves its own static equilibrium — the path before):
//  * the radiation axis on a [bem] scene: one model per distinct (boom model, radiation model);
//  * the converged reference: its levels come from the same cache, so a level the grid also holds
//    (nodal N = 16) is built once;
//  * the static equilibrium: solved once per model, equal bit for bit to a run's own solve.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>

#include "scene/crane_model_cache.hpp"
#include "study/radiation_compare.hpp"
#include "study/sweep.hpp"
#include "study_test_support.hpp"
#include "sweep_rows.hpp"

namespace ffrf::study {
namespace {

using test::expect_same_result;

TEST(ModelCacheSharing, ARadiationAxisBuildsOneModelPerBoomAndRadiationModelWithUnchangedRows) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  SweepRequest request;
  request.duration = 3.0;  // within the 16 s wave ramp: a one-level reference
  request.stiffening = scene::Stiffening::none;
  request.radiation_axis = true;
  modal::ModeCache modes;
  SweepStudy study = sweep_scene(scene, request);
  scene::CraneModelCache models(study.scene, &modes);
  measure_reference(study, request, models);
  ASSERT_EQ(study.reference_models_built, 1);
  const int after_reference = models.models_built();

  // Three boom models of the quick grid crossed with the three radiation models, BDF, generalized-α and
  // (rigid) explicit RK.
  const std::set<std::string> booms{"rigid", "nodal N=4", "modal k=2+static (N=16)"};
  std::vector<SweepConfig> configs;
  std::set<std::pair<std::string, int>> distinct;  // (boom model, radiation model)
  for (const SweepConfig& config : sweep_grid(SweepGrid::quick, true)) {
    if (booms.count(config.choice.label()) == 0) continue;
    configs.push_back(config);
    distinct.insert({config.choice.label(), static_cast<int>(*config.radiation)});
  }
  ASSERT_EQ(distinct.size(), 9u) << "the grid holds the three boom models with the three radiation models";
  ASSERT_GT(configs.size(), distinct.size()) << "some models are shared by two integrators";

  const SweepSetup shared{&study.scene, &study.reference, study.window_start, study.judged, request.duration,
                          request.max_explicit_steps, &models};
  const SweepSetup own{&study.scene, &study.reference, study.window_start, study.judged, request.duration,
                       request.max_explicit_steps, nullptr};
  for (const SweepConfig& config : configs) {
    const SweepResult row = run_configuration(shared, config);
    // The quick grid's explicit run past its stability limit must fail; every other one runs.
    if (config.integrator != solve::Integrator::arkode) {
      ASSERT_EQ(row.status, RunStatus::ok) << config.choice.label() << ": " << row.reason;
    }
    expect_same_result(row, run_configuration(own, config));
  }
  EXPECT_EQ(models.models_built() - after_reference, static_cast<int>(distinct.size()));
  EXPECT_EQ(models.equilibria_solved() - 1, static_cast<int>(distinct.size())) << "one static solve per model";
  EXPECT_EQ(modes.eigen_solves(), 1) << "one mesh of modal booms";
  // The convolution models are the study scene's own (the reference's radiation model): no copy of the scene.
  EXPECT_EQ(&models.scene(hydro::RadiationKind::convolution), &models.scene());
  EXPECT_EQ(models.scene(hydro::RadiationKind::state_space).bem->radiation_model, hydro::RadiationKind::state_space);
}

TEST(ModelCacheSharing, TheReferenceLevelsAndTheGridShareOneBuildPerDistinctModel) {
  scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  ASSERT_TRUE(scene.wave.has_value());
  scene.wave->ramp_periods = 0.0;  // no ramp: every reference level runs on a short record
  SweepRequest request;
  request.grid = SweepGrid::quick;
  request.duration = 3.0;
  request.stiffening = scene::Stiffening::none;
  request.reference.max_levels = 2;
  request.reference.bound = 1e-12;  // both levels run
  request.jobs = 2;
  const SweepStudy study = sweep(scene, request);

  // The distinct models, counted from the labels: the grid's, the reference's levels, and both.
  std::set<std::string> grid, levels;
  for (const SweepConfig& config : sweep_grid(request.grid)) grid.insert(config.choice.label());
  for (const ReferenceLevel& level : study.reference.levels) levels.insert(scene::BoomChoice{scene::BoomKind::nodal, level.elements}.label());
  ASSERT_EQ(levels, (std::set<std::string>{"nodal N=8", "nodal N=16"}));
  ASSERT_EQ(grid.count("nodal N=16"), 1u) << "the grid holds a reference level's model";
  std::set<std::string> all = grid;
  all.insert(levels.begin(), levels.end());
  EXPECT_EQ(study.reference_models_built, static_cast<int>(levels.size()));
  EXPECT_EQ(study.reference_models_built + study.models_built, static_cast<int>(all.size())) << "nodal N=16 built once";

  // The reference through the cache equals the reference on models of its own (converged_reference
  // on the scene), and the rows equal the rows without sharing.
  const ConvergedReference alone = converged_reference(study.scene, request.reference, request.duration);
  ASSERT_EQ(alone.run.result.samples.size(), study.reference.run.result.samples.size());
  EXPECT_EQ(alone.run.result.stats.steps, study.reference.run.result.stats.steps);
  EXPECT_EQ(alone.levels.back().change, study.reference.levels.back().change);
  for (std::size_t i = 0; i < alone.run.result.samples.size(); ++i) {
    ASSERT_EQ(alone.run.result.samples[i].cargo, study.reference.run.result.samples[i].cargo) << "sample " << i;
    ASSERT_EQ(alone.run.result.samples[i].wire_tension, study.reference.run.result.samples[i].wire_tension) << "sample " << i;
  }
  const SweepSetup own{&study.scene, &study.reference, study.window_start, study.judged, request.duration,
                       request.max_explicit_steps, nullptr};
  for (const SweepResult& row : study.results) {
    if (row.config.choice.label() == "nodal N=16") expect_same_result(row, run_configuration(own, row.config));
  }
}

TEST(ModelCacheSharing, AStaticEquilibriumIsSolvedOncePerModelAndEqualsARunsOwnSolve) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  scene::CraneModelCache models(scene);
  const scene::BoomChoice nodal{scene::BoomKind::nodal, 8}, modal{scene::BoomKind::modal, 16, 2, true};
  for (int i = 0; i < 3; ++i) {
    for (const scene::BoomChoice& choice : {nodal, modal}) {
      const PreparedRun shared = prepare_run(models, choice);
      const PreparedRun alone = prepare_run(scene, choice);  // its own model, its own KINSOL solve
      EXPECT_EQ(shared.statics.z, alone.statics.z) << choice.label();
      EXPECT_EQ(shared.statics.outputs.wire_tension, alone.statics.outputs.wire_tension) << choice.label();
      EXPECT_EQ(shared.statics.newton_iterations, alone.statics.newton_iterations) << choice.label();
      EXPECT_EQ(shared.initial_state, alone.initial_state) << choice.label();
    }
  }
  EXPECT_EQ(models.models_built(), 2);
  EXPECT_EQ(models.equilibria_solved(), 2);
  // A different stiffening is a different model with its own equilibrium (the boom's geometric
  // stiffness moves the tip: z differs).
  scene::BoomChoice stiffened = nodal;
  stiffened.stiffening = scene::Stiffening::static_load;
  const multibody::StaticEquilibrium other = models.static_equilibrium(stiffened);
  EXPECT_EQ(models.equilibria_solved(), 3);
  EXPECT_NE(other.z, models.static_equilibrium(nodal).z);
  EXPECT_EQ(models.equilibria_solved(), 3);
}

}  // namespace
}  // namespace ffrf::study
