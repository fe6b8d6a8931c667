// Constant radiation coefficients from a table (see planar_coefficients.hpp).
#include "hydro/planar_coefficients.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ffrf::hydro {

ConstantRadiation radiation_at(const PlanarRadiation& r, double omega) {
  if (r.frequency.empty()) throw std::invalid_argument("radiation_at: the coefficient table is empty");
  if (!std::isfinite(omega) || omega < 0.0)
    throw std::invalid_argument(fmt::format("radiation_at: frequency {} rad/s is invalid; valid range >= 0", omega));
  const auto& w = r.frequency;
  if (omega <= w.front()) return {r.added_mass.front(), r.damping.front()};
  if (omega >= w.back()) return {r.added_mass.back(), r.damping.back()};
  const auto i = static_cast<std::size_t>(std::upper_bound(w.begin(), w.end(), omega) - w.begin());
  const double t = (omega - w[i - 1]) / (w[i] - w[i - 1]);
  return {(1.0 - t) * r.added_mass[i - 1] + t * r.added_mass[i], (1.0 - t) * r.damping[i - 1] + t * r.damping[i]};
}

}  // namespace ffrf::hydro
