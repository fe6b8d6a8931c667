// Constants shared by the sea-state, spectrum and BEM files of hydro/.
#pragma once

#include <numbers>

namespace ffrf::hydro {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;  // rad per cycle: ω = 2π/T, Δω = 2π/record

}  // namespace ffrf::hydro
