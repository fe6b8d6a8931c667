// Scene loader: walks the TOML document against the schema table, collects every problem, and
// builds the Scene value (scene_build.hpp). Only this file, key_values.cpp (one key's value
// against its schema entry) and scene_overrides.cpp (values given beside the file, written into the
// document first) know toml++.
#include "scene/scene_loader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <map>

#include "scene/bem_files.hpp"
#include "scene/computed_quantities.hpp"
#include "scene/bem_keys.hpp"
#include "scene/key_values.hpp"
#include "scene/override_nodes.hpp"
#include "scene/scene_build.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_key.hpp"
#include "scene/scene_schema.hpp"
#include "scene/wave_keys.hpp"

namespace ffrf::scene {
namespace {

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

// Byte offset of the 1-based code-point column `column` in a UTF-8 line.
std::size_t byte_offset(std::string_view line, std::size_t column) {
  std::size_t offset = 0;
  for (std::size_t seen = 1; offset < line.size() && seen < column; ++seen) {
    do {
      ++offset;
    } while (offset < line.size() && (static_cast<unsigned char>(line[offset]) & 0xC0) == 0x80);
  }
  return offset;
}

class SceneReader final : public WrittenKeys {
 public:
  // `overridden`: the nodes of values given beside the file (override_nodes.hpp) and their text;
  // `problems`: those found before (overrides that name no key).
  SceneReader(std::string file, std::string_view text, OverrideValues overridden, std::string origin,
              std::vector<SceneProblem> problems)
      : file_(std::move(file)), problems_(std::move(problems)), overridden_(std::move(overridden)), origin_(std::move(origin)) {
    for (std::size_t start = 0; start <= text.size();) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      lines_.push_back(text.substr(start, end - start));
      start = end + 1;
    }
  }

  Scene read(const toml::table& root) {
    collect_present(root);
    resolve_keys();
    check_one_of_groups();
    if (problems_.empty()) check_scene();
    if (!problems_.empty()) throw SceneError(sorted(std::move(problems_)));
    Scene scene = build_scene(*this, file_, {crane_, hub_, cargo_, sections_.contains("wave"), sections_.contains("bem")});
    check_physics(scene);
    if (problems_.empty()) read_bem_files(scene);
    if (!problems_.empty()) throw SceneError(sorted(std::move(problems_)));
    return scene;
  }

 private:
  void report(int line, std::string key, std::string value, std::string message) override {
    std::string origin = overridden_.keys.contains(key) ? origin_ : std::string();
    problems_.push_back({file_, line, 0, std::move(key), std::move(value), std::move(message), std::move(origin)});
  }

  // Pass 1: unknown sections and keys; remember where each known key and section is.
  void collect_present(const toml::table& root) {
    for (auto&& [name, node] : root) {
      const std::string section(name.str());
      const auto* table = node.as_table();
      if (table == nullptr) {
        const auto hint = suggest_key(section);
        report(line_of(node), section, show_value(node),
               fmt::format("unknown top-level key: scene values belong in a section ([boom], [hull], ...){}",
                           hint ? fmt::format("; did you mean {}?", *hint) : ""));
        continue;
      }
      if (find_section(section) == nullptr) {
        const auto hint = suggest_section(section);
        report(line_of(node), section, "", fmt::format("unknown section [{}]{}", section,
                                                       hint ? fmt::format("; did you mean [{}]?", *hint) : ""));
        continue;
      }
      sections_[section] = table;
      for (auto&& [leaf, value] : *table) {
        const std::string dotted = section + "." + std::string(leaf.str());
        if (find_key(dotted) == nullptr) {
          const auto computed = computed_quantity_note(dotted);
          const auto hint = suggest_key(dotted);
          report(line_of(value), dotted, show_value(value),
                 computed ? fmt::format("not a scene key: {}", *computed)
                          : fmt::format("unknown key{}", hint ? fmt::format("; did you mean {}?", *hint) : ""));
          continue;
        }
        present_[dotted] = &value;
      }
    }
    hub_ = sections_.contains("hub");
    // A hull crane needs all of [hull], [cargo], [wire]; with a hub, [cargo] and [wire] are optional.
    for (const SectionSpec& section : scene_sections()) {
      if (section.role == SectionRole::crane && sections_.contains(std::string(section.name))) crane_ = true;
    }
    if (hub_) {
      crane_ = sections_.contains("hull");
      if (crane_) {
        report(line_of(*sections_.at("hub")), "hub", "",
               "[hub] and [hull] exclude each other: a scene's boom is clamped either to a floating hull or to a hub");
      }
      cargo_ = sections_.contains("cargo") || sections_.contains("wire");
      if (!crane_ && sections_.contains("cargo") != sections_.contains("wire")) {
        report(0, sections_.contains("cargo") ? "wire" : "cargo", "",
               "a hub scene with a cargo needs both [cargo] and [wire] (or neither)");
      }
    } else {
      cargo_ = crane_;
    }
    for (const SectionSpec& section : scene_sections()) {
      if (sections_.contains(std::string(section.name))) continue;
      if (section.role == SectionRole::required) {
        report(0, std::string(section.name), "", fmt::format("missing section [{}] (required)", section.name));
      } else if (section.role == SectionRole::crane && crane_ && !hub_) {
        report(0, std::string(section.name), "",
               fmt::format("missing section [{}]: a crane scene (one with [hull], [cargo] or [wire]) needs all of "
                           "[hull], [cargo] and [wire]",
                           section.name));
      }
    }
  }

