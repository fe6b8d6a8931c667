// The scene loader: the reference scenes load with the exact documented values (docs/architecture.md), and every kind
// of bad input is reported with file, key, value and valid range — all problems at once.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <regex>
#include <tuple>

#include "scene/scene_loader.hpp"
#include "scene/scene_schema.hpp"

namespace ffrf::scene {
namespace {

constexpr const char* kBoom = R"([boom]
length = 10.0
youngs_modulus = 2.1e11
area = 0.01
second_moment = 8.333e-6
density = 7850.0
)";

std::vector<SceneProblem> problems_of(const std::string& text) {
  try {
    (void)load_scene_text(text, "bad.toml");
  } catch (const SceneError& error) {
    return error.problems();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

// The only problem of `text`, checked to name file, key and (when given) the value.
SceneProblem single_problem(const std::string& text, const std::string& key, const std::string& value) {
  const auto problems = problems_of(text);
  EXPECT_EQ(problems.size(), 1u) << (problems.empty() ? std::string("none") : SceneError(problems).what());
  if (problems.empty()) return {};
  const SceneProblem& problem = problems.front();
  EXPECT_EQ(problem.file, "bad.toml");
  EXPECT_EQ(problem.key, key);
  EXPECT_EQ(problem.value, value);
  return problem;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(SceneLoader, CantileverSceneFile) {
  const Scene scene = load_scene(FFRF_SOURCE_DIR "/cases/cantilever.toml");
  EXPECT_FALSE(scene.is_crane());
  EXPECT_EQ(scene.boom.mesh.length, 10.0);
  EXPECT_EQ(scene.boom.mesh.section.youngs_modulus, 2.1e11);
  EXPECT_EQ(scene.boom.mesh.section.area, 0.01);
  EXPECT_EQ(scene.boom.mesh.section.second_moment, 8.333e-6);
  EXPECT_DOUBLE_EQ(scene.boom.mesh.section.mass_per_length, 78.5);
  EXPECT_EQ(scene.boom.density, 7850.0);
  EXPECT_EQ(scene.boom.mesh.element_count, 16);
  EXPECT_EQ(scene.boom.boundary, fem::Boundary::clamped_free);
  EXPECT_FALSE(scene.wave.has_value());
  EXPECT_TRUE(scene.environment.deep_water());  // default
}

TEST(SceneLoader, ReferenceSceneHasTheDesignValues) {
  const Scene s = load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  ASSERT_TRUE(s.is_crane());
  const Hull& hull = *s.hull;
  EXPECT_EQ(hull.mass, 12.6e6);
  EXPECT_EQ(hull.pitch_radius_of_gyration, 22.5);
  EXPECT_EQ(hull.length, 90.0);
  EXPECT_EQ(hull.width, 40.0);
  EXPECT_EQ(hull.depth, 8.0);
  EXPECT_EQ(hull.g1_above_keel, 6.0);
  EXPECT_EQ(hull.g1_aft_of_mid_length, 13.0);
  const Boom& boom = s.boom;
  EXPECT_EQ(boom.mesh.length, 120.0);
  EXPECT_EQ(boom.mesh.total_mass(), 1.2e6);
  EXPECT_DOUBLE_EQ(boom.mount->angle, std::numbers::pi / 3.0);
  EXPECT_EQ(boom.mount->root_x, 35.0);
  EXPECT_EQ(boom.mount->root_y, 8.0);
  EXPECT_EQ(boom.mesh.section.youngs_modulus, 2.1e11);
  EXPECT_EQ(boom.mesh.section.area, 1.27);
  EXPECT_EQ(boom.mesh.section.second_moment, 11.4);
  EXPECT_EQ(boom.mesh.section.mass_per_length, 1e4);
  EXPECT_EQ(boom.damping_ratio, 0.02);
  const Cargo& cargo = *s.cargo;
  EXPECT_EQ(cargo.mass, 1.3e6);
  EXPECT_EQ(cargo.length, 20.0);
  EXPECT_EQ(cargo.height, 10.0);
  EXPECT_EQ(cargo.hook_x, 0.0);
  EXPECT_EQ(cargo.hook_y, 5.0);
  EXPECT_TRUE(cargo.radius_of_gyration_derived);
  EXPECT_DOUBLE_EQ(cargo.pitch_radius_of_gyration, std::sqrt(500.0 / 12.0));
  EXPECT_EQ(s.wire->unstretched_length, 20.0);
  EXPECT_EQ(s.wire->stiffness, 2.0e8);
  EXPECT_EQ(s.wire->damping_ratio, 0.02);
  EXPECT_EQ(s.environment.water_density, 1025.0);
  EXPECT_EQ(s.environment.gravity, 9.81);
  EXPECT_TRUE(s.environment.deep_water());
  ASSERT_TRUE(s.wave.has_value());
  EXPECT_EQ(s.wave->height, 1.0);
  EXPECT_EQ(s.wave->period, 10.0);
  EXPECT_EQ(s.wave->direction, hydro::WaveHeading::following);
  EXPECT_EQ(s.wave->ramp_periods, 2.0);
  EXPECT_EQ(s.radiation.heave_added_mass, 1.5);
  EXPECT_EQ(s.radiation.surge_added_mass, 0.05);
  EXPECT_EQ(s.radiation.pitch_added_inertia, 1.0);
  EXPECT_EQ(s.radiation.heave_damping, 0.05);
  EXPECT_EQ(s.radiation.pitch_damping, 0.05);
  EXPECT_EQ(s.radiation.surge_damping, 0.02);
  EXPECT_EQ(s.mooring.surge_stiffness, 5.0e5);
  EXPECT_EQ(s.simulation.duration, 120.0);
  EXPECT_EQ(s.simulation.output_interval, 0.05);
  EXPECT_EQ(s.simulation.initial_state, InitialState::static_equilibrium);
}

TEST(SceneLoader, ConvertsUnitStrings) {
  const std::string text = replaced(replaced(kBoom, "length = 10.0", "length = \"10000 mm\""),
                                    "youngs_modulus = 2.1e11", "youngs_modulus = \"210 GPa\"");
  const Scene scene = load_scene_text(text, "units.toml");
  EXPECT_DOUBLE_EQ(scene.boom.mesh.length, 10.0);
  EXPECT_DOUBLE_EQ(scene.boom.mesh.section.youngs_modulus, 2.1e11);
}

TEST(SceneLoader, WrongDimensionNamesKeyValueAndUnits) {
  const auto p = single_problem(replaced(kBoom, "length = 10.0", "length = \"120 kg\""), "boom.length", "\"120 kg\"");
  EXPECT_NE(p.message.find("kg is a mass, expected a length (m, mm, cm, km)"), std::string::npos) << p.message;
  EXPECT_EQ(p.line, 2);
  EXPECT_EQ(format_problem(p).rfind("bad.toml:2: boom.length = \"120 kg\": kg is a mass", 0), 0u) << format_problem(p);
}

TEST(SceneLoader, RejectsNaN) {
  const auto p = single_problem(replaced(kBoom, "area = 0.01", "area = nan"), "boom.area", "nan");
  EXPECT_NE(p.message.find("NaN"), std::string::npos);
  EXPECT_NE(p.message.find("[1e-06, 100] m^2"), std::string::npos);
}

struct BadValue {
  std::string key;         // dotted
  std::string line;        // as in kBoom (or appended)
  std::string bad_value;   // as written
  std::string range;       // expected in the message
};

class NonPositive : public ::testing::TestWithParam<BadValue> {};

TEST_P(NonPositive, NamesFileKeyValueAndRange) {
  const BadValue& bad = GetParam();
  const std::string leaf = bad.key.substr(bad.key.find('.') + 1);
  const std::string text = bad.line.empty() ? std::string(kBoom) + leaf + " = " + bad.bad_value + "\n"
                                            : replaced(kBoom, bad.line, leaf + " = " + bad.bad_value);
  const auto p = single_problem(text, bad.key, bad.bad_value);
  EXPECT_NE(p.message.find("valid range " + bad.range), std::string::npos) << p.message;
  const std::string shown = format_problem(p);
  for (const std::string& part : {std::string("bad.toml"), bad.key, bad.bad_value, bad.range}) {
    EXPECT_NE(shown.find(part), std::string::npos) << shown << " lacks " << part;
  }
}

INSTANTIATE_TEST_SUITE_P(
    SceneLoader, NonPositive,
    ::testing::Values(BadValue{"boom.length", "length = 10.0", "0", "[0.1, 1000] m"},
                      BadValue{"boom.length", "length = 10.0", "-10.0", "[0.1, 1000] m"},
                      BadValue{"boom.youngs_modulus", "youngs_modulus = 2.1e11", "0", "[1, 1500] GPa"},
                      BadValue{"boom.youngs_modulus", "youngs_modulus = 2.1e11", "-2.1e+11", "[1, 1500] GPa"},
                      BadValue{"boom.area", "area = 0.01", "0.0", "[1e-06, 100] m^2"},
                      BadValue{"boom.area", "area = 0.01", "-0.01", "[1e-06, 100] m^2"},
                      BadValue{"boom.second_moment", "second_moment = 8.333e-6", "0", "[1e-14, 10000] m^4"},
                      BadValue{"boom.second_moment", "second_moment = 8.333e-6", "-1", "[1e-14, 10000] m^4"},
                      BadValue{"boom.density", "density = 7850.0", "0", "[100, 25000] kg/m^3"},
                      BadValue{"boom.density", "density = 7850.0", "-7850.0", "[100, 25000] kg/m^3"},
                      BadValue{"boom.elements", "", "0", "[1, 10000]"},
                      BadValue{"boom.elements", "", "-4", "[1, 10000]"},
                      BadValue{"boom.elements", "", "2.5", "[1, 10000]"},
                      BadValue{"boom.elements", "", "3000000000", "[1, 10000]"},
                      BadValue{"boom.length", "length = 10.0", "1e308", "[0.1, 1000] m"},
                      BadValue{"boom.youngs_modulus", "youngs_modulus = 2.1e11", "1e-300", "[1, 1500] GPa"}));

TEST(SceneLoader, UnitSlipGetsADidYouMean) {
  const auto p = single_problem(replaced(kBoom, "youngs_modulus = 2.1e11", "youngs_modulus = 210"), "boom.youngs_modulus",
                                "210");
  EXPECT_NE(p.message.find("valid range [1, 1500] GPa); did you mean \"210 GPa\"?"), std::string::npos) << p.message;
  const auto d = single_problem(replaced(kBoom, "density = 7850.0", "density = \"7.85 kg/m^3\""), "boom.density",
                                "\"7.85 kg/m^3\"");
  EXPECT_NE(d.message.find("did you mean \"7.85 t/m^3\""), std::string::npos) << d.message;
}

TEST(SceneLoader, AngleNeedsItsUnit) {
  const std::string crane = FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml";
  std::ifstream in(crane);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto sixty = single_problem(replaced(text, "angle = \"60 deg\"", "angle = 60"), "boom.angle", "60");
  EXPECT_NE(sixty.message.find("an angle needs its unit"), std::string::npos) << sixty.message;
  EXPECT_NE(sixty.message.find("did you mean \"60 deg\"?"), std::string::npos) << sixty.message;
  EXPECT_NE(sixty.message.find("(valid range (0, 90) deg)"), std::string::npos) << sixty.message;
  // 1.0 is inside the range either way: both readings are offered, nothing is assumed.
  const auto one = single_problem(replaced(text, "angle = \"60 deg\"", "angle = 1.0"), "boom.angle", "1.0");
  EXPECT_NE(one.message.find("did you mean \"1.0 rad\" or \"1.0 deg\"?"), std::string::npos) << one.message;
  // A string without a unit is the same bare number; 0 needs no unit.
  (void)single_problem(replaced(text, "angle = \"60 deg\"", "angle = \"60\""), "boom.angle", "\"60\"");
  EXPECT_NO_THROW((void)load_scene_text(std::string(kBoom) + "[hub]\nangle = 0\n", "hub.toml"));
}

TEST(SceneLoader, HullDampingTakesItsUnitsAndBelongsToAHull) {
  // The keys with units (kN s/m = 1e3 N s/m); a hub has no hull to damp: a named error at the section.
  const Scene reference = load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  EXPECT_EQ(reference.hull_damping.linear, Eigen::Vector3d::Zero());
  std::ifstream in(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  const std::string crane((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Scene damped = load_scene_text(crane + "\n[hull_damping]\nsurge_linear = \"200 kN s/m\"\n"
                                               "pitch_quadratic = \"3 MN m s^2/rad^2\"\n",
                                       "damped.toml");
  EXPECT_DOUBLE_EQ(damped.hull_damping.linear.x(), 2.0e5);
  EXPECT_DOUBLE_EQ(damped.hull_damping.quadratic.z(), 3.0e6);
  const auto wrong_unit = single_problem(std::string(kBoom) + "[hub]\nangle = 0\n[hull_damping]\nheave_linear = \"5 N/m\"\n",
                                         "hull_damping.heave_linear", "\"5 N/m\"");
  EXPECT_NE(wrong_unit.message.find("N s/m"), std::string::npos) << wrong_unit.message;
  const auto hub = single_problem(std::string(kBoom) + "[hub]\nangle = 0\n[hull_damping]\nheave_linear = 1e5\n", "hull_damping", "");
  EXPECT_NE(hub.message.find("belongs to a floating hull"), std::string::npos) << hub.message;
}

TEST(SceneLoader, OverflowingIntegerNamesKeyAndRange) {
  // Beyond int64: toml++ refuses the line; the problem still names the key, its value and range.
  const auto problems = problems_of(std::string(kBoom) + "elements = 99999999999999999999\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "boom.elements");
  EXPECT_EQ(problems[0].value, "99999999999999999999");
  EXPECT_NE(problems[0].message.find("valid range [1, 10000]"), std::string::npos) << problems[0].message;
}

TEST(SceneLoader, UnknownKeySuggestsTheClosest) {
  const auto p = single_problem(std::string(kBoom) + "elemnts = 8\n", "boom.elemnts", "8");
  EXPECT_NE(p.message.find("unknown key; did you mean boom.elements?"), std::string::npos) << p.message;
}

// Keys a user may expect to set but ffrf computes (the draft, the static tension): the message says
// so and names the keys that change the quantity, and every key it names is one the schema has.
TEST(SceneLoader, ComputedQuantityIsNamedAsComputedWithTheKeysThatChangeIt) {
  const std::string crane = FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml";
  std::ifstream in(crane);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [section, leaf, value, key] : {std::tuple{"[hull]\n", "draft", "4.2", "hull.draft"},
                                                  std::tuple{"[hull]\n", "displacement", "12600", "hull.displacement"},
                                                  std::tuple{"[wire]\n", "tension", "1.2e7", "wire.tension"}}) {
    const std::string line = std::string(leaf) + " = " + value + "\n";
    const auto p = single_problem(replaced(text, section, section + line), key, value);
    EXPECT_NE(p.message.find("not a scene key: computed, not set"), std::string::npos) << p.message;
    EXPECT_EQ(p.message.find("unknown key"), std::string::npos) << p.message;
    EXPECT_NE(p.message.find("cargo.mass"), std::string::npos) << "the cargo's mass changes it: " << p.message;
    const std::regex dotted(R"(\b([a-z]+\.[a-z0-9_]*[a-z])\b)");
    for (std::sregex_iterator it(p.message.begin(), p.message.end(), dotted), end; it != end; ++it) {
      EXPECT_NE(find_key((*it)[1].str()), nullptr) << (*it)[1].str() << " named in: " << p.message;
    }
  }
}

TEST(SceneLoader, ReportsEveryProblemAtOnce) {
  // A misspelt key also leaves its key missing: both are reported, with the other unknown key.
  const auto all = problems_of(replaced(kBoom, "length = 10.0", "lenght = 10.0\nwidht = 3"));
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].key, "boom.length");  // missing, reported at the [boom] header (line 1)
  EXPECT_EQ(all[1].key, "boom.lenght");
  EXPECT_NE(all[1].message.find("did you mean boom.length?"), std::string::npos);
  EXPECT_EQ(all[2].key, "boom.widht");
}

TEST(SceneLoader, UnknownSectionSuggestsTheClosest) {
  const auto problems = problems_of(std::string(kBoom) + "[wvae]\nheight = 1.0\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].key, "wvae");
  EXPECT_NE(problems[0].message.find("did you mean [wave]?"), std::string::npos) << problems[0].message;
}

TEST(SceneLoader, MissingRequiredKeyShowsItsRange) {
  const auto p = single_problem(replaced(kBoom, "second_moment = 8.333e-6\n", ""), "boom.second_moment", "");
  EXPECT_NE(p.message.find("missing key"), std::string::npos);
  EXPECT_NE(p.message.find("[1e-14, 10000] m^4"), std::string::npos);
}

TEST(SceneLoader, MassPerLengthAndDensityAreExclusive) {
  const auto p = single_problem(std::string(kBoom) + "mass_per_length = 78.5\n", "boom.mass_per_length", "78.5");
  EXPECT_NE(p.message.find("give exactly one of boom.mass_per_length, boom.density"), std::string::npos) << p.message;
  const auto none = problems_of(replaced(kBoom, "density = 7850.0\n", ""));
  ASSERT_EQ(none.size(), 1u);
  EXPECT_NE(none[0].message.find("give exactly one of"), std::string::npos);
}

TEST(SceneLoader, UnknownBoundaryListsTheChoices) {
  const auto p = single_problem(std::string(kBoom) + "boundary = \"clamped\"\n", "boom.boundary", "\"clamped\"");
  EXPECT_NE(p.message.find("clamped-free, free-free, pinned-pinned"), std::string::npos) << p.message;
}

TEST(SceneLoader, MalformedTomlGivesLineAndColumn) {
  const auto problems = problems_of(std::string(kBoom) + "area = = 3\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].line, 7);
  EXPECT_GT(problems[0].column, 0);
  EXPECT_NE(problems[0].message.find("malformed TOML"), std::string::npos);
  EXPECT_EQ(format_problem(problems[0]).rfind("bad.toml:7:", 0), 0u) << format_problem(problems[0]);
}

TEST(SceneLoader, CraneSceneNeedsAllCraneSections) {
  const std::string text = std::string(kBoom) + "angle = \"60 deg\"\nroot_x = 35\nroot_y = 8\n[wire]\n"
                           "unstretched_length = 20\nstiffness = 2e8\n";
  const auto problems = problems_of(text);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].key, "hull");
  EXPECT_EQ(problems[1].key, "cargo");
}

TEST(SceneLoader, BoomAngleOutsideTheOpenQuarterIsRejected) {
  const std::string crane = FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml";
  std::ifstream in(crane);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto p = single_problem(replaced(text, "angle = \"60 deg\"", "angle = \"90 deg\""), "boom.angle", "\"90 deg\"");
  EXPECT_NE(p.message.find("(0, 90) deg"), std::string::npos) << p.message;
}

TEST(SceneLoader, SinkingHullIsRejected) {
  std::ifstream in(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto p = single_problem(replaced(text, "mass = 12.6e6", "mass = \"40000 t\""), "hull.mass", "\"40000 t\"");
  EXPECT_NE(p.message.find("would sink"), std::string::npos) << p.message;
}

TEST(SceneLoader, MissingFileIsOneProblem) {
  try {
    (void)load_scene("/nonexistent/scene.toml");
    FAIL();
  } catch (const SceneError& error) {
    ASSERT_EQ(error.problems().size(), 1u);
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace ffrf::scene
