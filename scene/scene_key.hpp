// A scene key named in code: scene_key("hull.mass") is the dotted name, checked at compile time
// against the one schema table (scene/scene_schema_table.hpp), so a key the code reads, tests or
// names in a message cannot drift from its declaration: a name that is not in the table does not
// compile.
#pragma once

#include <string_view>

#include "scene/scene_schema_table.hpp"

namespace ffrf::scene {

// The table's own name (a string literal, so null-terminated): usable as text and as a string_view.
consteval const char* scene_key(std::string_view dotted_name) {
  for (const KeySpec& spec : schema_table::kKeys) {
    if (spec.name == dotted_name) return spec.name.data();
  }
  throw "not a key of the scene schema (scene/scene_schema_table.hpp)";  // not a constant expression: no build
}

}  // namespace ffrf::scene
