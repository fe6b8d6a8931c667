// JSON documents of the reports, built with nlohmann-json (Debian nlohmann-json3-dev): ordered
// objects, so keys appear in the order the report writes them. Numbers that JSON cannot represent
// (NaN, infinity) are written as null. Headers see only the forward declaration; the full library
// is included by the .cpp files that build documents.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

namespace ffrf::report {

using Json = nlohmann::ordered_json;

// The document as text: two-space indentation, UTF-8 as is, a final newline.
std::string json_text(const Json& document);

}  // namespace ffrf::report