  // Pass 2: each key of each present section: value, unit, range; defaults for absent keys.
  void resolve_keys() {
    for (const KeySpec& key : scene_keys()) {
      const auto section = sections_.find(std::string(key.section()));
      if (section == sections_.end()) {
        if (key.presence == Presence::defaulted) resolved_[std::string(key.name)] = default_of(key);
        continue;
      }
      const auto found = present_.find(std::string(key.name));
      if (found == present_.end()) {
        resolve_absent(key, line_of(*section->second));
        continue;
      }
      const toml::node& node = *found->second;
      const std::string shown = show_value(node);
      KeyValue value = resolve_value(key, node, shown);
      if (value.value) {
        resolved_[std::string(key.name)] = std::move(*value.value);
      } else {
        report(line_of(node), std::string(key.name), shown, std::move(value.problem));
      }
    }
  }

  static Resolved default_of(const KeySpec& key) {
    return {key.default_value, std::string(key.default_text), {}};
  }

  void resolve_absent(const KeySpec& key, int section_line) {
    const bool needed = key.presence == Presence::required || (key.presence == Presence::crane_required && crane_);
    if (key.presence == Presence::defaulted) {
      resolved_[std::string(key.name)] = default_of(key);
    } else if (needed) {
      report(section_line, std::string(key.name), "",
             fmt::format("missing {}key: {} (valid range {})", key.presence == Presence::crane_required ? "crane " : "",
                         key.help, format_range(key)));
    }
  }

  void check_one_of_groups() {
    for (const KeySpec& key : scene_keys()) {
      if (key.presence != Presence::one_of || !sections_.contains(std::string(key.section()))) continue;
      std::vector<std::string_view> members;
      std::vector<std::string_view> given;
      for (const KeySpec& other : scene_keys()) {
        if (other.one_of != key.one_of) continue;
        members.push_back(other.name);
        if (present_.contains(std::string(other.name))) given.push_back(other.name);
      }
      if (members.front() != key.name) continue;  // report each group once
      if (given.empty()) {
        report(line_of(*sections_.at(std::string(key.section()))), fmt::format("{}", fmt::join(members, " | ")), "",
               fmt::format("missing: give exactly one of {}", fmt::join(members, ", ")));
      } else if (given.size() > 1) {
        std::sort(given.begin(), given.end(), [&](std::string_view a, std::string_view b) {
          return line_of(*present_.at(std::string(a))) < line_of(*present_.at(std::string(b)));
        });
        const toml::node& later = *present_.at(std::string(given[1]));
        report(line_of(later), std::string(given[1]), show_value(later),
               fmt::format("conflicts with {}: give exactly one of {}", given[0], fmt::join(members, ", ")));
      }
    }
  }

  double number(std::string_view name) const override { return resolved_.at(std::string(key_spec(name).name)).number; }
  const std::string& text(std::string_view name) const override { return resolved_.at(std::string(key_spec(name).name)).text; }
  bool has(std::string_view name) const override { return resolved_.contains(std::string(key_spec(name).name)); }
  const std::vector<double>& list(std::string_view name) const override { return resolved_.at(std::string(key_spec(name).name)).list; }
  bool written(std::string_view name) const override { return present_.contains(name); }
  int line(std::string_view name) const override { return line_of(*present_.find(name)->second); }
  std::string shown(std::string_view name) const override { return show_value(*present_.find(name)->second); }

