// One scene key's TOML value checked against its entry in the schema table (scene_schema.hpp): a
// number (SI, or a "value unit" string; unit slips get a "did you mean"), a whole number, a choice,
// a list of quantities or a text string. Gives the value, or what is wrong with it and the valid
// range. With the loader (scene_loader.cpp), the only files that know toml++.
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <vector>

#include "scene/scene_schema.hpp"

namespace ffrf::scene {

// A key's valid value: `number` for numbers and whole numbers, `text` for choices and text,
// `list` for number lists.
struct Resolved {
  double number = 0.0;
  std::string text;
  std::vector<double> list;
};

// The valid value, or (when `value` is empty) the problem's message.
struct KeyValue {
  std::optional<Resolved> value;
  std::string problem;
};

// `node`: the key's TOML value, `shown`: the value as the file writes it.
KeyValue resolve_value(const KeySpec& key, const toml::node& node, const std::string& shown);

// A value as toml++ understood it (used when its source text is not available).
std::string show_parsed_value(const toml::node& node);

}  // namespace ffrf::scene
