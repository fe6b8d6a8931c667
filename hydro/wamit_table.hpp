// The numeric table under every WAMIT output file (internal to the WAMIT readers): rows of
// whitespace-separated numbers with their line numbers, an optional one-line header (NUMHDR = 1),
// blank lines skipped; and the order check of the period blocks. Errors are WamitFileError.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "hydro/wamit_reader.hpp"

namespace ffrf::hydro::wamit_detail {

struct Row {
  int line = 0;
  std::vector<double> fields;
};

// kind names the file type in messages (".1 added mass and damping", ...). Throws WamitFileError on
// an unreadable file, a non-numeric or non-finite field (line, field number, text), or no rows.
std::vector<Row> read_rows(const std::string& path, const std::string& kind);

// A whole-number field in [1, 9999] (a WAMIT mode index) or WamitFileError.
int mode_index(const std::string& path, const Row& row, std::size_t field, const std::string& what);

// Period blocks: rows with the same PER are contiguous; the finite periods are strictly monotonic
// (increasing or decreasing) in file order; no PER comes back after another one. Returns the block
// index of the row (0, 1, ... in file order).
class PeriodBlocks {
 public:
  explicit PeriodBlocks(std::string path) : path_(std::move(path)) {}
  std::size_t visit(double period, int line);
  const std::vector<double>& periods() const { return periods_; }
  const std::vector<int>& first_lines() const { return first_lines_; }

 private:
  std::string path_;
  std::vector<double> periods_;
  std::vector<int> first_lines_;
  std::map<double, std::size_t> seen_;
  double last_finite_ = 0.0;
  int direction_ = 0;  // +1 increasing, −1 decreasing, 0 unknown
};

}  // namespace ffrf::hydro::wamit_detail
