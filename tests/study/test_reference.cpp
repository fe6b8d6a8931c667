// The converged reference (cases/reference_model.hpp) is shown converged by its own check: the
// last refinement (half the element size, a tenth of the tolerance) changed the outputs by less
// than the stated bound, the changes shrink from level to level, and an independent re-comparison
// of the last two levels reproduces the recorded change.
#include <gtest/gtest.h>

#include <cstdio>

#include "cases/reference_model.hpp"
#include "coupling/error_metrics.hpp"
#include "crane_test_support.hpp"

namespace {

using namespace ffrf;

TEST(ReferenceModel, ReferenceSceneReferenceIsConvergedByItsOwnCheck) {
  const cases::Scene scene = test::reference_scene();
  cases::ReferenceRequest request;
  request.start_elements = 4;
  request.start_relative_tolerance = 1e-6;
  request.bound = 1e-5;  // tight, so that the check takes several levels
  request.max_levels = 4;
  request.duration = 40.0;  // ramp (20 s) + two wave periods
  const cases::ConvergedReference reference = cases::converged_reference(scene, request);
  for (const auto& level : reference.levels) {
    std::printf("reference level N=%d rtol=%.0e change=%.3g\n", level.elements, level.relative_tolerance, level.change);
  }
  ASSERT_TRUE(reference.converged);
  ASSERT_GE(reference.levels.size(), 2u);
  EXPECT_LT(reference.levels.back().change, request.bound);
  for (std::size_t i = 2; i < reference.levels.size(); ++i) {
    EXPECT_LT(reference.levels[i].change, reference.levels[i - 1].change) << "level " << i;
  }
  // Re-run the previous level independently and compare with the reference.
  const auto& previous = reference.levels[reference.levels.size() - 2];
  auto equations = cases::build_crane(scene, {cases::BoomKind::nodal, previous.elements, 0, false});
  coupling::IntegratorSettings settings = reference.settings;
  settings.relative_tolerance = settings.absolute_tolerance = previous.relative_tolerance;
  const auto run = coupling::integrate(*equations, coupling::solve_static_equilibrium(*equations, equations->initial_guess()).z, settings);
  const double change = coupling::compare_runs(run, reference.run, reference.window_start).worst_normalized_rms();
  EXPECT_NEAR(change, reference.levels.back().change, 1e-6 + 1e-3 * change);
}

}  // namespace
