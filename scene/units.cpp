// Unit table and quantity parsing for scene values (see units.hpp).
#include "scene/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace ffrf::scene {
namespace {

struct Unit {
  std::string_view symbol;
  Dimension dimension;
  double factor;  // SI value of one unit
  bool listed;    // shown in "expected ... (m, mm, km)"; aliases are not
};

// First entry of each dimension is its SI unit.
constexpr std::array kUnits{
    Unit{"", Dimension::ratio, 1.0, false},
    Unit{"%", Dimension::ratio, 0.01, true},
    Unit{"m", Dimension::length, 1.0, true},
    Unit{"mm", Dimension::length, 1e-3, true},
    Unit{"cm", Dimension::length, 1e-2, true},
    Unit{"km", Dimension::length, 1e3, true},
    Unit{"m^2", Dimension::area, 1.0, true},
    Unit{"m2", Dimension::area, 1.0, false},
    Unit{"m²", Dimension::area, 1.0, false},
    Unit{"cm^2", Dimension::area, 1e-4, true},
    Unit{"cm2", Dimension::area, 1e-4, false},
    Unit{"mm^2", Dimension::area, 1e-6, true},
    Unit{"mm2", Dimension::area, 1e-6, false},
    Unit{"m^4", Dimension::second_moment, 1.0, true},
    Unit{"m4", Dimension::second_moment, 1.0, false},
    Unit{"m⁴", Dimension::second_moment, 1.0, false},
    Unit{"cm^4", Dimension::second_moment, 1e-8, true},
    Unit{"cm4", Dimension::second_moment, 1e-8, false},
    Unit{"mm^4", Dimension::second_moment, 1e-12, true},
    Unit{"mm4", Dimension::second_moment, 1e-12, false},
    Unit{"kg", Dimension::mass, 1.0, true},
    Unit{"g", Dimension::mass, 1e-3, true},
    Unit{"t", Dimension::mass, 1e3, true},
    Unit{"s", Dimension::time, 1.0, true},
    Unit{"ms", Dimension::time, 1e-3, true},
    Unit{"min", Dimension::time, 60.0, true},
    Unit{"h", Dimension::time, 3600.0, true},
    Unit{"rad", Dimension::angle, 1.0, true},
    Unit{"deg", Dimension::angle, 3.14159265358979323846 / 180.0, true},
    Unit{"°", Dimension::angle, 3.14159265358979323846 / 180.0, false},
    Unit{"Pa", Dimension::pressure, 1.0, true},
    Unit{"N/m^2", Dimension::pressure, 1.0, false},
    Unit{"N/m2", Dimension::pressure, 1.0, false},
    Unit{"kPa", Dimension::pressure, 1e3, true},
    Unit{"MPa", Dimension::pressure, 1e6, true},
    Unit{"N/mm^2", Dimension::pressure, 1e6, false},
    Unit{"N/mm2", Dimension::pressure, 1e6, false},
    Unit{"GPa", Dimension::pressure, 1e9, true},
    Unit{"kg/m^3", Dimension::density, 1.0, true},
    Unit{"kg/m3", Dimension::density, 1.0, false},
    Unit{"kg/m³", Dimension::density, 1.0, false},
    Unit{"t/m^3", Dimension::density, 1e3, true},
    Unit{"t/m3", Dimension::density, 1e3, false},
    Unit{"g/cm^3", Dimension::density, 1e3, true},
    Unit{"g/cm3", Dimension::density, 1e3, false},
    Unit{"kg/m", Dimension::mass_per_length, 1.0, true},
    Unit{"t/m", Dimension::mass_per_length, 1e3, true},
    Unit{"m/s^2", Dimension::acceleration, 1.0, true},
    Unit{"m/s2", Dimension::acceleration, 1.0, false},
    Unit{"m/s²", Dimension::acceleration, 1.0, false},
    Unit{"N/m", Dimension::stiffness, 1.0, true},
    Unit{"kN/m", Dimension::stiffness, 1e3, true},
    Unit{"MN/m", Dimension::stiffness, 1e6, true},
    Unit{"N/mm", Dimension::stiffness, 1e3, false},
    Unit{"rad/s", Dimension::angular_velocity, 1.0, true},
    Unit{"deg/s", Dimension::angular_velocity, 3.14159265358979323846 / 180.0, true},
    Unit{"rpm", Dimension::angular_velocity, 2.0 * 3.14159265358979323846 / 60.0, true},
    Unit{"N s/m", Dimension::linear_damping, 1.0, true},
    Unit{"kN s/m", Dimension::linear_damping, 1e3, true},
    Unit{"MN s/m", Dimension::linear_damping, 1e6, true},
    Unit{"N m s/rad", Dimension::rotational_damping, 1.0, true},
    Unit{"kN m s/rad", Dimension::rotational_damping, 1e3, true},
    Unit{"MN m s/rad", Dimension::rotational_damping, 1e6, true},
    Unit{"N s^2/m^2", Dimension::quadratic_damping, 1.0, true},
    Unit{"kN s^2/m^2", Dimension::quadratic_damping, 1e3, true},
    Unit{"MN s^2/m^2", Dimension::quadratic_damping, 1e6, true},
    Unit{"N m s^2/rad^2", Dimension::rotational_quadratic_damping, 1.0, true},
    Unit{"kN m s^2/rad^2", Dimension::rotational_quadratic_damping, 1e3, true},
    Unit{"MN m s^2/rad^2", Dimension::rotational_quadratic_damping, 1e6, true},
};

const Unit* find_unit(std::string_view symbol, Dimension dimension) {
  for (const Unit& unit : kUnits) {
    if (unit.symbol == symbol && unit.dimension == dimension) return &unit;
  }
  return nullptr;
}

const Unit* find_any_unit(std::string_view symbol) {
  for (const Unit& unit : kUnits) {
    if (unit.symbol == symbol) return &unit;
  }
  return nullptr;
}

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

}  // namespace