  // Checks that involve several keys (only run when every key is valid on its own).
  void check_scene() {
    if (sections_.contains("wave")) check_wave_keys(*this, line_of(*sections_.at("wave")));
    if (hub_ && sections_.contains("hull_damping")) {
      report(line_of(*sections_.at("hull_damping")), "hull_damping", "",
             "belongs to a floating hull: a hub scene has no hull degrees of freedom to damp");
    }
    if (sections_.contains("bem")) check_bem_keys(*this, line_of(*sections_.at("bem")));
    // A pinned heel and the luffing wires come together, on a floating hull.
    const bool pinned = resolved_.contains(scene_key("boom.heel")) && resolved_.at(scene_key("boom.heel")).text == "pinned";
    if (pinned && (hub_ || !crane_)) {
      report(line_of(*present_.at(scene_key("boom.heel"))), scene_key("boom.heel"), shown(scene_key("boom.heel")),
             "a pinned heel belongs to a crane on a floating hull ([hull] with [luffing]); a hub scene clamps its boom");
    } else if (pinned && !sections_.contains("luffing")) {
      report(line_of(*present_.at(scene_key("boom.heel"))), scene_key("boom.heel"), shown(scene_key("boom.heel")),
             "a pinned boom needs the [luffing] wires that hold it (luffing.a_frame_x, luffing.a_frame_y, luffing.stiffness)");
    } else if (!pinned && sections_.contains("luffing")) {
      report(line_of(*sections_.at("luffing")), "luffing", "",
             "luffing wires hold a pinned boom: set boom.heel = \"pinned\" (a clamped boom needs none)");
    }
    // An A-frame on its deck pin holds the luffing wires' end, and the backstays hold it.
    if (sections_.contains("a_frame") && !sections_.contains("luffing")) {
      report(line_of(*sections_.at("a_frame")), "a_frame", "",
             "an A-frame on its deck pin holds the luffing wires of a pinned boom: give [luffing] (and boom.heel = \"pinned\"), "
             "or leave [a_frame] out");
    } else if (sections_.contains("a_frame") && !sections_.contains("backstay")) {
      report(line_of(*sections_.at("a_frame")), "a_frame", "",
             "an A-frame pinned to the deck needs the [backstay] wires that hold it (backstay.deck_x, backstay.deck_y, "
             "backstay.stiffness); without [a_frame] the A-frame is rigid with the hull");
    } else if (!sections_.contains("a_frame") && sections_.contains("backstay")) {
      report(line_of(*sections_.at("backstay")), "backstay", "",
             "backstays hold an A-frame pinned to the deck: give [a_frame] (pin_x, pin_y, mass), or leave [backstay] out");
    }
    if (hub_) {
      for (const char* key : {scene_key("boom.angle"), scene_key("boom.root_x"), scene_key("boom.root_y")}) {
        if (present_.contains(key)) {
          report(line_of(*present_.at(key)), key, show_value(*present_.at(key)),
                 "belongs to a hull crane; a hub scene clamps the boom at hub.radius along hub.angle");
        }
      }
    }
  }

  // The cross-key physics of the built scene (scene_checks.hpp): errors are problems, warnings go
  // with the scene. Each finding is reported at its first key, shown with the value as written.
  void check_physics(Scene& scene) {
    for (SceneFinding& finding : physics_findings(scene)) {
      const std::string& key = finding.keys.front();
      int line = 0;
      std::string value;
      if (const auto found = present_.find(key); found != present_.end()) {
        line = line_of(*found->second);
        value = show_value(*found->second);
      } else {
        // An absent key: its section's line, else the first other key of the finding that is written.
        const KeySpec& spec = key_spec(key);
        if (const auto section = sections_.find(std::string(spec.section())); section != sections_.end()) {
          line = line_of(*section->second);
        }
        for (std::size_t k = 1; line == 0 && k < finding.keys.size(); ++k) {
          if (const auto other = present_.find(finding.keys[k]); other != present_.end()) line = line_of(*other->second);
        }
        value = spec.presence == Presence::defaulted ? format_default(spec) + " (default)" : std::string();
      }
      if (finding.error) {
        report(line, key, value, std::move(finding.message));
      } else {
        scene.warnings.push_back(format_problem({file_, line, 0, key, value, std::move(finding.message)}));
      }
    }
  }

  // Reads the WAMIT files of [bem] (scene/bem_files.hpp); a problem is reported at the key that
  // names the file (or the key the inconsistency concerns), the file's own line in the message.
  void read_bem_files(Scene& scene) {
    if (!scene.bem) return;
    const auto line_of_key = [&](const std::string& key) {
      if (const auto found = present_.find(key); found != present_.end()) return line_of(*found->second);
      return line_of(*sections_.at("bem"));
    };
    const auto value_of_key = [&](const std::string& key) {
      const auto found = present_.find(key);
      return found != present_.end() ? show_value(*found->second) : std::string();
    };
    if (sections_.contains("radiation")) {
      report(line_of(*sections_.at("radiation")), "radiation", "",
             "conflicts with [bem]: the BEM files give the radiation coefficients; remove one of the two sections");
      return;
    }
    bool bem_files_failed = false;
    for (const BemProblem& problem : load_bem_files(scene)) {
      bem_files_failed = bem_files_failed || !problem.warning;
      if (problem.warning) {
        scene.warnings.push_back(format_problem({file_, line_of_key(problem.key), 0, problem.key, value_of_key(problem.key), problem.message}));
      } else {
        report(line_of_key(problem.key), problem.key, value_of_key(problem.key), problem.message);
      }
    }
    if (bem_files_failed) return;
    // One added-mass matrix for every path of the model, whatever the file format: its symmetric part.
    BemHull& bem = *scene.bem;
    bem.added_mass_asymmetry = hydro::symmetrise_added_mass(bem.radiation);
    if (bem.added_mass_asymmetry.relative > hydro::asymmetry_warning) {
      const std::string key = scene.bem->format == BemFormat::capytaine ? scene_key("bem.capytaine_file") : scene_key("bem.radiation_file");
      scene.warnings.push_back(format_problem(
          {file_, line_of_key(key), 0, key, value_of_key(key),
           fmt::format("the added-mass matrix of {} is not symmetric: its largest relative asymmetry is {}; the model uses "
                       "the symmetric part (A + Aᵀ)/2 at every frequency (a zero-speed radiation added mass is symmetric, "
                       "so the difference is the BEM code's numerical error; docs/hydrodynamics.md §6)",
                       bem.radiation_file, bem.added_mass_asymmetry.describe())}));
    }
  }

