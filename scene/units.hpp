// Physical dimensions and units of scene values. A scene number is in the SI unit of its key; a
// string "value unit" ("120 m", "60 deg", "210 GPa", "2 %") is converted to SI. A unit of the
// wrong dimension, NaN, and infinity (unless the key allows it) are errors with a message that
// names the expected dimension and its units. An angle needs its unit ("60 deg", "1.05 rad"): a
// bare number is ambiguous between degrees and radians, so only 0 may be written without one.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ffrf::scene {

enum class Dimension {
  ratio,            // dimensionless [-]
  length,           // m
  area,             // m^2
  second_moment,    // m^4 (second moment of area)
  mass,             // kg
  time,             // s
  angle,            // rad
  pressure,         // Pa (modulus, stress)
  density,          // kg/m^3
  mass_per_length,  // kg/m
  acceleration,     // m/s^2
  stiffness,        // N/m (translational spring)
  angular_velocity, // rad/s
  linear_damping,   // N s/m (force per velocity)
  rotational_damping,  // N m s/rad (moment per angular velocity)
  quadratic_damping,   // N s^2/m^2 (force per velocity squared)
  rotational_quadratic_damping,  // N m s^2/rad^2 (moment per angular velocity squared)
};

std::string_view si_unit(Dimension dimension);         // "m", "kg/m^3", "" for ratio
std::string_view dimension_name(Dimension dimension);  // "a length", "a mass", ...
std::string accepted_units(Dimension dimension);       // "m, mm, cm, km"

// Factor that converts a value in `unit` into SI, when `unit` is a unit of `dimension`.
double unit_factor(std::string_view unit, Dimension dimension);  // throws std::invalid_argument

// Whether a bare number is refused for this dimension (angles: degrees or radians?); 0 is allowed.
bool unit_required(Dimension dimension);

struct UnitChoice {
  std::string_view symbol;  // "GPa"
  double factor;            // SI value of one unit
};
// The listed units of a dimension, SI first ("Pa", "kPa", "MPa", "GPa").
std::vector<UnitChoice> units_of(Dimension dimension);

// "210 GPa" -> {"210", "GPa"}, "3.5" -> {"3.5", ""}: the number as written and its unit (trimmed);
// nothing when the text does not start with a number.
struct WrittenQuantity {
  std::string number;
  std::string unit;
};
std::optional<WrittenQuantity> split_quantity(std::string_view text);

// Result of parsing one quantity: the SI value or the reason it was rejected.
struct QuantityError {
  std::string message;
};
using QuantityResult = std::variant<double, QuantityError>;

// `text` is "value" or "value unit" (whitespace between them optional); an empty unit means SI.
QuantityResult parse_quantity(std::string_view text, Dimension dimension, bool allow_infinity);
// A plain number (already SI): rejects NaN and, unless allowed, infinity.
QuantityResult check_number(double value, bool allow_infinity);
// A number written without a unit for a key of `dimension`: check_number, and refused (unless 0)
// when the dimension needs its unit.
QuantityResult check_bare_number(double value, Dimension dimension, bool allow_infinity);

}  // namespace ffrf::scene
