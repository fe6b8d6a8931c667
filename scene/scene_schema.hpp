// The scene schema: every scene key declared once — dotted name, kind, physical dimension, valid
// range, default or requirement, help text: one definition drives code and docs. The loader (scene_loader.cpp),
// `ffrf check` and the Markdown reference docs/scenes.md (`ffrf scene-reference`) all read this
// one table; nothing else lists scene keys.
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/units.hpp"

namespace ffrf::scene {

// Whether a section must appear. A crane scene is one that has any crane section; it then needs
// all of them. Optional sections may be left out as a whole (their keys take their defaults).
enum class SectionRole { required, crane, optional };

struct SectionSpec {
  std::string_view name;  // "boom"
  SectionRole role;
  std::string_view help;
};

enum class ValueKind {
  number,   // a physical quantity: SI number or "value unit" string
  integer,  // a whole number
  choice,   // one keyword of `choices`
  text,     // free text
  number_list,  // an array of physical quantities (SI numbers or "value unit" strings), each in range
};

// Whether a key must appear when its section is present.
enum class Presence {
  required,        // always
  crane_required,  // in a crane scene only
  defaulted,       // has a default
  optional,        // may be absent; the loader derives a value or leaves it empty
  one_of,          // exactly one key of the same `one_of` group
};

struct Bound {
  double value;
  bool closed;  // the bound itself is valid
};

struct Range {
  Bound lower{-std::numeric_limits<double>::infinity(), false};
  Bound upper{std::numeric_limits<double>::infinity(), false};
  bool contains(double value) const;
};

struct KeySpec {
  std::string_view name;  // dotted: "section.key"
  ValueKind kind;
  Dimension dimension;    // for number keys
  Range range;            // SI, for number and integer keys
  Presence presence;
  double default_value;           // number/integer keys with Presence::defaulted
  std::string_view default_text;  // choice/text keys with Presence::defaulted
  std::string_view choices;       // "following|head" for choice keys
  std::string_view help;
  std::string_view display_unit = {};  // unit for ranges and defaults in messages and docs ("deg")
  bool allow_infinity = false;
  std::string_view one_of = {};  // group name for Presence::one_of

  std::string_view section() const { return name.substr(0, name.find('.')); }
  std::string_view leaf() const { return name.substr(name.find('.') + 1); }
};

std::span<const SectionSpec> scene_sections();
std::span<const KeySpec> scene_keys();

const SectionSpec* find_section(std::string_view name);
const KeySpec* find_key(std::string_view dotted_name);
// The key spec by name; throws std::logic_error for a name that is not in the table (a bug).
const KeySpec& key_spec(std::string_view dotted_name);

// "[0.1, 1000] m", "[1, 10000]", "(0, 90) deg" in the key's display unit ("... or inf" where allowed).
std::string format_range(const KeySpec& key);
// Whether a value (SI) is valid for the key: inside its range, or +inf where allowed.
bool accepts(const KeySpec& key, double value);
// A unit slip: the other units of the key's dimension in which `number` (as written, with
// `written_unit`; empty for a bare SI number) would lie in the key's range, as "\"210 GPa\"",
// nearest the middle of the range first (at most two).
std::vector<std::string> unit_slips(const KeySpec& key, std::string_view number, std::string_view written_unit);
// "; did you mean A?" or "; did you mean A or B?" (empty for no suggestion).
std::string did_you_mean(const std::vector<std::string>& suggestions);
// "16", "clamped-free", "inf m", "0.02"; empty when the key has no default.
std::string format_default(const KeySpec& key);
// The closest known key to a misspelled dotted name (edit distance), if any is close enough.
std::optional<std::string_view> suggest_key(std::string_view dotted_name);
std::optional<std::string_view> suggest_section(std::string_view name);
// Levenshtein distance (exposed for tests).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The Markdown scene reference (docs/scenes.md), generated from the table.
std::string scene_reference_markdown();

}  // namespace ffrf::scene