  static std::vector<SceneProblem> sorted(std::vector<SceneProblem> problems) {
    std::stable_sort(problems.begin(), problems.end(), [](const SceneProblem& a, const SceneProblem& b) {
      return std::pair(a.line == 0, a.line) < std::pair(b.line == 0, b.line);
    });
    return problems;
  }

  // The value as written in the scene file (one-line values) or as given beside it, else as parsed.
  std::string show_value(const toml::node& node) const {
    if (const auto given = overridden_.shown.find(&node); given != overridden_.shown.end()) return given->second;
    const auto& region = node.source();
    if (region.begin.line == region.end.line && region.begin.line >= 1 && region.begin.line <= lines_.size() &&
        region.end.column > region.begin.column) {
      const std::string_view line = lines_[region.begin.line - 1];
      const std::size_t first = byte_offset(line, region.begin.column);
      const std::size_t last = byte_offset(line, region.end.column);
      if (last > first) return std::string(line.substr(first, last - first));
    }
    return show_parsed_value(node);
  }

  std::string file_;
  std::vector<std::string_view> lines_;
  std::vector<SceneProblem> problems_;
  OverrideValues overridden_;
  std::string origin_;
  bool crane_ = false;  // a hull crane
  bool hub_ = false;    // a hub scene
  bool cargo_ = false;  // cargo and wire present
  std::map<std::string, const toml::table*, std::less<>> sections_;
  std::map<std::string, const toml::node*, std::less<>> present_;
  std::map<std::string, Resolved, std::less<>> resolved_;
};

std::string join_messages(const std::vector<SceneProblem>& problems) {
  std::string text;
  for (const SceneProblem& problem : problems) {
    if (!text.empty()) text += '\n';
    text += format_problem(problem);
  }
  return text;
}

}  // namespace

std::string format_problem(const SceneProblem& problem) {
  std::string text = problem.file;
  if (problem.line > 0) text += fmt::format(":{}", problem.line);
  if (problem.column > 0) text += fmt::format(":{}", problem.column);
  if (!text.empty()) text += ": ";
  if (!problem.key.empty()) {
    text += problem.key;
    if (!problem.value.empty()) text += " = " + problem.value;
    if (!problem.origin.empty()) text += " (" + problem.origin + ")";
    text += ": ";
  }
  return text + problem.message;
}

SceneError::SceneError(std::vector<SceneProblem> problems)
    : std::runtime_error(join_messages(problems)), problems_(std::move(problems)) {}

Scene load_scene_text(std::string_view toml_text, const std::string& file) {
  return load_scene_text(toml_text, file, SceneOverrides{});
}

Scene load_scene_text(std::string_view toml_text, const std::string& file, const SceneOverrides& overrides) {
  toml::table root;
  try {
    root = toml::parse(toml_text, file);
  } catch (const toml::parse_error& error) {
    const auto& begin = error.source().begin;
    SceneProblem problem{file, static_cast<int>(begin.line), static_cast<int>(begin.column), "", "",
                         fmt::format("malformed TOML: {}", error.description())};
    // Name the key and value of the line when it is a known scene key ("elements = 99999999999999999999").
    if (const auto written = key_on_line(toml_text, problem.line)) {
      problem.key = written->key;
      problem.value = written->value;
      if (const KeySpec* key = find_key(written->key)) problem.message += fmt::format(" (valid range {})", format_range(*key));
    }
    throw SceneError({std::move(problem)});
  }
  OverrideValues written;
  std::vector<SceneProblem> problems = write_overrides(root, overrides, file, written);
  Scene scene = SceneReader(file, toml_text, std::move(written), overrides.origin, std::move(problems)).read(root);
  for (const SceneOverride& item : overrides.values) scene.overrides.push_back(to_string(item));
  return scene;
}

}  // namespace ffrf::scene
