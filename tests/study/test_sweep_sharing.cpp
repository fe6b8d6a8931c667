// A sweep shares its models: one eigen solve per distinct mesh, one build per distinct
// crane model, and results that do not depend on the sharing or on the thread count — the quick
// grid over 4 s run with 1 and with 2 threads, and each configuration again on a model of its own
// (the unshared path: run_configuration without a model cache), all identical bit for bit apart
// from the wall time.
#include <gtest/gtest.h>

#include <set>

#include "study/sweep.hpp"
#include "study_test_support.hpp"
#include "sweep_rows.hpp"

namespace {

using namespace ffrf;

using test::expect_same_result;

TEST(SweepSharing, OneSolvePerMeshOneBuildPerModelAndTheSameResultsOnAnyThreadCount) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  study::SweepRequest request;
  request.grid = study::SweepGrid::quick;
  request.duration = 4.0;
  request.stiffening = scene::Stiffening::none;
  request.reference.max_levels = 1;
  request.jobs = 1;
  const study::SweepStudy serial = study::sweep(scene, request);
  request.jobs = 2;
  const study::SweepStudy threaded = study::sweep(scene, request);

  // What the grid holds, counted independently of the caches: its distinct models (labels) and
  // the distinct meshes of its modal booms.
  std::set<std::string> models;
  std::set<int> modal_meshes;
  for (const study::SweepConfig& config : study::sweep_grid(request.grid)) {
    models.insert(config.choice.label());
    if (config.choice.kind == scene::BoomKind::modal) modal_meshes.insert(config.choice.elements);
  }
  ASSERT_EQ(modal_meshes.size(), 1u);
  for (const study::SweepStudy* study : {&serial, &threaded}) {
    EXPECT_EQ(study->models_built, static_cast<int>(models.size()));
    EXPECT_EQ(study->eigen_solves, static_cast<int>(modal_meshes.size()));
  }

  ASSERT_EQ(serial.results.size(), threaded.results.size());
  int ok = 0;
  for (std::size_t i = 0; i < serial.results.size(); ++i) {
    expect_same_result(serial.results[i], threaded.results[i]);
    ok += serial.results[i].status == study::RunStatus::ok;
  }
  EXPECT_GT(ok, 15) << "most of the quick grid runs (a test of identical failures would prove little)";

  // Each configuration on a model of its own, as before the models were shared.
  const study::SweepSetup own{&serial.scene, &serial.reference, serial.window_start, serial.judged, request.duration,
                              request.max_explicit_steps, nullptr};
  for (const study::SweepResult& shared : serial.results) expect_same_result(shared, study::run_configuration(own, shared.config));
}

}  // namespace
