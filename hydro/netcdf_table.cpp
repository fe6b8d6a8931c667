// NetCDF variables by name through the netCDF C library (see netcdf_table.hpp).
#include "hydro/netcdf_table.hpp"

#include <fmt/format.h>
#include <netcdf.h>

#include <algorithm>
#include <array>
#include <numeric>

namespace ffrf::hydro {

CapytaineFileError::CapytaineFileError(std::string file, std::string variable, const std::string& message)
    : std::runtime_error(variable.empty() ? fmt::format("{}: {}", file, message)
                                          : fmt::format("{}: variable {}: {}", file, variable, message)),
      file_(std::move(file)),
      variable_(std::move(variable)) {}

namespace capytaine_detail {

namespace {

std::string trimmed(std::string text) {
  const auto end = text.find_last_not_of(std::string(" \0", 2));
  text.erase(end == std::string::npos ? 0 : end + 1);
  return text;
}

}  // namespace

bool Variable::has_dimension(std::string_view dimension) const {
  return std::any_of(dimensions.begin(), dimensions.end(), [&](const Dimension& d) { return d.name == dimension; });
}

std::string Variable::dimension_list() const {
  std::vector<std::string> names;
  for (const Dimension& d : dimensions) names.push_back(fmt::format("{} = {}", d.name, d.length));
  return fmt::format("({})", fmt::join(names, ", "));
}

double Variable::at(std::initializer_list<std::pair<std::string_view, std::size_t>> index) const {
  std::size_t flat = 0;
  for (const Dimension& d : dimensions) {
    std::size_t i = 0;
    for (const auto& [dimension, value] : index)
      if (dimension == d.name) i = value;
    flat = flat * d.length + i;
  }
  return values.at(flat);
}

NetcdfFile::NetcdfFile(std::string path) : path_(std::move(path)) {
  if (const int status = nc_open(path_.c_str(), NC_NOWRITE, &id_); status != NC_NOERR) {
    id_ = -1;
    throw CapytaineFileError(path_, "", fmt::format("cannot read it as NetCDF ({}); valid: a NetCDF file written by Capytaine",
                                                    nc_strerror(status)));
  }
}

NetcdfFile::~NetcdfFile() {
  if (id_ >= 0) nc_close(id_);
}

bool NetcdfFile::has_variable(const std::string& name) const {
  int id = 0;
  return nc_inq_varid(id_, name.c_str(), &id) == NC_NOERR;
}

int NetcdfFile::variable_id(const std::string& name) const {
  int id = 0;
  if (nc_inq_varid(id_, name.c_str(), &id) != NC_NOERR)
    throw CapytaineFileError(path_, name, "missing from the dataset");
  return id;
}

Variable NetcdfFile::numbers(const std::string& name) const {
  const int id = variable_id(name);
  Variable variable{name, {}, {}};
  int count = 0;
  nc_inq_varndims(id_, id, &count);
  std::vector<int> dimension_ids(static_cast<std::size_t>(count));
  if (count > 0) nc_inq_vardimid(id_, id, dimension_ids.data());
  for (const int d : dimension_ids) {
    std::array<char, NC_MAX_NAME + 1> text{};
    std::size_t length = 0;
    nc_inq_dim(id_, d, text.data(), &length);
    variable.dimensions.push_back({text.data(), length});
  }
  const std::size_t size = std::accumulate(variable.dimensions.begin(), variable.dimensions.end(), std::size_t{1},
                                           [](std::size_t n, const Dimension& d) { return n * d.length; });
  variable.values.resize(size);
  if (size > 0) {
    if (const int status = nc_get_var_double(id_, id, variable.values.data()); status != NC_NOERR)
      throw CapytaineFileError(path_, name, fmt::format("cannot be read as numbers ({})", nc_strerror(status)));
  }
  return variable;
}

std::vector<std::string> NetcdfFile::strings(const std::string& name) const {
  const int id = variable_id(name);
  nc_type type = NC_NAT;
  int count = 0;
  nc_inq_vartype(id_, id, &type);
  nc_inq_varndims(id_, id, &count);
  std::vector<int> dimension_ids(static_cast<std::size_t>(count));
  if (count > 0) nc_inq_vardimid(id_, id, dimension_ids.data());
  std::vector<std::size_t> lengths;
  for (const int d : dimension_ids) {
    std::size_t length = 0;
    nc_inq_dimlen(id_, d, &length);
    lengths.push_back(length);
  }
  std::vector<std::string> result;
  if (type == NC_STRING && lengths.size() == 1) {
    std::vector<char*> text(lengths[0], nullptr);
    if (const int status = nc_get_var_string(id_, id, text.data()); status != NC_NOERR)
      throw CapytaineFileError(path_, name, fmt::format("cannot be read as strings ({})", nc_strerror(status)));
    for (const char* s : text) result.emplace_back(s != nullptr ? s : "");
    nc_free_string(text.size(), text.data());
    return result;
  }
  if (type == NC_CHAR && lengths.size() == 2) {
    std::string buffer(lengths[0] * lengths[1], '\0');
    if (!buffer.empty()) nc_get_var_text(id_, id, buffer.data());
    for (std::size_t i = 0; i < lengths[0]; ++i) result.push_back(trimmed(buffer.substr(i * lengths[1], lengths[1])));
    return result;
  }
  throw CapytaineFileError(path_, name, "expected a list of names (a 1-D string or a 2-D character variable)");
}

std::optional<std::string> NetcdfFile::global_text(const std::string& attribute) const {
  nc_type type = NC_NAT;
  std::size_t length = 0;
  if (nc_inq_att(id_, NC_GLOBAL, attribute.c_str(), &type, &length) != NC_NOERR) return std::nullopt;
  if (type == NC_CHAR) {
    std::string text(length, '\0');
    if (length > 0) nc_get_att_text(id_, NC_GLOBAL, attribute.c_str(), text.data());
    return trimmed(text);
  }
  if (type == NC_STRING && length >= 1) {
    std::vector<char*> text(length, nullptr);
    nc_get_att_string(id_, NC_GLOBAL, attribute.c_str(), text.data());
    std::string first = text[0] != nullptr ? text[0] : "";
    nc_free_string(text.size(), text.data());
    return first;
  }
  return std::nullopt;
}

void require_dimensions(const std::string& path, const Variable& variable, const std::vector<std::string>& needed) {
  for (const std::string& name : needed) {
    if (!variable.has_dimension(name))
      throw CapytaineFileError(path, variable.name, fmt::format("has dimensions {}; expected ({}), in any order",
                                                                variable.dimension_list(), fmt::join(needed, ", ")));
  }
  for (const Dimension& d : variable.dimensions) {
    if (std::find(needed.begin(), needed.end(), d.name) == needed.end() && d.length != 1)
      throw CapytaineFileError(path, variable.name, fmt::format(
          "has the extra dimension {} of length {} (dimensions {}); ffrf reads one value of it: select one "
          "(ds.sel({}=...)) before exporting", d.name, d.length, variable.dimension_list(), d.name));
  }
}

double scalar(const NetcdfFile& file, const std::string& name) {
  const Variable v = file.numbers(name);
  if (v.values.size() != 1)
    throw CapytaineFileError(file.path(), name, fmt::format("holds {} values {}; expected one (a scalar coordinate)",
                                                            v.values.size(), v.dimension_list()));
  return v.values.front();
}

}  // namespace capytaine_detail
}  // namespace ffrf::hydro
