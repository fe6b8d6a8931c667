// Scene overrides (scene_overrides.hpp) and their nodes in a scene file's TOML document
// (override_nodes.hpp).
#include "scene/scene_overrides.hpp"

#include <fmt/format.h>

#include "scene/computed_quantities.hpp"
#include "scene/override_nodes.hpp"
#include "scene/scene_schema.hpp"

namespace ffrf::scene {
namespace {

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// The value as a TOML value when it is exactly one ("16", "2.1e11", "[1, 2]", "\"x\"", "inf", "true"),
// else as a string ("55 deg", "pinned"): what a user means on a command line.
toml::table value_holder(const std::string& value) {
  if (value.find_first_of("\n\r") == std::string::npos && !value.empty()) {
    try {
      toml::table parsed = toml::parse("value = " + value);
      const toml::node* node = parsed.get("value");
      if (parsed.size() == 1 && node != nullptr && !node->is_table()) return parsed;
    } catch (const toml::parse_error&) {  // not a TOML value: the text itself
    }
  }
  toml::table holder;
  holder.insert("value", value);
  return holder;
}

}  // namespace

SceneOverride parse_override(std::string_view text, std::string_view origin) {
  const auto equals = text.find('=');
  const std::string_view key = trimmed(text.substr(0, equals));
  if (equals == std::string_view::npos || key.empty()) {
    throw SceneError({{"", 0, 0, "", std::string(text),
                       fmt::format("{} {}: not KEY=VALUE (e.g. boom.angle=\"55 deg\", cargo.mass=\"2400 t\")", origin, text),
                       std::string(origin)}});
  }
  return {std::string(key), std::string(trimmed(text.substr(equals + 1)))};
}

std::string to_string(const SceneOverride& override_value) { return override_value.key + "=" + override_value.value; }

std::vector<SceneProblem> write_overrides(toml::table& root, const SceneOverrides& overrides, const std::string& file,
                                          OverrideValues& written) {
  std::vector<SceneProblem> problems;
  std::map<std::string, std::string> given;  // key → value, the last of each key
  for (const SceneOverride& item : overrides.values) {
    if (find_key(item.key) == nullptr) {
      std::string message;
      if (const auto computed = computed_quantity_note(item.key)) {
        message = fmt::format("not a scene key: {}", *computed);
      } else if (const auto hint = suggest_key(item.key)) {
        message = fmt::format("unknown key; did you mean {}?", *hint);
      } else {
        message = "unknown key: a scene key is SECTION.KEY (docs/scenes.md lists them)";
      }
      problems.push_back({file, 0, 0, item.key, item.value, std::move(message), overrides.origin});
      continue;
    }
    given[item.key] = item.value;
  }
  for (const auto& [key, value] : given) {
    const KeySpec& spec = key_spec(key);
    const std::string section(spec.section());
    if (root.get(section) == nullptr) root.insert(section, toml::table{});
    toml::table* table = root.get(section)->as_table();
    if (table == nullptr) continue;  // the file writes [section] as a plain key: the loader names that
    const toml::table holder = value_holder(value);
    table->insert_or_assign(std::string(spec.leaf()), *holder.get("value"));  // a copy: no source line
    written.shown[table->get(spec.leaf())] = value;
    written.keys.insert(key);
  }
  return problems;
}

}  // namespace ffrf::scene
