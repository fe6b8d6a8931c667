// Unit conversions and number formats the reports share: degrees per radian, a frequency in hertz
// and a period from an angular frequency, a number in scientific notation ("-" when it is not
// finite), and a wave heading's name.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

#include "hydro/wave_synthesis.hpp"

namespace ffrf::report {

inline constexpr double degrees = 180.0 / std::numbers::pi;  // degrees per radian

inline double hertz(double angular_frequency) { return angular_frequency / (2.0 * std::numbers::pi); }
inline double period_of(double angular_frequency) { return 2.0 * std::numbers::pi / angular_frequency; }
inline std::string sci(double value) { return std::isfinite(value) ? fmt::format("{:.2e}", value) : "-"; }
inline std::string heading_name(hydro::WaveHeading heading) {
  return heading == hydro::WaveHeading::head ? "head" : "following";
}

}  // namespace ffrf::report
