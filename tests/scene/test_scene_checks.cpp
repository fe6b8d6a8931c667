// The cross-key physics checks (scene/scene_checks.hpp) against independent results: the resting
// hydrostatics against KINSOL's static equilibrium of the built crane (draft, trim, cargo height)
// and against coupling's box pitch stiffness; the breaking limit against the deep-water wavelength
// g T² / 2π; the surge and deck findings against a static equilibrium that indeed does not exist;
// the attachment points against the boxes' edges by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

#include "solve/failure.hpp"
#include "sea/hull_pressure.hpp"
#include "multibody/crane_statics.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf::scene {
namespace {

const std::string kCrane = FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml";

std::string crane_text() {
  std::ifstream in(kCrane);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

std::vector<SceneProblem> problems_of(const std::string& text) {
  try {
    (void)load_scene_text(text, "crane.toml");
  } catch (const SceneError& error) {
    return error.problems();
  }
  return {};
}

// The one problem of `text`, at `key`, whose message contains `words`.
void expect_problem(const std::string& text, const std::string& key, const std::string& words) {
  const auto problems = problems_of(text);
  ASSERT_EQ(problems.size(), 1u) << (problems.empty() ? "accepted" : SceneError(problems).what());
  EXPECT_EQ(problems[0].key, key) << problems[0].message;
  EXPECT_NE(problems[0].message.find(words), std::string::npos) << problems[0].message;
  EXPECT_GT(problems[0].line, 0) << format_problem(problems[0]);
}

TEST(SceneChecks, ShippedScenesHaveNoFindings) {
  for (const char* name : {"cantilever", "paper_floating_crane", "dropped_load", "spin_up_beam", "pinned_luffing_crane", "a_frame_crane"}) {
    const Scene scene = load_scene(std::string(FFRF_SOURCE_DIR "/cases/") + name + ".toml");
    EXPECT_TRUE(physics_findings(scene).empty()) << name;
    EXPECT_TRUE(scene.warnings.empty()) << name;
  }
}

TEST(SceneChecks, RestingHydrostaticsAgreeWithTheStaticEquilibrium) {
  const Scene scene = load_scene(kCrane);
  const RestingHydrostatics rest = resting_hydrostatics(scene);
  // The checks take the boom as built (rigid): compare with the rigid boom's equilibrium.
  auto crane = build_crane_equations(scene, BoomChoice{BoomKind::rigid, 1});
  const auto statics = multibody::solve_static_equilibrium(*crane, crane->initial_guess());
  const Hull& hull = *scene.hull;
  // The box's draft at mid-length is the mean draft for any small trim: exact.
  const double pitch = statics.outputs.hull.z();  // bow up > 0
  const double keel_mid_y = statics.outputs.hull.y() + std::sin(pitch) * hull.g1_aft_of_mid_length -
                            std::cos(pitch) * hull.g1_above_keel;
  EXPECT_NEAR(rest.draft, -keel_mid_y, 1e-3 * rest.draft);
  // The linear trim against the nonlinear pressure integral's equilibrium: within 2 %.
  EXPECT_NEAR(rest.trim, -pitch, 0.02 * std::abs(pitch)) << "trim " << -pitch * 180.0 / std::numbers::pi << " deg";
  // The cargo's lowest point: G2 at equilibrium minus half the box, to a centimetre of 84 m.
  const double bottom = statics.outputs.cargo.y() - 0.5 * scene.cargo->height;
  EXPECT_NEAR(rest.cargo_bottom, bottom, 0.01);
  EXPECT_GT(bottom, 80.0);
}

TEST(SceneChecks, MetacentricHeightIsTheBoxPitchStiffnessOverWeight) {
  const Scene scene = load_scene(kCrane);
  const RestingHydrostatics rest = resting_hydrostatics(scene);
  const Hull& hull = *scene.hull;
  const BoomMount& mount = *scene.boom.mount;
  // KG by hand, the cargo's weight at the boom tip.
  const double boom_mass = scene.boom.mesh.total_mass();
  const double tip = hull.g1_above_keel + mount.root_y + 120.0 * std::sin(mount.angle);
  const double kg = (hull.mass * hull.g1_above_keel + boom_mass * (tip - 60.0 * std::sin(mount.angle)) +
                     scene.cargo->mass * tip) / rest.displacement;
  const double rho = scene.environment.water_density, g = scene.environment.gravity;
  const sea::BoxHullSection box{hull.g1_aft_of_mid_length - 45.0, hull.g1_aft_of_mid_length + 45.0,
                                     -hull.g1_above_keel, hull.depth - hull.g1_above_keel, hull.width};
  const double volume = rest.displacement / rho;
  const double pitch_stiffness = sea::box_hydrostatic_stiffness(box, rho, g, volume, kg)(1);
  EXPECT_NEAR(rest.metacentric_height, pitch_stiffness / (rho * g * volume), 1e-9 * rest.metacentric_height);
}

TEST(SceneChecks, UnstablePitchIsAnErrorWithItsMetacentricHeight) {
  // A 12 m hull under the 120 m boom: BM_L = L²/(12 T) is far below the tip's height.
  std::string text = replaced(crane_text(), "length = 90.0 ", "length = 12.0 ");
  text = replaced(text, "g1_aft_of_mid_length = 13.0 ", "g1_aft_of_mid_length = 0.0 ");
  text = replaced(text, "root_x = 35.0 ", "root_x = 0.0 ");
  text = replaced(text, "pitch_radius_of_gyration = 22.5", "pitch_radius_of_gyration = 4.0");
  text = replaced(text, "width = 40.0 ", "width = 400.0 ");
  text = replaced(text, "root_y = 8.0 ", "root_y = 2.0 ");
  expect_problem(text, "hull.g1_above_keel", "unstable in pitch: GM_L");
}

TEST(SceneChecks, BreakingWaveAtOneSeventhOfTheDeepWaterWavelength) {
  const double wavelength = 9.81 * 10.0 * 10.0 / (2.0 * std::numbers::pi);  // T = 10 s, deep water: 156.1 m
  ASSERT_NEAR(wavelength / 7.0, 22.30, 0.01);
  EXPECT_TRUE(problems_of(replaced(crane_text(), "height = 1.0 ", "height = 22.2 ")).empty());
  expect_problem(replaced(crane_text(), "height = 1.0 ", "height = 22.4 "), "wave.height", "the wave breaks");
}

TEST(SceneChecks, DepthLimitedBreakingAndShallowWaterWarning) {
  std::string text = replaced(crane_text(), "water_depth = inf ", "water_depth = 10.0 ");
  expect_problem(replaced(text, "height = 1.0 ", "height = 7.9 "), "wave.height", "H/d");
  // 1 m in 10 m of water at T = 10 s: kd = 0.66 but the Ursell number H λ²/d³ ≈ 9: no warning; at
  // T = 20 s (λ ≈ 195 m) it is ≈ 38: linear theory is outside its range.
  EXPECT_TRUE(load_scene_text(text, "crane.toml").warnings.empty());
  const Scene shallow = load_scene_text(replaced(text, "period = 10.0 ", "period = 20.0 "), "crane.toml");
  ASSERT_EQ(shallow.warnings.size(), 1u);
  EXPECT_NE(shallow.warnings[0].find("Ursell"), std::string::npos) << shallow.warnings[0];
  EXPECT_NE(shallow.warnings[0].find("environment.water_depth = 10.0"), std::string::npos) << shallow.warnings[0];
}

TEST(SceneChecks, WaterShallowerThanTheDraftGrounds) {
  expect_problem(replaced(replaced(crane_text(), "water_depth = inf ", "water_depth = 4.0 "), "height = 1.0 ",
                          "height = 0.5 "),
                 "environment.water_depth", "ground");
}

TEST(SceneChecks, NoMooringMeansNoSurgeEquilibrium) {
  // The finding names the cause...
  std::string text = crane_text();
  text = text.substr(0, text.find("[mooring]")) + text.substr(text.find("[simulation]"));
  const auto problems = problems_of(text);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "mooring.surge_stiffness");
  EXPECT_NE(problems[0].message.find("surge has no restoring force"), std::string::npos);
  // ...and it is real: without the spring KINSOL finds no equilibrium (the surge row is singular).
  Scene scene = load_scene(kCrane);
  scene.mooring.surge_stiffness = 0.0;
  auto crane = build_crane_equations(scene, BoomChoice{BoomKind::nodal, 2});
  EXPECT_THROW((void)multibody::solve_static_equilibrium(*crane, crane->initial_guess()), solve::SolverFailure);
}

TEST(SceneChecks, DeckUnderWaterAtRestIsNamedBeforeKinsolFails) {
  // 14 000 t at the 95 m outreach: it floats, but no trim balances its moment.
  const std::string text = replaced(crane_text(), "mass = 1.3e6 ", "mass = 14.0e6 ");
  expect_problem(text, "cargo.mass", "the deck would be under water at rest");
  Scene scene = load_scene(kCrane);
  scene.cargo->mass = 14.0e6;
  auto crane = build_crane_equations(scene, BoomChoice{BoomKind::nodal, 2});
  EXPECT_THROW((void)multibody::solve_static_equilibrium(*crane, crane->initial_guess()), solve::SolverFailure);
}

TEST(SceneChecks, CargoHangingInTheWater) {
  expect_problem(replaced(crane_text(), "unstretched_length = 20.0 ", "unstretched_length = 200.0 "),
                 "wire.unstretched_length", "the cargo would hang in the water");
}

TEST(SceneChecks, AttachmentPointsOnTheirBodies) {
  // The hull spans [13 − 45, 13 + 45] = [−32, 58] m from G1; the keel is 6 m below G1, the deck 2 m
  // above, a pedestal up to 45 m above the deck; the cargo box is 20 m × 10 m about G2.
  EXPECT_TRUE(problems_of(replaced(crane_text(), "root_x = 35.0 ", "root_x = 58.0 ")).empty());
  expect_problem(replaced(crane_text(), "root_x = 35.0 ", "root_x = 58.5 "), "boom.root_x", "[-32, 58] m");
  expect_problem(replaced(crane_text(), "root_y = 8.0 ", "root_y = -6.5 "), "boom.root_y", "[-6, 47] m");
  expect_problem(replaced(crane_text(), "hook_x = 0.0 ", "hook_x = 10.5 "), "cargo.hook_x", "[-10, 10] m");
  expect_problem(replaced(crane_text(), "hook_y = 5.0 ", "hook_y = 25.0 "), "cargo.hook_y", "[-5, 5] m");
  expect_problem(replaced(crane_text(), "g1_above_keel = 6.0 ", "g1_above_keel = 8.0 "), "hull.g1_above_keel",
                 "below the deck");
  expect_problem(replaced(crane_text(), "g1_aft_of_mid_length = 13.0 ", "g1_aft_of_mid_length = 46.0 "),
                 "hull.g1_aft_of_mid_length", "[-45, 45] m");
  // A radius of gyration beyond the farthest corner (hypot(58, 6) = 58.3 m from G1).
  expect_problem(replaced(crane_text(), "pitch_radius_of_gyration = 22.5", "pitch_radius_of_gyration = 60"),
                 "hull.pitch_radius_of_gyration", "58.31");
}

TEST(SceneChecks, FloatingHullNeedsGravity) {
  expect_problem(replaced(crane_text(), "gravity = 9.81 ", "gravity = 0 "), "environment.gravity", "needs gravity");
}

TEST(SceneChecks, OutputSampleCountIsLimited) {
  std::string text = replaced(crane_text(), "duration = 120.0 ", "duration = 1e5 ");
  expect_problem(replaced(text, "output_interval = 0.05 ", "output_interval = 0.01 "), "simulation.output_interval",
                 "more than the limit of 1e+06");
}

TEST(SceneChecks, LightHullIsAWarningAboutUnits) {
  const Scene scene = load_scene_text(replaced(crane_text(), "mass = 12.6e6 ", "mass = 12600 "), "crane.toml");
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("hull.mass = 12600"), std::string::npos) << scene.warnings[0];
  EXPECT_NE(scene.warnings[0].find("in t written as kg"), std::string::npos) << scene.warnings[0];
}

