// Regular linear (Airy) wave travelling along ±x, deep or finite water depth, ramped in smoothly
// over the first periods: surface elevation ζ(x, t) and the total pressure p(x, y, t) of the
// incident wave with its hydrostatic part (y up, still water level y = 0):
//   ζ = ζ_a r(t) cos(k x − dir·ω t)   (crests travel +x for dir = +1, −x for dir = −1),
//   p = ρ g (−y + ζ f(y))   for y ≤ 0 and y ≤ ζ, with f = e^{k y} (deep) or
//       cosh(k (y + d)) / cosh(k d) (depth d),
//   p = ρ g (ζ − y)         for 0 < y ≤ ζ (hydrostatic extension up to the crest),
//   p = 0                   above ζ (also in a trough, where linear theory would give p < 0).
// Dispersion ω² = g k tanh(k d) (safeguarded Newton iteration to machine precision; ω² = g k in
// deep water). Reference: Faltinsen, Sea Loads on Ships and Offshore Structures (1990), §2.
#pragma once

#include <limits>

namespace ffrf::coupling {

struct AiryWave {
  double amplitude = 0.0;          // ζ_a = H / 2 [m]
  double angular_frequency = 0.0;  // ω [rad/s]
  double wave_number = 0.0;        // k [1/m]
  double direction = 1.0;          // +1 travels +x (following sea), −1 travels −x (head sea)
  double ramp_duration = 0.0;      // [s]; ≤ 0 = no ramp (full amplitude from t = −∞)
  double depth = std::numeric_limits<double>::infinity();  // [m]; +inf = deep water
  double gravity = 9.81;           // [m/s²]

  // Wave of height H (crest to trough) and period T; ramp over ramp_periods · T; depth = +inf for
  // deep water. Throws std::invalid_argument on H < 0, T ≤ 0, direction ∉ {−1, +1},
  // ramp_periods < 0, depth ≤ 0 or NaN, gravity ≤ 0.
  static AiryWave from_height_period(double height, double period, double direction, double ramp_periods,
                                     double depth, double gravity);
  // Solves ω² = g k tanh(k d) for k (d = +inf: k = ω² / g). Throws std::invalid_argument on bad input.
  static double wave_number_from_dispersion(double angular_frequency, double depth, double gravity);

  double ramp(double t) const;                 // 0 for t ≤ 0, ½(1 − cos(π t / t_r)), 1 for t ≥ t_r: C¹
  double elevation(double x, double t) const;  // ζ [m]
  // Total pressure [Pa] (≥ 0 for y ≥ −d; the formula is only meaningful above the sea bed).
  double pressure(double x, double y, double t, double density) const;
  double depth_attenuation(double y) const;    // f(y) for y ≤ 0: e^{k y} or cosh(k(y + d)) / cosh(k d)
  double wavelength() const;                   // 2π / k [m] (+inf when k = 0)
  double period() const;                       // 2π / ω [s] (+inf when ω = 0)
};

}  // namespace ffrf::coupling
