// The scene schema table is consistent (sections, defaults inside ranges, choices match fem) and
// docs/scenes.md is exactly what the table generates.
#include <gtest/gtest.h>

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
      EXPECT_TRUE(key.range.contains(key.default_value)) << key.name;
    } else if (key.kind == ValueKind::choice) {
      EXPECT_NE(key.choices.find(key.default_text), std::string_view::npos) << key.name;
    }
  }
}

TEST(SceneSchema, BoundaryChoicesMatchFem) {
  EXPECT_EQ(key_spec("boom.boundary").choices, fem::boundary_choices());
}

TEST(SceneSchema, FormatsRangesInDisplayUnits) {
  EXPECT_EQ(format_range(key_spec("boom.length")), "(0, inf) m");
  EXPECT_EQ(format_range(key_spec("boom.angle")), "(0, 90) deg");
  EXPECT_EQ(format_range(key_spec("boom.elements")), "[1, inf)");
  EXPECT_EQ(format_range(key_spec("environment.water_depth")), "(0, inf] m");
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