TEST(SceneChecks, DirectoryOrHugeFileIsNotAScene) {
  try {
    (void)load_scene(FFRF_SOURCE_DIR "/cases");
    FAIL();
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("is a directory"), std::string::npos) << error.what();
  }
  try {
    (void)load_scene("/dev/zero");  // never ends: refused after max_scene_bytes
    FAIL();
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("larger than"), std::string::npos) << error.what();
  }
}


// The A-frame on its deck pin (scene/a_frame.cpp): what keeps it from standing is named by its keys.
std::string a_frame_text() {
  std::ifstream in(FFRF_SOURCE_DIR "/cases/a_frame_crane.toml");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SceneChecks, BackstaysOnTheBoomsSideCannotHoldTheAFrame) {
  // The deck point 35 m forward instead of aft: the backstays would have to push.
  expect_problem(replaced(a_frame_text(), "deck_x = -35.0", "deck_x = 35.0"), "backstay.deck_x", "cannot hold the A-frame");
}

TEST(SceneChecks, TheWiresMustFitTheSolversEventCount) {
  // 1 hoist + 4 luffing + 4 backstays = 9 wires, one event function each; the solvers track 8.
  const std::string text = replaced(replaced(a_frame_text(), "wires = 2                         # -\ndamping_ratio = 0.02              # - (2 % of critical for the boom",
                                             "wires = 4                         # -\ndamping_ratio = 0.02              # - (2 % of critical for the boom"),
                                    "wires = 2                         # -\ndamping_ratio = 0.02              # - (2 % of critical for the A-frame",
                                    "wires = 4                         # -\ndamping_ratio = 0.02              # - (2 % of critical for the A-frame");
  expect_problem(text, "backstay.wires", "at most 8 are tracked");
}

