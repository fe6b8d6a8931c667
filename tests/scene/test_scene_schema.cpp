// The scene schema table is consistent (sections, defaults inside ranges, choices match fem) and
// docs/scenes.md is exactly what the table generates.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "scene/scene_schema.hpp"
#include "fem/boundary.hpp"

namespace ffrf::scene {
namespace {

TEST(SceneSchema, EveryKeyIsDeclaredOnceInAKnownSection) {
  std::set<std::string_view> names;
  for (const KeySpec& key : scene_keys()) {
    EXPECT_TRUE(names.insert(key.name).second) << "declared twice: " << key.name;
    EXPECT_NE(find_section(key.section()), nullptr) << key.name;
    EXPECT_FALSE(key.help.empty()) << key.name;
  }
}

TEST(SceneSchema, DefaultsAreValid) {
  for (const KeySpec& key : scene_keys()) {
    if (key.presence != Presence::defaulted) continue;
    if (key.kind == ValueKind::number || key.kind == ValueKind::integer) {
      EXPECT_TRUE(accepts(key, key.default_value)) << key.name;
    } else if (key.kind == ValueKind::choice) {
      EXPECT_NE(key.choices.find(key.default_text), std::string_view::npos) << key.name;
    }
  }
}

TEST(SceneSchema, BoundaryChoicesMatchFem) {
  EXPECT_EQ(key_spec("boom.boundary").choices, fem::boundary_choices());
}

TEST(SceneSchema, FormatsRangesInDisplayUnits) {
  EXPECT_EQ(format_range(key_spec("boom.length")), "[0.1, 1000] m");
  EXPECT_EQ(format_range(key_spec("boom.angle")), "(0, 90) deg");
  EXPECT_EQ(format_range(key_spec("boom.youngs_modulus")), "[1, 1500] GPa");
  EXPECT_EQ(format_range(key_spec("boom.elements")), "[1, 10000]");
  EXPECT_EQ(format_range(key_spec("environment.water_depth")), "[0.5, 11000] m or inf");
  EXPECT_EQ(format_default(key_spec("boom.elements")), "16");
  EXPECT_THROW((void)key_spec("boom.lenght"), std::logic_error);
}

TEST(SceneSchema, SuggestsCloseKeys) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(suggest_key("boom.lenght"), "boom.length");
  EXPECT_EQ(suggest_key("boom.youngs_modulos"), "boom.youngs_modulus");
  EXPECT_EQ(suggest_key("hull.youngs_modulus"), "boom.youngs_modulus");
  EXPECT_FALSE(suggest_key("boom.colour").has_value());
  EXPECT_EQ(suggest_section("bom"), "boom");
}

TEST(SceneSchema, EveryNumberHasAFinitePhysicalRange) {
  // Plausibility, not only validity: no open-ended range lets 1e308 or 1e-300 through to a solver.
  for (const KeySpec& key : scene_keys()) {
    if (key.kind != ValueKind::number && key.kind != ValueKind::integer) continue;
    EXPECT_TRUE(std::isfinite(key.range.lower.value) && std::isfinite(key.range.upper.value)) << key.name;
    EXPECT_LT(key.range.lower.value, key.range.upper.value) << key.name;
    if (key.kind == ValueKind::integer) {
      EXPECT_LE(key.range.upper.value, 2147483647.0) << key.name << " fits an int";
    }
  }
}

TEST(SceneSchema, UnitSlipsSuggestTheUnitThatFits) {
  // 210 read as Pa is out of [1, 1500] GPa; 210 GPa is in it.
  EXPECT_EQ(unit_slips(key_spec("boom.youngs_modulus"), "210", ""), std::vector<std::string>{"\"210 GPa\""});
  // 12.6e6 t for a hull: 12.6e6 kg was meant.
  const auto hull = unit_slips(key_spec("hull.mass"), "12.6e6", "t");
  ASSERT_FALSE(hull.empty());
  EXPECT_EQ(hull.front(), "\"12.6e6 kg\"");
  // 120000 m for a boom: 120000 mm (or cm) was meant; the one nearer the middle of the range first.
  const auto boom = unit_slips(key_spec("boom.length"), "120000", "");
  ASSERT_FALSE(boom.empty());
  EXPECT_EQ(boom.front(), "\"120000 mm\"");
  // A bare angle: 60 can only be degrees inside (0, 90) deg; 1.0 could be either.
  EXPECT_EQ(unit_slips(key_spec("boom.angle"), "60", ""), std::vector<std::string>{"\"60 deg\""});
  EXPECT_EQ(unit_slips(key_spec("boom.angle"), "1.0", "").size(), 2u);
  // A damping ratio of 2 meant as 2 %.
  EXPECT_EQ(unit_slips(key_spec("boom.damping_ratio"), "2", ""), std::vector<std::string>{"\"2 %\""});
  // Nothing fits: no suggestion.
  EXPECT_TRUE(unit_slips(key_spec("boom.length"), "1e300", "").empty());
  EXPECT_EQ(did_you_mean({"\"a\"", "\"b\""}), "; did you mean \"a\" or \"b\"?");
}

TEST(SceneSchema, DocsAreGeneratedFromTheTable) {
  std::ifstream in(FFRF_SOURCE_DIR "/docs/scenes.md");
  ASSERT_TRUE(in) << "docs/scenes.md is missing: run `ffrf scene-reference > docs/scenes.md`";
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), scene_reference_markdown())
      << "docs/scenes.md is stale: run `ffrf scene-reference > docs/scenes.md`";
}

}  // namespace
}  // namespace ffrf::scene
