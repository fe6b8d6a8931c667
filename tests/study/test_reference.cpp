// The converged reference (study/reference.hpp) is shown converged by its own check: the last
// refinement (half the element size, a tenth of the tolerance) changed the outputs by less than the
// stated bound, the changes shrink from level to level, and an independent re-run of the previous
// level (built here from the coupling library, not through the study) reproduces the recorded change.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "multibody/error_metrics.hpp"
#include "multibody/crane_statics.hpp"
#include "study/recommend.hpp"
#include "study/reference.hpp"
#include "study_test_support.hpp"

namespace {

using namespace ffrf;

TEST(Reference, ReferenceSceneReferenceIsConvergedByItsOwnCheck) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  study::ReferenceOptions options;
  options.start_elements = 4;
  options.start_relative_tolerance = 1e-6;
  options.bound = 1e-5;  // tight, so that the check takes several levels
  options.max_levels = 4;
  const double duration = 40.0;  // ramp (20 s) + two wave periods
  const study::ConvergedReference reference = study::converged_reference(scene, options, duration);
  for (const auto& level : reference.levels) {
    std::printf("reference level N=%d rtol=%.0e change=%.3g\n", level.elements, level.relative_tolerance, level.change);
  }
  ASSERT_TRUE(reference.converged);
  ASSERT_GE(reference.levels.size(), 2u);
  EXPECT_LT(reference.levels.back().change, options.bound);
  for (std::size_t i = 2; i < reference.levels.size(); ++i) {
    EXPECT_LT(reference.levels[i].change, reference.levels[i - 1].change) << "level " << i;
  }
  // Re-run the previous level independently and compare with the reference.
  const auto& previous = reference.levels[reference.levels.size() - 2];
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, previous.elements, 0, false});
  multibody::RunSettings settings = reference.settings;
  settings.relative_tolerance = settings.absolute_tolerance = previous.relative_tolerance;
  const auto run = multibody::simulate(*equations, multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z, settings);
  const double change = multibody::compare_runs(run, reference.run.result, reference.window_start).worst_normalized_rms();
  EXPECT_NEAR(change, reference.levels.back().change, 1e-6 + 1e-3 * change);
}

TEST(Reference, OneSetOfDefaultsTwoDecadesBelowTheModelsAndATenthOfTheVerdictTolerance) {
  // docs/architecture.md and study/reference.hpp: N0 = 8, rtol0 = 1e-6, bound 1e-3, 3 levels.
  const study::ReferenceOptions defaults;
  const study::DynamicsRequest models;  // what compare runs its models at by default
  EXPECT_EQ(defaults.start_elements, 8);
  EXPECT_EQ(defaults.max_levels, 3);
  const double last_rtol = defaults.start_relative_tolerance * std::pow(0.1, defaults.max_levels - 1);
  EXPECT_NEAR(last_rtol, models.relative_tolerance / 100.0, 1e-20);
  EXPECT_NEAR(defaults.bound, study::RecommendRequest{}.tolerance / 10.0, 1e-15);
}

}  // namespace