TEST(SceneChecks, AnAFrameNeedsItsBackstaysAndTheBackstaysAnAFrame) {
  const std::string text = a_frame_text();
  const auto backstay = text.find("[backstay]"), end = text.find("[cargo]");
  ASSERT_NE(backstay, std::string::npos);
  std::string without_backstay = text;
  without_backstay.erase(backstay, end - backstay);
  expect_problem(without_backstay, "a_frame", "needs the [backstay] wires");
  const auto a_frame = text.find("[a_frame]");
  std::string without_a_frame = text;
  without_a_frame.erase(a_frame, backstay - a_frame);
  expect_problem(without_a_frame, "backstay", "give [a_frame]");
}

TEST(SceneChecks, TheSinkingLoadCountsTheAFrame) {
  // 16 000 t of A-frame on top of hull, boom and cargo: more than the box's whole buoyancy.
  const auto problems = problems_of(replaced(a_frame_text(), "mass = 150.0e3 ", "mass = 16.0e6 "));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("+ A-frame 16000 t = 31100 t"), std::string::npos) << problems[0].message;
}

TEST(SceneChecks, BackstaysLongerThanTheirSpanAreAWarning) {
  const Scene scene =
      load_scene_text(replaced(a_frame_text(), "stiffness = 2.0e8                 # N/m (each backstay)",
                               "stiffness = 2.0e8\nunstretched_length = 60.0"),
                      "crane.toml");
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("backstay.unstretched_length = 60"), std::string::npos) << scene.warnings[0];
  EXPECT_NE(scene.warnings[0].find("slack at the A-frame's built pose"), std::string::npos) << scene.warnings[0];
}

}  // namespace
}  // namespace ffrf::scene
