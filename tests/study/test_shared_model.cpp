// Model and workspace apart: CraneEquations made from ONE shared crane model
// (scene/crane_model_cache.hpp, multibody/crane_model.hpp) and integrated by several threads at
// once give, bit for bit, what a run on a model of its own gives serially (the second method: the
// unshared path, build_crane_equations → its own model). Nodal and modal booms on the reference scene, and
// the BEM barge crane with Cummins convolution radiation, whose radiation memory is run state that
// each set of equations must own. Also: making more equations from a model repeats no eigen
// solve and no model build.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "scene/crane_model_cache.hpp"
#include "study/run_pipeline.hpp"
#include "study_test_support.hpp"

namespace {

using namespace ffrf;

void expect_identical(const multibody::RunResult& a, const multibody::RunResult& b, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(a.time.size(), b.time.size());
  ASSERT_EQ(a.samples.size(), b.samples.size());
  EXPECT_EQ(a.stats.steps, b.stats.steps);
  EXPECT_EQ(a.stats.function_evaluations, b.stats.function_evaluations);
  EXPECT_EQ(a.stats.jacobian_evaluations, b.stats.jacobian_evaluations);
  EXPECT_EQ(a.stats.newton_iterations, b.stats.newton_iterations);
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const multibody::CraneOutputs &x = a.samples[i], &y = b.samples[i];
    ASSERT_EQ(a.time[i], b.time[i]) << i;
    // Bitwise: == on every number (no tolerance); the first difference stops the comparison.
    const bool same = x.hull == y.hull && x.cargo == y.cargo && x.tip_deflection == y.tip_deflection &&
                      x.wire_tension == y.wire_tension && x.wire_length == y.wire_length &&
                      x.joint_reaction == y.joint_reaction && x.root_axial_force == y.root_axial_force &&
                      x.kinetic_energy == y.kinetic_energy && x.strain_energy == y.strain_energy &&
                      x.gravity_energy == y.gravity_energy && x.wire_energy == y.wire_energy;
    ASSERT_TRUE(same) << "sample " << i << " (t = " << a.time[i] << " s): cargo heave " << x.cargo.y() << " vs "
                      << y.cargo.y() << ", wire tension " << x.wire_tension << " vs " << y.wire_tension;
  }
}

// Serial runs on models of their own, then `threads` runs at once on one shared model.
void check_concurrent_runs(const scene::Scene& scene, const scene::BoomChoice& choice, double duration, int threads) {
  study::DynamicsRequest request;
  request.duration = duration;
  const multibody::RunSettings settings = study::integrator_settings(scene, request);
  const study::ModelRun serial = study::run_model(scene, choice, settings);

  scene::CraneModelCache models(scene);
  std::vector<study::ModelRun> runs(static_cast<std::size_t>(threads));
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) {
    workers.emplace_back([&, t] {
      study::PreparedRun prepared = study::prepare_run(models, choice);
      runs[static_cast<std::size_t>(t)] = study::integrate_run(models.scene(), prepared, settings);
    });
  }
  for (std::thread& worker : workers) worker.join();
  EXPECT_EQ(models.models_built(), 1) << "one shared model for all threads";
  EXPECT_EQ(models.modes().eigen_solves(), choice.kind == scene::BoomKind::modal ? 1 : 0);
  ASSERT_GT(serial.result.samples.size(), 10u);
  for (int t = 0; t < threads; ++t) expect_identical(serial.result, runs[static_cast<std::size_t>(t)].result, choice.label() + ", thread " + std::to_string(t));
  // The statics too (KINSOL on each run's own equations).
  EXPECT_EQ(serial.statics.z, runs[0].statics.z);
}

TEST(SharedModel, ThreadsOnOneNodalModelMatchSerialRunsBitwise) {
  check_concurrent_runs(test::scene_file("paper_floating_crane.toml"), {scene::BoomKind::nodal, 8}, 10.0, 3);
}

TEST(SharedModel, ThreadsOnOneModalModelMatchSerialRunsBitwise) {
  check_concurrent_runs(test::scene_file("paper_floating_crane.toml"), {scene::BoomKind::modal, 16, 4, true}, 10.0, 3);
}

TEST(SharedModel, ThreadsWithConvolutionRadiationMemoryMatchSerialRunsBitwise) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  ASSERT_TRUE(scene.bem.has_value());
  check_concurrent_runs(scene, {scene::BoomKind::nodal, 4}, 6.0, 3);
}

TEST(SharedModel, MoreEquationsFromAModelRepeatNoSolveAndNoBuild) {
  scene::CraneModelCache models(test::scene_file("paper_floating_crane.toml"));
  const scene::BoomChoice modal{scene::BoomKind::modal, 16, 6, false};
  const auto first = models.model(modal);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(models.model(modal), first) << "the same object, not a copy";
    EXPECT_EQ(first->equations()->elastic_size(), 6);
  }
  // k = 4 on the same mesh: another model, but served by the same eigen solve (modal/mode_cache.hpp).
  EXPECT_NE(models.model({scene::BoomKind::modal, 16, 4, false}), first);
  EXPECT_EQ(models.models_built(), 2);
  EXPECT_EQ(models.modes().eigen_solves(), 1);
}

}  // namespace
