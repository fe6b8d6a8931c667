// The NetCDF access under the Capytaine reader (internal to capytaine_reader.cpp): a file opened
// read-only through the netCDF C library, its variables read whole with their dimensions by name,
// and an entry addressed by dimension names (the order of a variable's dimensions is the file's).
// Errors are CapytaineFileError naming the file and the variable.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hydro/capytaine_reader.hpp"

namespace ffrf::hydro::capytaine_detail {

struct Dimension {
  std::string name;
  std::size_t length = 0;
};

// A numeric variable: its dimensions in file order and its values in C (row-major) order.
struct Variable {
  std::string name;
  std::vector<Dimension> dimensions;
  std::vector<double> values;

  bool has_dimension(std::string_view dimension) const;
  std::string dimension_list() const;  // "(omega, radiating_dof, influenced_dof)"
  // The value at the given index of each named dimension; the variable's other dimensions have
  // length 1 (require_dimensions checked it) and take index 0.
  double at(std::initializer_list<std::pair<std::string_view, std::size_t>> index) const;
};

class NetcdfFile {
 public:
  explicit NetcdfFile(std::string path);  // CapytaineFileError when it is not a readable NetCDF file
  ~NetcdfFile();
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;

  const std::string& path() const { return path_; }
  bool has_variable(const std::string& name) const;
  Variable numbers(const std::string& name) const;                   // any numeric type, as double
  std::vector<std::string> strings(const std::string& name) const;  // 1-D string or 2-D char variable
  std::optional<std::string> global_text(const std::string& attribute) const;

 private:
  int variable_id(const std::string& name) const;
  std::string path_;
  int id_ = -1;
};

// Throws CapytaineFileError unless `variable` has every dimension of `needed` and every other
// dimension has length 1.
void require_dimensions(const std::string& path, const Variable& variable, const std::vector<std::string>& needed);

// The single value of a scalar variable (0-d, or every dimension of length 1).
double scalar(const NetcdfFile& file, const std::string& name);

}  // namespace ffrf::hydro::capytaine_detail
