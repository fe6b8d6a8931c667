// The radiation model as an axis of `ffrf sweep`: on a scene with [bem] the grid is
// crossed with the three radiation models, and each configuration is measured against the converged
// reference run with the Cummins convolution. Checked against independent facts: the convolution
// configuration is the reference's own model, so its error is at the level of the reference's own
// convergence (its last level change); the state-space fit's error is bounded by its stated
// impulse-response error e_r; constant A, B at the wave frequency cannot follow the barge's
// frequency-dependent damping, so its error exceeds the state-space model's.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "scene/bem_hull_model.hpp"
#include "scene/crane_model_cache.hpp"
#include "study/radiation_compare.hpp"
#include "study/sweep.hpp"
#include "study_test_support.hpp"

namespace ffrf::study {
namespace sweep_radiation_test {

using hydro::RadiationKind;

TEST(SweepRadiation, TheGridIsCrossedWithTheThreeRadiationModelsOnlyWhenAsked) {
  const std::vector<SweepConfig> plain = sweep_grid(SweepGrid::quick);
  const std::vector<SweepConfig> crossed = sweep_grid(SweepGrid::quick, true);
  ASSERT_EQ(crossed.size(), 3 * plain.size());
  const std::array kinds{RadiationKind::constant, RadiationKind::state_space, RadiationKind::convolution};
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(plain[i].id, static_cast<int>(i));
    EXPECT_FALSE(plain[i].radiation.has_value());
    EXPECT_EQ(radiation_name(plain[i]), "");
    for (std::size_t k = 0; k < kinds.size(); ++k) {
      const SweepConfig& c = crossed[3 * i + k];
      EXPECT_EQ(c.id, static_cast<int>(3 * i + k));
      EXPECT_EQ(c.choice.label(), plain[i].choice.label());
      EXPECT_EQ(integrator_label(c), integrator_label(plain[i]));
      ASSERT_TRUE(c.radiation.has_value());
      EXPECT_EQ(*c.radiation, kinds[k]);
    }
  }
}

// A pinned boom's sweep repeats every modal model with the free-free and the chord frame's mode
// sets, after the plain grid's configurations, which keep their ids.
TEST(SweepModeSets, TheFreeFreeAndPinnedPinnedSetsAreAppendedAndThePlainIdsStay) {
  const std::vector<SweepConfig> plain = sweep_grid(SweepGrid::quick);
  const std::vector<SweepConfig> with_sets = sweep_grid(SweepGrid::quick, false, 1e-6, true);
  std::size_t plain_modal = 0, chord = 0, free = 0;
  for (const SweepConfig& c : plain) plain_modal += c.choice.kind == scene::BoomKind::modal ? 1 : 0;
  for (const SweepConfig& c : with_sets) chord += c.choice.mode_set == fem::Boundary::pinned_pinned ? 1 : 0;
  for (const SweepConfig& c : with_sets) free += c.choice.mode_set == fem::Boundary::free_free ? 1 : 0;
  EXPECT_EQ(chord, plain_modal);
  EXPECT_EQ(free, plain_modal);
  EXPECT_EQ(with_sets.size(), plain.size() + chord + free);
  std::size_t same = 0;
  for (std::size_t i = 0; i < plain.size() && i < with_sets.size(); ++i) {
    same += plain[i].choice.label() == with_sets[i].choice.label() && plain[i].integrator == with_sets[i].integrator ? 1 : 0;
  }
  // The quick grid's last plain configuration (the explicit run past its limit) follows the models.
  EXPECT_GE(same, plain.size() - 1);
  for (const SweepConfig& c : with_sets) {
    if (c.choice.mode_set != fem::Boundary::clamped_free) {
      EXPECT_EQ(c.choice.kind, scene::BoomKind::modal) << c.choice.label();
    }
  }
}

TEST(SweepRadiation, ASceneWithoutBemCannotHaveTheAxis) {
  SweepRequest request;
  request.duration = 5.0;
  request.radiation_axis = true;
  EXPECT_THROW(sweep_reference(test::scene_file("paper_floating_crane.toml"), request, nullptr), scene::SceneError);
}

TEST(SweepRadiation, ErrorsAgainstTheConvolutionReferenceOrderTheRadiationModels) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  SweepRequest request;
  request.duration = 40.0;  // the wave ramp ends at 16 s: 24 s of error window
  request.reference.max_levels = 2;
  request.radiation_axis = true;
  modal::ModeCache modes;
  const SweepStudy study = sweep_reference(scene, request, &modes);
  ASSERT_TRUE(study.scene.bem.has_value());
  EXPECT_EQ(study.scene.bem->radiation_model, RadiationKind::convolution);  // the reference's model
  ASSERT_EQ(study.reference.levels.size(), 2u);
  scene::CraneModelCache models(study.scene, &modes);
  const SweepSetup setup{&study.scene, &study.reference, study.window_start, study.judged, request.duration,
                         request.max_explicit_steps, &models};
  // The reference's own mesh at the models' default tolerance, with each radiation model.
  SweepConfig config;
  config.choice = study.reference.choice;
  config.rtol = 1e-6;
  std::array<double, 3> error{};
  const std::array kinds{RadiationKind::constant, RadiationKind::state_space, RadiationKind::convolution};
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    config.radiation = kinds[k];
    const SweepResult result = run_configuration(setup, config);
    ASSERT_EQ(result.status, RunStatus::ok) << result.reason;
    error[k] = result.worst.error;
  }
  const double constant = error[0], state_space = error[1], convolution = error[2];
  const double fit_error = scene::bem_radiation_model(with_radiation(scene, RadiationKind::state_space))->fit_error;
  // Same model and mesh as the reference at a ten times looser tolerance: of the order of the
  // reference's own last level change (the integration error), far below the verdict's 1 %.
  EXPECT_LT(convolution, 3.0 * study.reference.levels.back().change);
  EXPECT_LT(convolution, 1e-2 * state_space);
  EXPECT_GT(state_space, convolution);
  EXPECT_LT(state_space, fit_error);  // the fit's stated impulse-response error e_r bounds its effect
  EXPECT_GT(constant, state_space);   // B(ω) of the barge is not one number
  std::printf("errors: constant %.3g, state-space %.3g (e_r %.3g), convolution %.3g; reference change %.3g\n", constant,
              state_space, fit_error, convolution, study.reference.levels.back().change);
}

}  // namespace sweep_radiation_test
}  // namespace ffrf::study
