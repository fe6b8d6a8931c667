// The boom model of a run (study/boom_choice.hpp), the one check every front end goes through: the
// scene's default, overrides, and each bad request named by its setting, value and range. The mode
// count's range is checked against the built nodal boom's elastic coordinates (3N for N elements).
#include <gtest/gtest.h>

#include <string>

#include "study/boom_choice.hpp"
#include "study/run_pipeline.hpp"
#include "study/work_limits.hpp"
#include "study_test_support.hpp"

namespace ffrf::study {
namespace boom_choice_test {

// The SettingError a request raises (fails the test when it raises none).
SettingError refusal(const BoomRequest& request, const scene::BoomChoice& base) {
  try {
    boom_choice(request, base);
  } catch (const SettingError& error) {
    return error;
  }
  ADD_FAILURE() << "no SettingError";
  return SettingError(Setting::boom_model, "", "");
}

TEST(BoomChoice, DefaultsToTheScenesMeshAndOverridesWhatIsSet) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const scene::BoomChoice base = default_boom_choice(scene);
  EXPECT_EQ(base.kind, scene::BoomKind::nodal);
  EXPECT_EQ(base.elements, scene.boom.mesh.element_count);
  EXPECT_EQ(base.modes, default_modal_modes);
  EXPECT_TRUE(base.static_modes);
  EXPECT_FALSE(base.stiffening.has_value());

  const scene::BoomChoice unchanged = boom_choice({}, base);  // nothing asked: the default
  EXPECT_EQ(unchanged.label(), base.label());
  EXPECT_EQ(unchanged.modes, base.modes);
  EXPECT_EQ(unchanged.static_modes, base.static_modes);
  BoomRequest request;
  request.kind = "modal";
  request.elements = 12;
  request.modes = 4;
  request.static_modes = false;
  request.stiffening = "static";
  const scene::BoomChoice modal = boom_choice(request, base);
  EXPECT_EQ(modal.kind, scene::BoomKind::modal);
  EXPECT_EQ(modal.elements, 12);
  EXPECT_EQ(modal.modes, 4);
  EXPECT_FALSE(modal.static_modes);
  EXPECT_EQ(modal.stiffening, scene::Stiffening::static_load);
}

TEST(BoomChoice, ModeCountRangeIsTheNodalBoomsElasticCoordinates) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const int elements = 2;
  const int elastic = prepare_run(scene, scene::BoomChoice{scene::BoomKind::nodal, elements}).equations->elastic_size();
  BoomRequest request;
  request.kind = "modal";
  request.elements = elements;
  request.modes = elastic - 1;
  EXPECT_EQ(boom_choice(request, default_boom_choice(scene)).modes, elastic - 1);
  request.modes = elastic;
  const SettingError error = refusal(request, default_boom_choice(scene));
  EXPECT_EQ(error.setting(), Setting::modes);
  EXPECT_EQ(error.value(), std::to_string(elastic));
  EXPECT_NE(error.problem().find("valid range [1, " + std::to_string(elastic - 1) + "]"), std::string::npos) << error.what();
  request.modes = 0;
  EXPECT_EQ(refusal(request, default_boom_choice(scene)).setting(), Setting::modes);
}

TEST(BoomChoice, BadRequestsNameTheSettingValueAndChoices) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const scene::BoomChoice base = default_boom_choice(scene);
  BoomRequest kind;
  kind.kind = "flexible";
  const SettingError unknown = refusal(kind, base);
  EXPECT_EQ(unknown.setting(), Setting::boom_model);
  EXPECT_EQ(unknown.value(), "flexible");
  EXPECT_NE(unknown.problem().find("rigid|nodal|modal"), std::string::npos) << unknown.what();

  BoomRequest stiffening;
  stiffening.stiffening = "stiff";
  EXPECT_EQ(refusal(stiffening, base).setting(), Setting::stiffening);

  BoomRequest none;
  none.elements = 0;
  const SettingError zero = refusal(none, base);
  EXPECT_EQ(zero.setting(), Setting::elements);
  EXPECT_NE(zero.problem().find("[1, inf)"), std::string::npos) << zero.what();

  BoomRequest huge;  // more elements than the memory limit allows (study/work_limits.hpp)
  huge.elements = max_nodal_elements() + 1;
  EXPECT_EQ(refusal(huge, base).setting(), Setting::elements);

  BoomRequest unknown_set;  // a set that is not a boundary condition, refused with the valid ones
  unknown_set.kind = "modal";
  unknown_set.mode_set = "hinged";
  const SettingError unknown_mode_set = refusal(unknown_set, base);
  EXPECT_EQ(unknown_mode_set.setting(), Setting::mode_set);
  EXPECT_NE(unknown_mode_set.problem().find("clamped-free|free-free|pinned-pinned"), std::string::npos) << unknown_mode_set.what();

  BoomRequest nodal_set;  // a mode set belongs to a modal boom
  nodal_set.kind = "nodal";
  nodal_set.mode_set = "pinned-pinned";
  EXPECT_EQ(refusal(nodal_set, base).setting(), Setting::mode_set);
}

TEST(BoomChoice, TheStressRecoveryIsAModalBoomsChoiceNamedWhenNotTheDefault) {
  const scene::Scene scene = test::scene_file("pinned_luffing_crane.toml");
  const scene::BoomChoice base = default_boom_choice(scene);
  EXPECT_EQ(base.stress_recovery, multibody::StressRecovery::mode_acceleration);
  BoomRequest request;
  request.kind = "modal";
  request.stress_recovery = "displacement";
  const scene::BoomChoice displacement = boom_choice(request, base);
  EXPECT_EQ(displacement.stress_recovery, multibody::StressRecovery::mode_displacement);
  EXPECT_NE(displacement.label().find("(MD stress)"), std::string::npos) << displacement.label();
  request.stress_recovery = "acceleration";
  EXPECT_EQ(boom_choice(request, base).label().find("stress"), std::string::npos) << "the default is not named";

  BoomRequest unknown;
  unknown.kind = "modal";
  unknown.stress_recovery = "modal";
  const SettingError bad = refusal(unknown, base);
  EXPECT_EQ(bad.setting(), Setting::stress_recovery);
  EXPECT_EQ(bad.value(), "modal");
  EXPECT_NE(bad.problem().find("displacement|acceleration"), std::string::npos) << bad.what();
  BoomRequest nodal;  // a nodal boom's stresses are its own displacements'
  nodal.kind = "nodal";
  nodal.stress_recovery = "acceleration";
  EXPECT_EQ(refusal(nodal, base).setting(), Setting::stress_recovery);
}

TEST(BoomChoice, TheModeSetIsKeptAndNamedInTheLabel) {
  const scene::Scene scene = test::scene_file("pinned_luffing_crane.toml");
  BoomRequest request;
  request.kind = "modal";
  request.modes = 2;
  request.mode_set = "pinned-pinned";
  const scene::BoomChoice choice = boom_choice(request, default_boom_choice(scene));
  EXPECT_EQ(choice.mode_set, fem::Boundary::pinned_pinned);
  EXPECT_EQ(choice.label(), "modal k=2+static pinned-pinned (N=16)");
  request.mode_set = "free-free";  // the tangent frame's second set, for any heel
  const scene::BoomChoice free = boom_choice(request, default_boom_choice(test::scene_file("paper_floating_crane.toml")));
  EXPECT_EQ(free.mode_set, fem::Boundary::free_free);
  EXPECT_EQ(free.label(), "modal k=2+static free-free (N=16)");
}

}  // namespace boom_choice_test
}  // namespace ffrf::study
