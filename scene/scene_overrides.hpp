// Scene values given beside a scene file: `--set KEY=VALUE` on the command line and
// `Scene.with_values({...})` in Python. An override replaces (or adds) one key of the file's TOML
// before the loader reads it, so it meets every check the file's own value meets — its unit, its
// range, the keys across each other, the physics — and a problem names the key, the value as given,
// the valid range and where it came from (SceneProblem::origin). The value is written as on the
// command line: a number (SI), a quantity with its unit ("55 deg", "2400 t"), a choice ("pinned"),
// or any TOML value ("[1, 2]", "\"text\"").
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ffrf::scene {

struct SceneOverride {
  std::string key;    // dotted: "boom.angle"
  std::string value;  // as given: "55 deg"
};

struct SceneOverrides {
  std::vector<SceneOverride> values;  // applied in order: a later one of the same key wins
  std::string origin = "--set";       // named in problems: "--set", "with_values"
  bool empty() const { return values.empty(); }
};

// "KEY=VALUE" (spaces around KEY trimmed, VALUE as given after the first '=', its ends trimmed).
// Throws SceneError (scene_loader.hpp) naming `origin` when the text has no '=' or no key.
SceneOverride parse_override(std::string_view text, std::string_view origin);
// "boom.angle=55 deg".
std::string to_string(const SceneOverride& override_value);

}  // namespace ffrf::scene
