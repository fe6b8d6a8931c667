// Capytaine NetCDF datasets for the planar model (see capytaine_reader.hpp).
#include "hydro/capytaine_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>

#include "hydro/netcdf_table.hpp"

namespace ffrf::hydro {

namespace {

using capytaine_detail::NetcdfFile;
using capytaine_detail::require_dimensions;
using capytaine_detail::scalar;
using capytaine_detail::Variable;

constexpr std::array<const char*, kPlanarDofs> kDofNames{"Surge", "Heave", "Pitch"};
constexpr std::array<const char*, 5> kFrequencyDimensions{"omega", "freq", "period", "wavelength", "wavenumber"};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// Index of each planar dof (surge, heave, pitch) in the coordinate variable `coordinate`.
std::array<std::size_t, kPlanarDofs> planar_dofs(const NetcdfFile& file, const std::string& coordinate) {
  const std::vector<std::string> names = file.strings(coordinate);
  std::array<std::size_t, kPlanarDofs> index{};
  for (int d = 0; d < kPlanarDofs; ++d) {
    const auto it = std::find_if(names.begin(), names.end(),
                                 [&](const std::string& n) { return lower(n) == lower(kDofNames[static_cast<std::size_t>(d)]); });
    if (it == names.end())
      throw CapytaineFileError(file.path(), coordinate, fmt::format(
          "holds {}; ffrf needs Surge, Heave and Pitch (Capytaine's rigid-body dof names): no {}",
          fmt::join(names, ", "), kDofNames[static_cast<std::size_t>(d)]));
    index[static_cast<std::size_t>(d)] = static_cast<std::size_t>(it - names.begin());
  }
  return index;
}

// The frequency dimension of a variable (omega, or the period, freq, ... Capytaine indexed it by).
std::string frequency_dimension(const std::string& path, const Variable& v) {
  for (const char* name : kFrequencyDimensions)
    if (v.has_dimension(name)) return name;
  throw CapytaineFileError(path, v.name, fmt::format("has dimensions {}; expected a frequency dimension (one of omega, "
                                                     "freq, period, wavelength, wavenumber)", v.dimension_list()));
}

// ω [rad/s] along the frequency dimension, from the variable omega.
std::vector<double> angular_frequencies(const NetcdfFile& file, const std::string& dimension) {
  const Variable omega = file.numbers("omega");
  require_dimensions(file.path(), omega, {dimension});
  std::vector<double> values;
  for (std::size_t k = 0; k < omega.values.size(); ++k) {
    const double w = omega.at({{dimension, k}});
    if (std::isnan(w) || w < 0.0)
      throw CapytaineFileError(file.path(), "omega", fmt::format("entry {} is {}; valid: ω >= 0 rad/s (inf: the infinite-frequency limit)", k, w));
    values.push_back(w);
  }
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  if (const auto twin = std::adjacent_find(sorted.begin(), sorted.end()); twin != sorted.end())
    throw CapytaineFileError(file.path(), "omega", fmt::format("ω = {} rad/s appears twice; valid: distinct frequencies", *twin));
  return values;
}

// An entry that must be a number: NaN is the fill value of a problem the dataset does not hold.
double present(const std::string& path, const Variable& v, double value, const std::string& where) {
  if (std::isnan(value))
    throw CapytaineFileError(path, v.name, fmt::format("is missing (NaN, the fill value) at {}: the BEM run did not solve that problem", where));
  return value;
}

PlanarMatrix planar_matrix(const std::string& path, const Variable& v, const std::string& frequency, std::size_t k,
                           const std::array<std::size_t, kPlanarDofs>& influenced,
                           const std::array<std::size_t, kPlanarDofs>& radiating, const std::string& where) {
  PlanarMatrix m;
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
      const double value = v.at({{frequency, k}, {"influenced_dof", influenced[ui]}, {"radiating_dof", radiating[uj]}});
      m(i, j) = kBemToPlanarSign[ui] * kBemToPlanarSign[uj] *
                present(path, v, value, fmt::format("{}, influenced_dof = {}, radiating_dof = {}", where, kDofNames[ui], kDofNames[uj]));
    }
  return m;
}

void read_radiation(const NetcdfFile& file, CapytaineDataset& data, std::string& frequency_dim, std::vector<double>& omega,
                    const std::array<std::size_t, kPlanarDofs>& influenced) {
  const std::string& path = file.path();
  const Variable added_mass = file.numbers("added_mass");
  frequency_dim = frequency_dimension(path, added_mass);
  require_dimensions(path, added_mass, {frequency_dim, "influenced_dof", "radiating_dof"});
  const Variable damping = file.numbers("radiation_damping");
  require_dimensions(path, damping, {frequency_dim, "influenced_dof", "radiating_dof"});
  omega = angular_frequencies(file, frequency_dim);
  const auto radiating = planar_dofs(file, "radiating_dof");
  std::vector<std::size_t> finite;
  PlanarRadiation& r = data.radiation;
  r.source = path;
  for (std::size_t k = 0; k < omega.size(); ++k) {
    const std::string where = fmt::format("ω = {} rad/s", omega[k]);
    if (omega[k] == 0.0) {
      r.has_zero_frequency = true;
      r.zero_frequency_added_mass = planar_matrix(path, added_mass, frequency_dim, k, influenced, radiating, where);
    } else if (std::isinf(omega[k])) {
      r.has_infinite_frequency = true;
      r.infinite_frequency_added_mass = planar_matrix(path, added_mass, frequency_dim, k, influenced, radiating, where);
    } else {
      finite.push_back(k);
    }
  }
  if (finite.empty()) throw CapytaineFileError(path, "omega", "no finite frequency ω > 0: valid datasets hold at least one");
  std::sort(finite.begin(), finite.end(), [&](std::size_t a, std::size_t b) { return omega[a] < omega[b]; });
  for (const std::size_t k : finite) {
    const std::string where = fmt::format("ω = {} rad/s", omega[k]);
    r.frequency.push_back(omega[k]);
    r.added_mass.push_back(planar_matrix(path, added_mass, frequency_dim, k, influenced, radiating, where));
    r.damping.push_back(planar_matrix(path, damping, frequency_dim, k, influenced, radiating, where));
  }
}

// Re and Im positions along the dimension `complex` (xarray writes the coordinate ["re", "im"]).
std::array<std::size_t, 2> complex_parts(const NetcdfFile& file) {
  if (!file.has_variable("complex")) return {0, 1};
  const std::vector<std::string> parts = file.strings("complex");
  const auto re = std::find(parts.begin(), parts.end(), "re"), im = std::find(parts.begin(), parts.end(), "im");
  if (parts.size() != 2 || re == parts.end() || im == parts.end())
    throw CapytaineFileError(file.path(), "complex", fmt::format("holds {}; expected re, im", fmt::join(parts, ", ")));
  return {static_cast<std::size_t>(re - parts.begin()), static_cast<std::size_t>(im - parts.begin())};
}

void read_excitation(const NetcdfFile& file, CapytaineDataset& data, const std::string& frequency_dim,
                     const std::vector<double>& omega, const std::array<std::size_t, kPlanarDofs>& influenced) {
  std::vector<std::string> names;
  if (file.has_variable("Froude_Krylov_force") && file.has_variable("diffraction_force")) {
    names = {"Froude_Krylov_force", "diffraction_force"};
  } else if (file.has_variable("excitation_force")) {
    names = {"excitation_force"};
  } else {
    return;
  }
  const std::string& path = file.path();
  const std::vector<std::string> dims{"complex", frequency_dim, "wave_direction", "influenced_dof"};
  std::vector<Variable> forces;
  for (const std::string& name : names) {
    forces.push_back(file.numbers(name));
    if (!forces.back().has_dimension("complex"))
      throw CapytaineFileError(path, name, fmt::format("has dimensions {}; expected the complex values split along a "
                                                       "dimension `complex` (re, im), as Capytaine exports them",
                                                       forces.back().dimension_list()));
    require_dimensions(path, forces.back(), dims);
  }
  const auto [re, im] = complex_parts(file);
  const Variable direction = file.numbers("wave_direction");
  require_dimensions(path, direction, {"wave_direction"});
  PlanarExcitation x;
  x.source = path;
  for (const double beta : direction.values) x.heading_degrees.push_back(beta * 180.0 / std::numbers::pi);
  x.force.assign(direction.values.size(), {});
  std::vector<std::size_t> finite;
  for (std::size_t k = 0; k < omega.size(); ++k)
    if (omega[k] > 0.0 && std::isfinite(omega[k])) finite.push_back(k);
  std::sort(finite.begin(), finite.end(), [&](std::size_t a, std::size_t b) { return omega[a] < omega[b]; });
  for (const std::size_t k : finite) {
    x.frequency.push_back(omega[k]);
    for (std::size_t h = 0; h < direction.values.size(); ++h) {
      PlanarComplexVector f = PlanarComplexVector::Zero();
      for (const Variable& v : forces)
        for (int d = 0; d < kPlanarDofs; ++d) {
          const auto ud = static_cast<std::size_t>(d);
          const std::string where = fmt::format("ω = {} rad/s, wave_direction = {} rad, influenced_dof = {}", omega[k],
                                                direction.values[h], kDofNames[ud]);
          const double real = v.at({{"complex", re}, {frequency_dim, k}, {"wave_direction", h}, {"influenced_dof", influenced[ud]}});
          const double imaginary = v.at({{"complex", im}, {frequency_dim, k}, {"wave_direction", h}, {"influenced_dof", influenced[ud]}});
          // e^{−iωt} phasor → ffrf's e^{iωt}: the complex conjugate; then ffrf's pitch sign.
          f(d) += kBemToPlanarSign[ud] * std::complex<double>(present(path, v, real, where), -present(path, v, imaginary, where));
        }
      x.force[h].push_back(f);
    }
  }
  data.excitation = std::move(x);
  data.excitation_variables = fmt::format("{}", fmt::join(names, " + "));
}

void read_hydrostatics(const NetcdfFile& file, CapytaineDataset& data, const std::array<std::size_t, kPlanarDofs>& influenced) {
  if (!file.has_variable("hydrostatic_stiffness")) return;
  const Variable c = file.numbers("hydrostatic_stiffness");
  require_dimensions(file.path(), c, {"influenced_dof", "radiating_dof"});
  const auto radiating = planar_dofs(file, "radiating_dof");
  PlanarMatrix m;
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
      m(i, j) = kBemToPlanarSign[ui] * kBemToPlanarSign[uj] *
                present(file.path(), c, c.at({{"influenced_dof", influenced[ui]}, {"radiating_dof", radiating[uj]}}),
                        fmt::format("influenced_dof = {}, radiating_dof = {}", kDofNames[ui], kDofNames[uj]));
    }
  data.hydrostatics = m;
}

