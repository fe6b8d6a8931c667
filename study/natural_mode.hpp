// One natural mode of the crane linearised about its static equilibrium (study/rao.hpp finds them):
// from an eigenvalue λ of the first-order form of M ẍ + C ẋ + K x = 0 (or a root of the memory hull's
// det D(s)), ω_n = |λ| and ζ = −Re λ / |λ|. A lightly damped mode's resonance peak lies at
//   ω_peak ≈ ω_n √(1 − 2ζ²),  height ≈ 1 / (2ζ √(1 − ζ²)) × the static response,
// and its half-power band is ω_n √(1 − 2ζ² ∓ 2ζ √(1 − ζ²)) (exact for one degree of freedom).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace ffrf::study {

struct NaturalMode {
  double angular_frequency = 0.0;  // |λ| [rad/s]
  double damping_ratio = 0.0;      // −Re λ / |λ| [-]
  std::string dominant;            // the coordinate with the largest share of the mode's kinetic energy ("hull heave", "boom")
  // A memory hull's mode that Newton could not refine (natural_modes with an impedance): why — the
  // mode is then the constant system's root, not a root of det D(s). Empty: refined, or not asked to be.
  std::string unrefined;
  double period() const { return 2.0 * std::numbers::pi / angular_frequency; }  // 2π / ω_n [s]
  // A resonance peak exists (0 < ζ < 1/√2): the one-degree-of-freedom amplification has a maximum.
  bool resonant() const { return damping_ratio > 0.0 && 2.0 * damping_ratio * damping_ratio < 1.0; }
  // ω_n √(1 − 2ζ²) [rad/s]: where a one-degree-of-freedom displacement response peaks (resonant() only).
  double peak_frequency() const { return angular_frequency * std::sqrt(1.0 - 2.0 * damping_ratio * damping_ratio); }
  // Whether ω lies within the half-power band (resonant() only; false otherwise).
  bool in_half_power_band(double omega) const {
    if (!resonant()) return false;
    const double z = damping_ratio, centre = 1.0 - 2.0 * z * z, spread = 2.0 * z * std::sqrt(1.0 - z * z);
    const double lower = angular_frequency * std::sqrt(std::max(0.0, centre - spread));
    return omega >= lower && omega <= angular_frequency * std::sqrt(centre + spread);
  }
};

}  // namespace ffrf::study
