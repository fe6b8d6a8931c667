// Scene values given beside the file (`--set KEY=VALUE`, Python's with_values): an override gives
// the scene the file would give with that line written in it, and meets every check of the file's own
// values — unit, range, unknown keys, the keys across each other — with the key, the value as given,
// the valid range and the origin named.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "scene/scene_loader.hpp"
#include "scene/scene_overrides.hpp"
#include "../scene_text.hpp"

namespace ffrf::scene {
namespace scene_overrides_test {

const std::string kPaper = FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml";

SceneOverrides set(std::vector<SceneOverride> values, std::string origin = "--set") {
  return {std::move(values), std::move(origin)};
}

std::vector<SceneProblem> problems_of(const SceneOverrides& overrides, const std::string& path = kPaper) {
  try {
    (void)load_scene(path, overrides);
  } catch (const SceneError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "accepted";
  return {};
}

TEST(SceneOverrides, GiveTheSceneOfTheEditedFile) {
  // The second way to the same scene: the file's text with the two lines written in it.
  const std::string text = test_text::read_text(kPaper);
  const std::string edited = test_text::replaced(test_text::replaced(text, "angle = \"60 deg\"", "angle = \"55 deg\""),
                                                 "mass = 1.3e6 ", "mass = \"2400 t\" ");
  const Scene by_file = load_scene_text(edited, kPaper);
  const Scene by_set = load_scene(kPaper, set({{"boom.angle", "55 deg"}, {"cargo.mass", "2400 t"}}));
  ASSERT_TRUE(by_set.boom.mount && by_file.boom.mount);
  EXPECT_EQ(by_set.boom.mount->angle, by_file.boom.mount->angle);
  EXPECT_DOUBLE_EQ(by_set.boom.mount->angle, 55.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(by_set.cargo->mass, 2.4e6);
  EXPECT_EQ(by_set.cargo->mass, by_file.cargo->mass);
  // Everything else as the file says.
  EXPECT_EQ(by_set.hull->mass, 12.6e6);
  EXPECT_EQ(by_set.boom.mesh.element_count, 16);
  EXPECT_EQ(by_set.overrides, (std::vector<std::string>{"boom.angle=55 deg", "cargo.mass=2400 t"}));
  EXPECT_TRUE(load_scene(kPaper).overrides.empty());
}

TEST(SceneOverrides, TomlValuesAndPlainWords) {
  const Scene scene = load_scene(kPaper, set({{"boom.elements", "4"}, {"wave.direction", "head"},
                                              {"wave.height", "1.5"}, {"simulation.duration", "\"30 s\""}}));
  EXPECT_EQ(scene.boom.mesh.element_count, 4);
  ASSERT_TRUE(scene.wave);
  EXPECT_EQ(scene.wave->height, 1.5);
  EXPECT_EQ(scene.simulation.duration, 30.0);
  EXPECT_NE(scene.wave->direction, load_scene(kPaper).wave->direction);
}

TEST(SceneOverrides, LaterValueOfAKeyWins) {
  const Scene scene = load_scene(kPaper, set({{"boom.elements", "4"}, {"boom.elements", "8"}}));
  EXPECT_EQ(scene.boom.mesh.element_count, 8);
}

TEST(SceneOverrides, AddTheSectionTheFileLeavesOut) {
  const std::string cantilever = FFRF_SOURCE_DIR "/cases/cantilever.toml";
  const Scene scene = load_scene(cantilever, set({{"simulation.duration", "5 s"}}));
  EXPECT_EQ(scene.simulation.duration, 5.0);
}

TEST(SceneOverrides, OutOfRangeNamesKeyValueRangeAndOrigin) {
  const auto problems = problems_of(set({{"boom.angle", "155 deg"}}, "with_values"));
  ASSERT_EQ(problems.size(), 1u);
  const SceneProblem& problem = problems.front();
  EXPECT_EQ(problem.file, kPaper);
  EXPECT_EQ(problem.line, 0);
  EXPECT_EQ(problem.key, "boom.angle");
  EXPECT_EQ(problem.value, "155 deg");
  EXPECT_EQ(problem.origin, "with_values");
  EXPECT_NE(problem.message.find("(valid range (0, 90) deg)"), std::string::npos) << problem.message;
  EXPECT_EQ(format_problem(problem), kPaper + ": boom.angle = 155 deg (with_values): " + problem.message);
}

TEST(SceneOverrides, WrongUnitAndNotANumber) {
  auto problems = problems_of(set({{"cargo.mass", "2400 m"}}));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "cargo.mass");
  EXPECT_EQ(problems[0].origin, "--set");
  EXPECT_NE(problems[0].message.find("valid range [0.001, 100000] t"), std::string::npos) << problems[0].message;
  problems = problems_of(set({{"boom.length", "long"}}));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].value, "long");
  EXPECT_NE(problems[0].message.find("valid range [0.1, 1000] m"), std::string::npos) << problems[0].message;
  // An angle needs its unit, as in the file.
  problems = problems_of(set({{"boom.angle", "55"}}));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("did you mean \"55 deg\""), std::string::npos) << problems[0].message;
}

TEST(SceneOverrides, UnknownKeysAreNamedWithAHint) {
  const auto problems = problems_of(set({{"boom.angel", "55 deg"}, {"hull.draft", "5"}, {"nothing", "1"}}));
  ASSERT_EQ(problems.size(), 3u);
  for (const SceneProblem& problem : problems) EXPECT_EQ(problem.origin, "--set");
  EXPECT_EQ(problems[0].key, "boom.angel");
  EXPECT_NE(problems[0].message.find("did you mean boom.angle?"), std::string::npos) << problems[0].message;
  EXPECT_EQ(problems[1].key, "hull.draft");
  EXPECT_NE(problems[1].message.find("not a scene key"), std::string::npos) << problems[1].message;
  EXPECT_EQ(problems[2].key, "nothing");
}

TEST(SceneOverrides, KeysAcrossEachOtherAreChecked) {
  // A pinned heel needs the luffing wires the reference crane does not have.
  const auto problems = problems_of(set({{"boom.heel", "pinned"}}));
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "boom.heel");
  EXPECT_EQ(problems[0].value, "pinned");
  EXPECT_EQ(problems[0].origin, "--set");
  EXPECT_NE(problems[0].message.find("[luffing]"), std::string::npos) << problems[0].message;
}

TEST(SceneOverrides, ParseKeyEqualsValue) {
  const SceneOverride parsed = parse_override(" boom.angle = 55 deg ", "--set");
  EXPECT_EQ(parsed.key, "boom.angle");
  EXPECT_EQ(parsed.value, "55 deg");
  EXPECT_EQ(to_string(parse_override("wave.height=2=3", "--set")).substr(0, 12), "wave.height=");
  try {
    (void)parse_override("boom.angle", "--set");
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("--set boom.angle: not KEY=VALUE"), std::string::npos) << error.what();
  }
}

}  // namespace scene_overrides_test
}  // namespace ffrf::scene
