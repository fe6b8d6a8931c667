// Reads a scene file (TOML, toml++) against the scene schema and builds a Scene. Every problem is
// collected — malformed TOML (with line and column), unknown sections and keys (with a "did you
// mean"), missing keys and sections, wrong units, NaN, values out of range, conflicting keys —
// and thrown together as one SceneError, so that `ffrf check` can list them all at once. Values given
// beside the file (`--set KEY=VALUE`, Python's `with_values`, scene_overrides.hpp) are read as if the
// file wrote them, and their problems say where they came from.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_overrides.hpp"

namespace ffrf::scene {

struct SceneProblem {
  std::string file;
  int line = 0;         // 1-based; 0 when unknown
  int column = 0;       // 1-based; 0 when unknown
  std::string key;      // dotted key or section name; empty for a malformed file
  std::string value;    // the value as written (strings quoted); empty when absent
  std::string message;  // what is wrong, with the valid range or choices
  std::string origin = {};  // the value was given by this, not the file: "--set", "with_values"
};

// "FILE:LINE: key = value: message" (parts that are empty are left out); a value given beside the
// file: "FILE: key = value (--set): message".
std::string format_problem(const SceneProblem& problem);

class SceneError : public std::runtime_error {
 public:
  explicit SceneError(std::vector<SceneProblem> problems);
  const std::vector<SceneProblem>& problems() const { return problems_; }

 private:
  std::vector<SceneProblem> problems_;
};

// A scene file is a few kilobytes; anything beyond this is refused unread (a device, a wrong file).
inline constexpr std::size_t max_scene_bytes = 1 << 20;

// Throws SceneError listing every problem; a file that cannot be read (missing, a directory, larger
// than max_scene_bytes) is one problem.
Scene load_scene(const std::string& path);
// The same for TOML text; `file` names it in messages (and BEM files are found beside it).
Scene load_scene_text(std::string_view toml_text, const std::string& file);
// The text of a scene file, refused as load_scene() refuses it (throws SceneError): for a front end
// that keeps a scene's source to load it again with other values (Python's Scene.with_values).
std::string read_scene_file(const std::string& path);
// The same with values given beside the file, checked with the file's (Scene::overrides records them).
Scene load_scene(const std::string& path, const SceneOverrides& overrides);
Scene load_scene_text(std::string_view toml_text, const std::string& file, const SceneOverrides& overrides);

}  // namespace ffrf::scene
