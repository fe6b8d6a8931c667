// Whether a sea state can exist: its significant steepness Sp = Hs / λp = 2π Hs / (g Tp²), with λp
// the deep-water wavelength of the peak period, against the limit DNV-RP-C205 §3.5.5 sets for it:
// 1/15 for Tp ≤ 8 s, 1/25 for Tp ≥ 15 s, linear in Tp between. A steeper sea breaks: it is not a
// sea state a lift can meet, whatever the crane.
#pragma once

namespace ffrf::hydro {

struct SeaSteepness {
  double steepness = 0.0;        // Sp = Hs / λp [-]
  double limit = 0.0;            // DNV-RP-C205's largest Sp for this Tp [-]
  double peak_wavelength = 0.0;  // λp = g Tp² / (2π) [m]
  bool breaking() const { return steepness > limit; }
  double largest_height() const { return limit * peak_wavelength; }  // the steepest Hs at this Tp [m]
};

// Throws std::invalid_argument unless Hs ≥ 0, Tp > 0 and g > 0 (finite).
SeaSteepness sea_steepness(double significant_height, double peak_period, double gravity);

}  // namespace ffrf::hydro
