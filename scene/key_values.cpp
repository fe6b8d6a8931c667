// A scene key's TOML value against its schema entry (see key_values.hpp).
#include "scene/key_values.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <variant>

#include "scene/units.hpp"

namespace ffrf::scene {
namespace {

KeyValue valid(Resolved value) { return {std::move(value), {}}; }
KeyValue invalid(std::string message) { return {std::nullopt, std::move(message)}; }

std::string join_names(std::string_view choices) {
  std::string text(choices);
  std::replace(text.begin(), text.end(), '|', ',');
  std::string spaced;
  for (char c : text) spaced += c == ',' ? std::string(", ") : std::string(1, c);
  return spaced;
}

KeyValue resolve_number(const KeySpec& key, const toml::node& node, const std::string& shown) {
  const std::string range = format_range(key);
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
    return invalid(fmt::format("{}{} (valid range {})", error->message, slips, range));
  }
  const double value = std::get<double>(result);
  if (!accepts(key, value)) {
    return invalid(fmt::format("out of range (valid range {}){}", range,
                               did_you_mean(unit_slips(key, written.number, written.unit))));
  }
  return valid({value, {}, {}});
}

// A whole number within the range (the range is finite: no value can wrap on conversion).
KeyValue resolve_integer(const KeySpec& key, const toml::node& node) {
  const auto value = node.value<double>();
  if (!node.is_number() || !value || !std::isfinite(*value) || std::floor(*value) != *value) {
    return invalid(fmt::format("expected a whole number (valid range {})", format_range(key)));
  }
  if (!key.range.contains(*value)) return invalid(fmt::format("out of range (valid range {})", format_range(key)));
  return valid({*value, {}, {}});
}

KeyValue resolve_choice(const KeySpec& key, const toml::node& node) {
  const auto* s = node.as_string();
  std::string_view rest = key.choices;
  bool known = false;
  while (s != nullptr && !known && !rest.empty()) {
    const auto bar = rest.find('|');
    known = rest.substr(0, bar) == s->get();
    rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
  }
  if (!known) return invalid(fmt::format("unknown choice; choose one of {}", join_names(key.choices)));
  return valid({0.0, s->get(), {}});
}

// An array of quantities: each an SI number or a "value unit" string, each in the key's range.
KeyValue resolve_list(const KeySpec& key, const toml::node& node) {
  const std::string range = format_range(key);
  const auto* array = node.as_array();
  if (array == nullptr || array->empty()) {
    return invalid(fmt::format("expected a non-empty array of numbers (valid range {})", range));
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
      return invalid(
          fmt::format("element {} = {}: {} (valid range {})", i + 1, show_parsed_value(element), why, range));
    }
    values.push_back(*value);
  }
  return valid({0.0, {}, std::move(values)});
}

}  // namespace

KeyValue resolve_value(const KeySpec& key, const toml::node& node, const std::string& shown) {
  switch (key.kind) {
    case ValueKind::number:
      return resolve_number(key, node, shown);
    case ValueKind::integer:
      return resolve_integer(key, node);
    case ValueKind::choice:
      return resolve_choice(key, node);
    case ValueKind::number_list:
      return resolve_list(key, node);
    case ValueKind::text:
      if (const auto* s = node.as_string()) return valid({0.0, s->get(), {}});
      return invalid("expected a text string");
  }
  return invalid("unknown value kind");
}

std::string show_parsed_value(const toml::node& node) {
  if (const auto* s = node.as_string()) return fmt::format("\"{}\"", s->get());
  if (const auto* i = node.as_integer()) return fmt::format("{}", i->get());
  if (const auto* f = node.as_floating_point()) return fmt::format("{}", f->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  std::ostringstream out;
  out << node.type();
  return fmt::format("({})", out.str());  // not "(" + ...: a false -Wstringop-overflow of GCC 12 through the PCH
}

}  // namespace ffrf::scene
