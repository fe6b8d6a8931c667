// The significant steepness of a sea state and DNV-RP-C205's breaking limit (see sea_steepness.hpp).
#include "hydro/sea_steepness.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ffrf::hydro {

SeaSteepness sea_steepness(double significant_height, double peak_period, double gravity) {
  if (!(std::isfinite(significant_height) && significant_height >= 0.0 && std::isfinite(peak_period) &&
        peak_period > 0.0 && std::isfinite(gravity) && gravity > 0.0)) {
    throw std::invalid_argument(fmt::format("sea steepness: Hs = {} m, Tp = {} s, g = {} m/s^2 (valid: Hs >= 0, Tp > 0, g > 0)",
                                            significant_height, peak_period, gravity));
  }
  const double tp = peak_period;
  SeaSteepness s;
  s.peak_wavelength = gravity * tp * tp / (2.0 * std::numbers::pi);
  s.limit = tp <= 8.0 ? 1.0 / 15.0 : (tp >= 15.0 ? 1.0 / 25.0 : 1.0 / 15.0 + (tp - 8.0) / 7.0 * (1.0 / 25.0 - 1.0 / 15.0));
  s.steepness = significant_height / s.peak_wavelength;
  return s;
}

}  // namespace ffrf::hydro
