// Reading a scene file safely and naming what is written on one of its lines: load_scene(path)
// refuses a directory, a device or a file larger than max_scene_bytes before any parsing, and
// key_on_line finds the dotted key and the value of a "key = value" line under its [section], so
// that a line toml++ cannot parse (an integer beyond int64) is still reported with its key.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "scene/scene_key.hpp"

namespace ffrf::scene {

struct WrittenKey {
  std::string key;    // dotted: scene_key("boom.elements")
  std::string value;  // as written, without a trailing comment
};
// The key and value written on `line_number` (1-based) of `text`; nothing for another kind of line.
std::optional<WrittenKey> key_on_line(std::string_view text, int line_number);

}  // namespace ffrf::scene
