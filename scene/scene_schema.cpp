// The scene schema table (docs/architecture.md, "Conventions"): the one place where scene keys are declared.
// Values of the reference scene live in cases/paper_floating_crane.toml, not here; defaults here
// are the values a scene gets when it leaves a key out.
#include "scene/scene_schema.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>
#include <vector>

#include "scene/scene_schema_table.hpp"

namespace ffrf::scene {
using namespace schema_table;  // the table and its range helpers (scene/scene_schema_table.hpp)

namespace {

double display_factor(const KeySpec& key) {
  return key.display_unit.empty() ? 1.0 : unit_factor(key.display_unit, key.dimension);
}

std::string_view display_unit(const KeySpec& key) {
  return key.display_unit.empty() ? si_unit(key.dimension) : key.display_unit;
}

std::string format_bound(double value, double factor) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{:.6g}", value / factor);
}

template <class Items, class Name>
std::optional<std::string_view> closest(std::string_view wanted, const Items& items, Name name) {
  std::optional<std::string_view> best;
  std::size_t best_distance = std::max<std::size_t>(2, wanted.size() / 3) + 1;
  for (const auto& item : items) {
    const std::size_t distance = edit_distance(wanted, name(item));
    if (distance < best_distance) {
      best_distance = distance;
      best = name(item);
    }
  }
  return best;
}

}  // namespace

bool Range::contains(double value) const {
  const bool above = lower.closed ? value >= lower.value : value > lower.value;
  const bool below = upper.closed ? value <= upper.value : value < upper.value;
  return above && below;
}

std::span<const SectionSpec> scene_sections() { return kSections; }
std::span<const KeySpec> scene_keys() { return kKeys; }

const SectionSpec* find_section(std::string_view name) {
  const auto it = std::find_if(kSections.begin(), kSections.end(), [&](const SectionSpec& s) { return s.name == name; });
  return it == kSections.end() ? nullptr : &*it;
}

const KeySpec* find_key(std::string_view dotted_name) {
  const auto it = std::find_if(kKeys.begin(), kKeys.end(), [&](const KeySpec& k) { return k.name == dotted_name; });
  return it == kKeys.end() ? nullptr : &*it;
}

const KeySpec& key_spec(std::string_view dotted_name) {
  const KeySpec* key = find_key(dotted_name);
  if (key == nullptr) throw std::logic_error(fmt::format("scene key '{}' is not in the schema", dotted_name));
  return *key;
}

std::string format_range(const KeySpec& key) {
  if (key.kind == ValueKind::choice) return std::string(key.choices);
  if (key.kind == ValueKind::text) return "any text";
  if (key.kind == ValueKind::number_list) {
    const KeySpec element{key.name, ValueKind::number, key.dimension, key.range, key.presence, 0.0, {}, {}, key.help,
                          key.display_unit};
    return format_range(element) + " each";
  }
  const double factor = display_factor(key);
  std::string range = fmt::format("{}{}, {}{}", key.range.lower.closed ? '[' : '(',
                                  format_bound(key.range.lower.value, factor),
                                  format_bound(key.range.upper.value, factor), key.range.upper.closed ? ']' : ')');
  const std::string_view unit = key.kind == ValueKind::number ? display_unit(key) : std::string_view{};
  if (!unit.empty()) {  // not `" " + std::string(unit)`: a false -Wstringop-overflow of GCC 12 through the PCH
    range += ' ';
    range += unit;
  }
  return key.allow_infinity ? range + " or inf" : range;
}

bool accepts(const KeySpec& key, double value) {
  return key.range.contains(value) || (key.allow_infinity && value == kInf);
}

std::vector<std::string> unit_slips(const KeySpec& key, std::string_view number, std::string_view written_unit) {
  if (key.kind != ValueKind::number) return {};
  double value = 0.0;
  const std::string_view digits = !number.empty() && number.front() == '+' ? number.substr(1) : number;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec != std::errc{} || end != digits.data() + digits.size() || !std::isfinite(value) || value == 0.0) return {};
  // The middle of the range: the default when there is one, else the geometric (or plain) mean of its ends.
  const Range& range = key.range;
  double middle = 0.5 * (range.lower.value + range.upper.value);
  if (key.presence == Presence::defaulted && key.default_value != 0.0 && std::isfinite(key.default_value)) {
    middle = key.default_value;
  } else if (range.lower.value > 0.0) {
    middle = std::sqrt(range.lower.value * range.upper.value);
  }
  const auto distance = [&](double si) {
    return middle > 0.0 && si > 0.0 ? std::abs(std::log(si / middle)) : std::abs(si - middle);
  };
  std::vector<std::pair<double, double>> found;  // (distance, SI value)
  std::vector<std::string> names;
  for (const UnitChoice& unit : units_of(key.dimension)) {
    const double si = value * unit.factor;
    if (unit.symbol == written_unit || (written_unit.empty() && !unit_required(key.dimension) && unit.factor == 1.0)) {
      continue;
    }
    if (!range.contains(si)) continue;
    const bool same = std::any_of(found.begin(), found.end(), [&](const auto& f) { return f.second == si; });
    if (same) continue;
    found.emplace_back(distance(si), si);
    names.push_back(fmt::format("\"{} {}\"", number, unit.symbol));
  }
  std::vector<std::size_t> order(found.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return found[a].first < found[b].first; });
  std::vector<std::string> sorted;
  for (std::size_t i = 0; i < order.size() && i < 2; ++i) sorted.push_back(names[order[i]]);
  return sorted;
}

std::string did_you_mean(const std::vector<std::string>& suggestions) {
  if (suggestions.empty()) return {};
  std::string text = "; did you mean " + suggestions.front();
  for (std::size_t i = 1; i < suggestions.size(); ++i) text += " or " + suggestions[i];
  return text + "?";
}

std::string format_default(const KeySpec& key) {
  if (key.presence != Presence::defaulted) return {};
  if (key.kind == ValueKind::choice || key.kind == ValueKind::text) return std::string(key.default_text);
  const std::string value = format_bound(key.default_value, display_factor(key));
  const std::string_view unit = key.kind == ValueKind::number ? display_unit(key) : std::string_view{};
  return unit.empty() ? value : value + " " + std::string(unit);
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment: insertions, deletions, substitutions and adjacent transpositions.
  const std::size_t columns = b.size() + 1;
  std::vector<std::size_t> d((a.size() + 1) * columns);
  const auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * columns + j]; };
  for (std::size_t i = 0; i <= a.size(); ++i) at(i, 0) = i;
  for (std::size_t j = 0; j <= b.size(); ++j) at(0, j) = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      at(i, j) = std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
    }
  }
  return at(a.size(), b.size());
}

std::optional<std::string_view> suggest_key(std::string_view dotted_name) {
  // Same leaf in another section ("hull.youngs_modulus" -> "boom.youngs_modulus") first.
  const std::string_view leaf = dotted_name.substr(dotted_name.find('.') + 1);
  std::vector<std::string_view> same_leaf;
  for (const KeySpec& key : kKeys) {
    if (key.leaf() == leaf) same_leaf.push_back(key.name);
  }
  if (same_leaf.size() == 1) return same_leaf.front();
  return closest(dotted_name, kKeys, [](const KeySpec& key) { return key.name; });
}

std::optional<std::string_view> suggest_section(std::string_view name) {
  return closest(name, kSections, [](const SectionSpec& section) { return section.name; });
}

}  // namespace ffrf::scene
