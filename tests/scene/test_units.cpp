// Units of scene values: SI numbers, "value unit" strings, wrong dimensions, NaN and infinity.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/units.hpp"

namespace ffrf::scene {
namespace {

double value_of(std::string_view text, Dimension dimension, bool allow_infinity = false) {
  const QuantityResult result = parse_quantity(text, dimension, allow_infinity);
  if (const auto* error = std::get_if<QuantityError>(&result)) ADD_FAILURE() << text << ": " << error->message;
  return std::holds_alternative<double>(result) ? std::get<double>(result) : std::nan("");
}

std::string error_of(std::string_view text, Dimension dimension, bool allow_infinity = false) {
  const QuantityResult result = parse_quantity(text, dimension, allow_infinity);
  if (const auto* error = std::get_if<QuantityError>(&result)) return error->message;
  ADD_FAILURE() << text << " was accepted";
  return {};
}

TEST(Units, ConvertsToSI) {
  EXPECT_DOUBLE_EQ(value_of("120 m", Dimension::length), 120.0);
  EXPECT_DOUBLE_EQ(value_of("120m", Dimension::length), 120.0);
  EXPECT_DOUBLE_EQ(value_of("250 mm", Dimension::length), 0.25);
  EXPECT_DOUBLE_EQ(value_of("60 deg", Dimension::angle), std::numbers::pi / 3.0);
  EXPECT_DOUBLE_EQ(value_of("12600 t", Dimension::mass), 12.6e6);
  EXPECT_DOUBLE_EQ(value_of("2.1e11 Pa", Dimension::pressure), 2.1e11);
  EXPECT_DOUBLE_EQ(value_of("210 GPa", Dimension::pressure), 2.1e11);
  EXPECT_DOUBLE_EQ(value_of("10 s", Dimension::time), 10.0);
  EXPECT_DOUBLE_EQ(value_of("2 min", Dimension::time), 120.0);
  EXPECT_DOUBLE_EQ(value_of("1.27 m^2", Dimension::area), 1.27);
  EXPECT_DOUBLE_EQ(value_of("8333 cm^4", Dimension::second_moment), 8.333e-5);
  EXPECT_DOUBLE_EQ(value_of("7.85 t/m^3", Dimension::density), 7850.0);
  EXPECT_DOUBLE_EQ(value_of("10 t/m", Dimension::mass_per_length), 1e4);
  EXPECT_DOUBLE_EQ(value_of("500 kN/m", Dimension::stiffness), 5e5);
  EXPECT_DOUBLE_EQ(value_of("2 %", Dimension::ratio), 0.02);
  EXPECT_DOUBLE_EQ(value_of("+3.5", Dimension::length), 3.5);  // no unit: SI
}

TEST(Units, WrongDimensionNamesBoth) {
  EXPECT_EQ(error_of("120 kg", Dimension::length), "kg is a mass, expected a length (m, mm, cm, km)");
  EXPECT_NE(error_of("60 m", Dimension::angle).find("expected an angle (rad, deg)"), std::string::npos);
}

TEST(Units, RejectsUnknownUnitsAndGarbage) {
  EXPECT_NE(error_of("3 furlongs", Dimension::length).find("unknown unit 'furlongs'"), std::string::npos);
  EXPECT_NE(error_of("long", Dimension::length).find("expected a number"), std::string::npos);
  EXPECT_NE(error_of("", Dimension::length).find("empty"), std::string::npos);
}

TEST(Units, RejectsNaNAndInfinityUnlessAllowed) {
  EXPECT_NE(error_of("nan m", Dimension::length).find("NaN"), std::string::npos);
  EXPECT_NE(error_of("inf m", Dimension::length).find("infinite"), std::string::npos);
  EXPECT_TRUE(std::isinf(value_of("inf", Dimension::length, true)));
  EXPECT_TRUE(std::holds_alternative<QuantityError>(check_number(std::nan(""), true)));
  EXPECT_TRUE(std::holds_alternative<QuantityError>(check_number(INFINITY, false)));
  EXPECT_TRUE(std::holds_alternative<double>(check_number(INFINITY, true)));
}

TEST(Units, UnitFactorThrowsForWrongDimension) {
  EXPECT_DOUBLE_EQ(unit_factor("t", Dimension::mass), 1e3);
  EXPECT_THROW((void)unit_factor("t", Dimension::length), std::invalid_argument);
}

}  // namespace
}  // namespace ffrf::scene
