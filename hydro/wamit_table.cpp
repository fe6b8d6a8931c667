// WAMIT numeric tables: tokenizing, header, period-block order (see wamit_table.hpp).
#include "hydro/wamit_table.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace ffrf::hydro {

WamitFileError::WamitFileError(std::string file, int line, const std::string& message)
    : std::runtime_error(line > 0 ? fmt::format("{}:{}: {}", file, line, message) : fmt::format("{}: {}", file, message)),
      file_(std::move(file)),
      line_(line) {}

namespace wamit_detail {

namespace {
bool parse_number(const std::string& token, double& value) {
  errno = 0;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !token.empty();
}
}  // namespace

std::vector<Row> read_rows(const std::string& path, const std::string& kind) {
  std::ifstream in(path);
  if (!in) throw WamitFileError(path, 0, fmt::format("cannot open the WAMIT {} file", kind));
  std::vector<Row> rows;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream tokens(text);
    std::vector<std::string> words;
    for (std::string w; tokens >> w;) words.push_back(w);
    if (words.empty()) continue;
    Row row{line, {}};
    double value = 0.0;
    if (line == 1 && !parse_number(words.front(), value)) continue;  // one header line (NUMHDR = 1)
    for (std::size_t f = 0; f < words.size(); ++f) {
      if (!parse_number(words[f], value))
        throw WamitFileError(path, line, fmt::format("field {} '{}' is not a number (WAMIT {} rows are numbers only)",
                                                     f + 1, words[f], kind));
      if (!std::isfinite(value))
        throw WamitFileError(path, line, fmt::format("field {} '{}' is not a finite number", f + 1, words[f]));
      row.fields.push_back(value);
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw WamitFileError(path, 0, fmt::format("no data rows: not a WAMIT {} file", kind));
  return rows;
}

int mode_index(const std::string& path, const Row& row, std::size_t field, const std::string& what) {
  const double v = row.fields[field];
  if (v != std::round(v) || v < 1.0 || v > 9999.0)
    throw WamitFileError(path, row.line, fmt::format("{} (field {}) = {} is not a mode index; valid: a whole number 1..9999",
                                                     what, field + 1, v));
  return static_cast<int>(v);
}

std::size_t PeriodBlocks::visit(double period, int line) {
  if (!periods_.empty() && period == periods_.back()) return periods_.size() - 1;
  if (const auto it = seen_.find(period); it != seen_.end())
    throw WamitFileError(path_, line, fmt::format(
        "period {} s appears again (its block began at line {}): duplicate period, or rows not grouped by period",
        period, first_lines_[it->second]));
  if (period > 0.0) {
    if (last_finite_ > 0.0) {
      const int direction = period > last_finite_ ? 1 : -1;
      if (direction_ != 0 && direction != direction_)
        throw WamitFileError(path_, line, fmt::format(
            "period {} s follows {} s: the periods are not monotonic (they {} before); valid: strictly {} periods",
            period, last_finite_, direction_ > 0 ? "increased" : "decreased", direction_ > 0 ? "increasing" : "decreasing"));
      direction_ = direction;
    }
    last_finite_ = period;
  }
  seen_.emplace(period, periods_.size());
  periods_.push_back(period);
  first_lines_.push_back(line);
  return periods_.size() - 1;
}

}  // namespace wamit_detail
}  // namespace ffrf::hydro
