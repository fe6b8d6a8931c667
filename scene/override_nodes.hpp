// The overrides of scene_overrides.hpp written into a scene file's TOML document before the loader
// reads it: each becomes its key's node in its section (the section added when the file has none),
// parsed as a TOML value when it is one ("16", "2.1e11", "[1, 2]", "\"pinned\"", "inf") and kept as
// a string otherwise ("55 deg", "pinned"), so that the loader checks it exactly as a value the file
// wrote. With the loader and key_values.cpp, the only files that know toml++.
#pragma once

#include <toml++/toml.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/scene_loader.hpp"
#include "scene/scene_overrides.hpp"

namespace ffrf::scene {

// The written overrides: each one's node in `root` with its value as given (for messages), and their keys.
struct OverrideValues {
  std::map<const toml::node*, std::string> shown;
  std::set<std::string, std::less<>> keys;
};

// Writes the overrides into `root`; returns the problems of those that name no scene key (with a
// "did you mean", or what a computed quantity follows from), each naming `file` and the origin.
// `written` receives every override's node (a later override of a key replaces the earlier).
std::vector<SceneProblem> write_overrides(toml::table& root, const SceneOverrides& overrides, const std::string& file,
                                          OverrideValues& written);

}  // namespace ffrf::scene
