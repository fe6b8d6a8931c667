// Scene loader: walks the TOML document against the schema table, collects every problem, and
// builds the Scene value. Only this file knows toml++.
#include "scene/scene_loader.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <map>
#include <sstream>
#include <toml++/toml.h>

#include "scene/scene_checks.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_schema.hpp"

namespace ffrf::scene {
namespace {

struct Resolved {
  double number = 0.0;
  std::string text;
  std::vector<double> list;  // number_list keys
};

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

// A value as toml++ understood it (used when its source text is not available).
std::string show_parsed_value(const toml::node& node) {
  if (const auto* s = node.as_string()) return fmt::format("\"{}\"", s->get());
  if (const auto* i = node.as_integer()) return fmt::format("{}", i->get());
  if (const auto* f = node.as_floating_point()) return fmt::format("{}", f->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  std::ostringstream out;
  out << node.type();
  return "(" + out.str() + ")";
}

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

std::string join_names(std::string_view choices) {
  std::string text(choices);
  std::replace(text.begin(), text.end(), '|', ',');
  std::string spaced;
  for (char c : text) spaced += c == ',' ? std::string(", ") : std::string(1, c);
  return spaced;
}

class SceneReader {
 public:
  SceneReader(std::string file, std::string_view text) : file_(std::move(file)) {
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
    Scene scene = build();
    check_physics(scene);
    if (!problems_.empty()) throw SceneError(sorted(std::move(problems_)));
    return scene;
  }

 private:
  void report(int line, std::string key, std::string value, std::string message) {
    problems_.push_back({file_, line, 0, std::move(key), std::move(value), std::move(message)});
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
          const auto hint = suggest_key(dotted);
          report(line_of(value), dotted, show_value(value),
                 fmt::format("unknown key{}", hint ? fmt::format("; did you mean {}?", *hint) : ""));
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
      resolve_present(key, *found->second);
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

  void resolve_present(const KeySpec& key, const toml::node& node) {
    const std::string shown = show_value(node);
    const std::string name(key.name);
    const int line = line_of(node);
    const std::string range = format_range(key);
    switch (key.kind) {
      case ValueKind::number: {
        QuantityResult result = QuantityError{fmt::format("expected a number (SI {}) or a \"value unit\" string",
                                                          si_unit(key.dimension).empty() ? "-" : si_unit(key.dimension))};
        WrittenQuantity written{shown, ""};
        if (const auto* s = node.as_string()) {
          result = parse_quantity(s->get(), key.dimension, key.allow_infinity);
          written = split_quantity(s->get()).value_or(WrittenQuantity{});
        } else if (node.is_number()) {
          result = check_bare_number(node.value<double>().value_or(0.0), key.dimension, key.allow_infinity);
        }
        if (const auto* error = std::get_if<QuantityError>(&result)) {
          const std::string slips = unit_required(key.dimension) && written.unit.empty()
                                        ? did_you_mean(unit_slips(key, written.number, written.unit))
                                        : std::string();
          report(line, name, shown, fmt::format("{}{} (valid range {})", error->message, slips, range));
        } else if (const double value = std::get<double>(result); !accepts(key, value)) {
          report(line, name, shown,
                 fmt::format("out of range (valid range {}){}", range,
                             did_you_mean(unit_slips(key, written.number, written.unit))));
        } else {
          resolved_[name] = {value, {}, {}};
        }
        return;
      }
      case ValueKind::integer: {
        // A whole number within the range (the range is finite: no value can wrap on conversion).
        const auto value = node.value<double>();
        if (!node.is_number() || !value || !std::isfinite(*value) || std::floor(*value) != *value) {
          report(line, name, shown, fmt::format("expected a whole number (valid range {})", range));
        } else if (!key.range.contains(*value)) {
          report(line, name, shown, fmt::format("out of range (valid range {})", range));
        } else {
          resolved_[name] = {*value, {}, {}};
        }
        return;
      }
      case ValueKind::choice: {
        const auto* s = node.as_string();
        std::string_view rest = key.choices;
        bool known = false;
        while (s != nullptr && !known && !rest.empty()) {
          const auto bar = rest.find('|');
          known = rest.substr(0, bar) == s->get();
          rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
        }
        if (!known) {
          report(line, name, shown, fmt::format("unknown choice; choose one of {}", join_names(key.choices)));
        } else {
          resolved_[name] = {0.0, s->get(), {}};
        }
        return;
      }
      case ValueKind::number_list:
        resolve_list(key, node);
        return;
      case ValueKind::text:
        if (const auto* s = node.as_string()) {
          resolved_[name] = {0.0, s->get(), {}};
        } else {
          report(line, name, shown, "expected a text string");
        }
        return;
    }
  }

  // An array of quantities: each an SI number or a "value unit" string, each in the key's range.
  void resolve_list(const KeySpec& key, const toml::node& node) {
    const std::string name(key.name);
    const std::string range = format_range(key);
    const auto* array = node.as_array();
    if (array == nullptr || array->empty()) {
      report(line_of(node), name, show_value(node), fmt::format("expected a non-empty array of numbers (valid range {})", range));
      return;
    }
    std::vector<double> values;
    for (std::size_t i = 0; i < array->size(); ++i) {
      const toml::node& element = *array->get(i);
      QuantityResult result = QuantityError{"expected a number"};
      if (const auto* s = element.as_string()) {
        result = parse_quantity(s->get(), key.dimension, false);
      } else if (element.is_number()) {
        result = check_number(element.value<double>().value_or(0.0), false);
      }
      const double* value = std::get_if<double>(&result);
      if (value == nullptr || !accepts(key, *value)) {
        const std::string why = value == nullptr ? std::get<QuantityError>(result).message : "out of range";
        report(line_of(node), name, show_value(node),
               fmt::format("element {} = {}: {} (valid range {})", i + 1, show_parsed_value(element), why, range));
        return;
      }
      values.push_back(*value);
    }
    resolved_[name] = {0.0, {}, std::move(values)};
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

  double number(std::string_view name) const { return resolved_.at(std::string(key_spec(name).name)).number; }
  const std::string& text(std::string_view name) const { return resolved_.at(std::string(key_spec(name).name)).text; }
  bool has(std::string_view name) const { return resolved_.contains(std::string(key_spec(name).name)); }
  const std::vector<double>& list(std::string_view name) const { return resolved_.at(std::string(key_spec(name).name)).list; }

  // Checks that involve several keys (only run when every key is valid on its own).
  void check_scene() {
    if (sections_.contains("wave")) check_wave_keys();
    if (hub_) {
      for (const char* key : {"boom.angle", "boom.root_x", "boom.root_y"}) {
        if (present_.contains(key)) {
          report(line_of(*present_.at(key)), key, show_value(*present_.at(key)),
                 "belongs to a hull crane; a hub scene clamps the boom at hub.radius along hub.angle");
        }
      }
    }
  }

  // The keys a [wave] spectrum needs, and no keys of another spectrum.
  void check_wave_keys() {
    const std::string& spectrum = text("wave.spectrum");
    const int wave_line = line_of(*sections_.at("wave"));
    const auto need = [&](const char* key) {
      if (!present_.contains(key)) {
        report(wave_line, key, "",
               fmt::format("missing key: wave.spectrum = \"{}\" needs it ({}; valid range {})", spectrum,
                           key_spec(key).help, format_range(key_spec(key))));
      }
    };
    const auto refuse = [&](const char* key, std::string_view owner) {
      if (const auto found = present_.find(key); found != present_.end()) {
        report(line_of(*found->second), key, show_value(*found->second),
               fmt::format("belongs to wave.spectrum = {}, not \"{}\"; remove it or change wave.spectrum", owner,
                           spectrum));
      }
    };
    const bool regular = spectrum == "regular", components = spectrum == "components";
    const bool parametric = !regular && !components;
    for (const char* key : {"wave.height", "wave.period"}) regular ? need(key) : refuse(key, "\"regular\"");
    for (const char* key : {"wave.significant_height", "wave.peak_period"}) {
      parametric ? need(key) : refuse(key, "\"jonswap\" or \"pierson-moskowitz\"");
    }
    if (spectrum != "jonswap") {
      for (const char* key : {"wave.peak_enhancement", "wave.sigma_below", "wave.sigma_above"}) refuse(key, "\"jonswap\"");
    }
    for (const char* key : {"wave.component_frequencies", "wave.component_amplitudes", "wave.component_phases"}) {
      components ? need(key) : refuse(key, "\"components\"");
    }
    if (!parametric) {
      for (const char* key : {"wave.seed", "wave.components", "wave.frequency_min", "wave.frequency_max", "wave.amplitudes"}) {
        refuse(key, "\"jonswap\" or \"pierson-moskowitz\"");
      }
    }
    if (components && has("wave.component_frequencies") && has("wave.component_amplitudes") &&
        has("wave.component_phases")) {
      const std::size_t count = list("wave.component_frequencies").size();
      for (const char* key : {"wave.component_amplitudes", "wave.component_phases"}) {
        if (list(key).size() != count) {
          report(line_of(*present_.at(key)), key, show_value(*present_.at(key)),
                 fmt::format("{} values for {} component frequencies (valid: one per frequency)", list(key).size(), count));
        }
      }
    }
    if (parametric && has("wave.frequency_min") && has("wave.frequency_max") &&
        !(number("wave.frequency_max") > number("wave.frequency_min"))) {
      report(line_of(*present_.at("wave.frequency_max")), "wave.frequency_max", show_value(*present_.at("wave.frequency_max")),
             fmt::format("not above wave.frequency_min = {:g} rad/s (valid range ({:g}, 100] rad/s)",
                         number("wave.frequency_min"), number("wave.frequency_min")));
    }
    if (parametric && has("wave.frequency_min") != has("wave.frequency_max")) {
      const char* given = has("wave.frequency_min") ? "wave.frequency_min" : "wave.frequency_max";
      report(line_of(*present_.at(given)), given, show_value(*present_.at(given)),
             "give both wave.frequency_min and wave.frequency_max (a band), or neither (the energy band)");
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

  double boom_mass_per_length() const {
    return has("boom.mass_per_length") ? number("boom.mass_per_length") : number("boom.density") * number("boom.area");
  }

  Scene build() const {
    Scene scene;
    scene.file = file_;
    if (has("scene.name")) scene.name = text("scene.name");
    if (has("scene.description")) scene.description = text("scene.description");
    const fem::BeamSection section{number("boom.youngs_modulus"), number("boom.area"), number("boom.second_moment"),
                                   boom_mass_per_length()};
    scene.boom.mesh = fem::BeamMesh{number("boom.length"), static_cast<int>(number("boom.elements")), section};
    scene.boom.boundary = boundary_of(text("boom.boundary"));
    scene.boom.damping_ratio = number("boom.damping_ratio");
    if (has("boom.density")) scene.boom.density = number("boom.density");
    scene.boom.stiffening = parse_stiffening(text("boom.stiffening")).value_or(Stiffening::none);
    if (crane_) {
      scene.boom.mount = BoomMount{number("boom.angle"), number("boom.root_x"), number("boom.root_y")};
      scene.hull = Hull{number("hull.mass"),  number("hull.pitch_radius_of_gyration"),
                        number("hull.length"), number("hull.width"), number("hull.depth"), number("hull.g1_above_keel"),
                        number("hull.g1_aft_of_mid_length")};
    }
    if (hub_) {
      const std::string& motion = text("hub.motion");
      scene.hub = Hub{number("hub.radius"), number("hub.angle"),
                      motion == "spin-up" ? HubMotion::spin_up
                                          : (motion == "constant-spin" ? HubMotion::constant_spin : HubMotion::fixed),
                      number("hub.spin_rate"), number("hub.spin_up_time")};
      scene.boom.mount = BoomMount{0.0, number("hub.radius"), 0.0};
    }
    if (cargo_) {
      const double l = number("cargo.length");
      const double h = number("cargo.height");
      const bool derived = !has("cargo.pitch_radius_of_gyration");
      scene.cargo = Cargo{number("cargo.mass"), l, h, number("cargo.hook_x"), number("cargo.hook_y"),
                          derived ? std::sqrt((l * l + h * h) / 12.0) : number("cargo.pitch_radius_of_gyration"),
                          derived};
      scene.wire = Wire{number("wire.unstretched_length"), number("wire.stiffness"), number("wire.damping_ratio")};
    }
    scene.environment = Environment{number("environment.water_density"), number("environment.gravity"),
                                    number("environment.water_depth")};
    if (sections_.contains("wave")) build_wave(scene);
    scene.radiation = Radiation{number("radiation.surge_added_mass"), number("radiation.heave_added_mass"),
                                number("radiation.pitch_added_inertia"), number("radiation.surge_damping"),
                                number("radiation.heave_damping"), number("radiation.pitch_damping")};
    scene.mooring = Mooring{number("mooring.surge_stiffness")};
    scene.simulation = Simulation{number("simulation.duration"), number("simulation.output_interval"),
                                  text("simulation.initial_state") == "as-built" ? InitialState::as_built
                                                                                 : InitialState::static_equilibrium,
                                  number("simulation.cargo_lift"), number("simulation.deflection_limit"),
                                  number("simulation.constraint_drift_limit")};
    return scene;
  }

  void build_wave(Scene& scene) const {
    const std::string& spectrum = text("wave.spectrum");
    const bool head = text("wave.direction") == "head";
    if (spectrum == "regular") {
      scene.wave = Wave{number("wave.height"), number("wave.period"), head ? WaveDirection::head : WaveDirection::following,
                        number("wave.ramp_periods")};
      return;
    }
    IrregularSea sea;
    sea.spectrum = spectrum == "jonswap"             ? SeaSpectrum::jonswap
                   : spectrum == "pierson-moskowitz" ? SeaSpectrum::pierson_moskowitz
                                                     : SeaSpectrum::components;
    sea.heading = head ? hydro::WaveHeading::head : hydro::WaveHeading::following;
    sea.ramp_periods = number("wave.ramp_periods");
    if (sea.spectrum == SeaSpectrum::components) {
      sea.component_frequencies = list("wave.component_frequencies");
      sea.component_amplitudes = list("wave.component_amplitudes");
      sea.component_phases = list("wave.component_phases");
    } else {
      sea.significant_height = number("wave.significant_height");
      sea.peak_period = number("wave.peak_period");
      sea.peak_enhancement = sea.spectrum == SeaSpectrum::jonswap ? number("wave.peak_enhancement") : 1.0;
      sea.sigma_below = number("wave.sigma_below");
      sea.sigma_above = number("wave.sigma_above");
      sea.seed = static_cast<std::uint64_t>(number("wave.seed"));
      sea.component_count = static_cast<int>(number("wave.components"));
      if (has("wave.frequency_min")) sea.frequency_min = number("wave.frequency_min");
      if (has("wave.frequency_max")) sea.frequency_max = number("wave.frequency_max");
      sea.random_amplitudes = text("wave.amplitudes") == "rayleigh";
    }
    scene.sea = std::move(sea);
  }

  static fem::Boundary boundary_of(const std::string& keyword) {
    // The schema's choices equal fem::boundary_choices(); the loader has validated the keyword.
    const auto boundary = fem::parse_boundary(keyword);
    if (!boundary) throw std::logic_error("scene schema and fem::parse_boundary disagree on " + keyword);
    return *boundary;
  }

  static std::vector<SceneProblem> sorted(std::vector<SceneProblem> problems) {
    std::stable_sort(problems.begin(), problems.end(), [](const SceneProblem& a, const SceneProblem& b) {
      return std::pair(a.line == 0, a.line) < std::pair(b.line == 0, b.line);
    });
    return problems;
  }

  // The value as written in the scene file (one-line values), else as parsed.
  std::string show_value(const toml::node& node) const {
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
  text += ": ";
  if (!problem.key.empty()) text += problem.value.empty() ? problem.key + ": " : problem.key + " = " + problem.value + ": ";
  return text + problem.message;
}

SceneError::SceneError(std::vector<SceneProblem> problems)
    : std::runtime_error(join_messages(problems)), problems_(std::move(problems)) {}

Scene load_scene_text(std::string_view toml_text, const std::string& file) {
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
  return SceneReader(file, toml_text).read(root);
}

}  // namespace ffrf::scene
