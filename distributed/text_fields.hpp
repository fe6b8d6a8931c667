// One record per line, fields separated by tabs: the text form of journal lines and of the results
// ranks send to rank 0. Any byte may appear in a field: backslash, tab, line feed and carriage
// return are written as \\, \t, \n and \r, so a record never spans lines and never splits wrongly.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ffrf::distributed {

std::string escape_field(std::string_view text);
// std::nullopt for a malformed escape (a lone backslash or an unknown escape letter).
std::optional<std::string> unescape_field(std::string_view text);

// The escaped fields joined by tabs (no line end).
std::string join_fields(const std::vector<std::string>& fields);
// Splits on tabs and unescapes; std::nullopt when a field is malformed.
std::optional<std::vector<std::string>> split_fields(std::string_view line);

}  // namespace ffrf::distributed