void read_environment(const NetcdfFile& file, CapytaineDataset& data) {
  const std::string& path = file.path();
  data.density = scalar(file, "rho");
  data.gravity = scalar(file, "g");
  data.water_depth = scalar(file, "water_depth");
  if (!(data.density > 0.0 && std::isfinite(data.density)))
    throw CapytaineFileError(path, "rho", fmt::format("= {}; valid: a water density > 0 kg/m^3", data.density));
  if (!(data.gravity > 0.0 && std::isfinite(data.gravity)))
    throw CapytaineFileError(path, "g", fmt::format("= {}; valid: gravity > 0 m/s^2", data.gravity));
  if (!(data.water_depth > 0.0))
    throw CapytaineFileError(path, "water_depth", fmt::format("= {}; valid: a depth > 0 m or inf (deep water)", data.water_depth));
  if (file.has_variable("forward_speed")) {
    const double speed = scalar(file, "forward_speed");
    if (speed != 0.0)
      throw CapytaineFileError(path, "forward_speed", fmt::format("= {} m/s; ffrf's hull has no forward speed: valid 0", speed));
  }
  if (const auto convention = file.global_text("incoming_waves_convention"); convention && lower(*convention) != "nemoh")
    throw CapytaineFileError(path, "", fmt::format(
        "attribute incoming_waves_convention = \"{}\"; valid: \"Nemoh\" (Capytaine's own convention; rerun with it)", *convention));
}

}  // namespace

CapytaineDataset read_capytaine(const std::string& path) {
  const NetcdfFile file(path);
  CapytaineDataset data;
  read_environment(file, data);
  const auto influenced = planar_dofs(file, "influenced_dof");
  std::string frequency_dim;
  std::vector<double> omega;
  read_radiation(file, data, frequency_dim, omega, influenced);
  read_excitation(file, data, frequency_dim, omega, influenced);
  read_hydrostatics(file, data, influenced);
  return data;
}

CapytaineDataset at_density(CapytaineDataset data, double density) {
  if (!(density > 0.0 && std::isfinite(density)))
    throw std::invalid_argument(fmt::format("at_density: water density {} kg/m^3; valid range > 0", density));
  const double factor = density / data.density;
  PlanarRadiation& r = data.radiation;
  for (auto& a : r.added_mass) a *= factor;
  for (auto& b : r.damping) b *= factor;
  r.zero_frequency_added_mass *= factor;
  r.infinite_frequency_added_mass *= factor;
  if (data.excitation)
    for (auto& per_heading : data.excitation->force)
      for (auto& x : per_heading) x *= factor;
  if (data.hydrostatics) *data.hydrostatics *= factor;
  data.density = density;
  return data;
}

}  // namespace ffrf::hydro