std::string_view si_unit(Dimension dimension) {
  for (const Unit& unit : kUnits) {
    if (unit.dimension == dimension) return unit.symbol;
  }
  return {};
}

std::string_view dimension_name(Dimension dimension) {
  switch (dimension) {
    case Dimension::ratio: return "a dimensionless ratio";
    case Dimension::length: return "a length";
    case Dimension::area: return "an area";
    case Dimension::second_moment: return "a second moment of area";
    case Dimension::mass: return "a mass";
    case Dimension::time: return "a time";
    case Dimension::angle: return "an angle";
    case Dimension::pressure: return "a pressure or modulus";
    case Dimension::density: return "a density";
    case Dimension::mass_per_length: return "a mass per length";
    case Dimension::acceleration: return "an acceleration";
    case Dimension::stiffness: return "a spring stiffness";
    case Dimension::angular_velocity: return "an angular velocity";
    case Dimension::linear_damping: return "a linear damping coefficient (force per velocity)";
    case Dimension::rotational_damping: return "a rotational damping coefficient (moment per angular velocity)";
    case Dimension::quadratic_damping: return "a quadratic damping coefficient (force per velocity squared)";
    case Dimension::rotational_quadratic_damping:
      return "a rotational quadratic damping coefficient (moment per angular velocity squared)";
  }
  return "a quantity";
}

std::string accepted_units(Dimension dimension) {
  std::string list;
  for (const Unit& unit : kUnits) {
    if (unit.dimension != dimension || !unit.listed) continue;
    if (!list.empty()) list += ", ";
    list += unit.symbol;
  }
  return dimension == Dimension::ratio ? (list.empty() ? "a plain number" : "a plain number or " + list) : list;
}

double unit_factor(std::string_view unit, Dimension dimension) {
  const Unit* found = find_unit(unit, dimension);
  if (found == nullptr) {
    throw std::invalid_argument(fmt::format("'{}' is not a unit of {}", unit, dimension_name(dimension)));
  }
  return found->factor;
}

bool unit_required(Dimension dimension) { return dimension == Dimension::angle; }

std::vector<UnitChoice> units_of(Dimension dimension) {
  std::vector<UnitChoice> units;
  for (const Unit& unit : kUnits) {
    if (unit.dimension == dimension && unit.listed) units.push_back({unit.symbol, unit.factor});
  }
  return units;
}

std::optional<WrittenQuantity> split_quantity(std::string_view text) {
  const std::string_view trimmed = trim(text);
  if (trimmed.empty()) return std::nullopt;
  // Optional leading '+', which std::from_chars does not accept.
  const std::string_view number_text = trimmed.front() == '+' ? trimmed.substr(1) : trimmed;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(number_text.data(), number_text.data() + number_text.size(), value);
  if (end == number_text.data() || (ec != std::errc{} && ec != std::errc::result_out_of_range)) return std::nullopt;
  const auto used = static_cast<std::size_t>(end - trimmed.data());
  return WrittenQuantity{std::string(trim(trimmed.substr(0, used))), std::string(trim(trimmed.substr(used)))};
}

QuantityResult check_number(double value, bool allow_infinity) {
  if (std::isnan(value)) return QuantityError{"not a number (NaN)"};
  if (std::isinf(value) && !allow_infinity) return QuantityError{"infinite values are not allowed here"};
  return value;
}

QuantityResult check_bare_number(double value, Dimension dimension, bool allow_infinity) {
  auto checked = check_number(value, allow_infinity);
  if (std::holds_alternative<QuantityError>(checked)) return checked;
  if (unit_required(dimension) && value != 0.0 && std::isfinite(value)) {
    return QuantityError{fmt::format("{} needs its unit: a bare number could be degrees or radians ({})",
                                     dimension_name(dimension), accepted_units(dimension))};
  }
  return checked;
}

QuantityResult parse_quantity(std::string_view text, Dimension dimension, bool allow_infinity) {
  const std::string_view trimmed = trim(text);
  if (trimmed.empty()) return QuantityError{fmt::format("empty value, expected {}", dimension_name(dimension))};
  const std::optional<WrittenQuantity> written = split_quantity(trimmed);
  double value = 0.0;
  if (written) {
    const std::string_view number = written->number.front() == '+' ? std::string_view(written->number).substr(1)
                                                                     : std::string_view(written->number);
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (ec == std::errc::result_out_of_range) {
      return QuantityError{fmt::format("{} is beyond the range of a double-precision number", written->number)};
    }
  }
  if (!written) {
    return QuantityError{fmt::format("expected a number optionally followed by a unit ({}), e.g. \"10 {}\"",
                                     accepted_units(dimension), si_unit(dimension))};
  }
  const std::string_view unit = written->unit;
  if (unit.empty()) return check_bare_number(value, dimension, allow_infinity);  // no unit: SI
  const Unit* found = find_unit(unit, dimension);
  if (found == nullptr) {
    if (const Unit* other = find_any_unit(unit); other != nullptr) {
      return QuantityError{fmt::format("{} is {}, expected {} ({})", unit,
                                       dimension_name(other->dimension), dimension_name(dimension),
                                       accepted_units(dimension))};
    }
    return QuantityError{fmt::format("unknown unit '{}', expected {} ({})", unit, dimension_name(dimension),
                                     accepted_units(dimension))};
  }
  auto checked = check_number(value, allow_infinity);
  if (std::holds_alternative<QuantityError>(checked)) return checked;
  return value * found->factor;
}

}  // namespace ffrf::scene
