// Long-crested linear waves travelling along ±x as a superposition of Airy components, deep or
// finite water depth, ramped in smoothly: surface elevation, total incident pressure (hydrostatic
// part included) and particle kinematics (y up, still water level y = 0). Component i has
// amplitude a_i, angular frequency ω_i, wave number k_i (dispersion ω² = g k tanh(k d)) and phase φ_i:
//   ζ(x, t) = r(t) Σ a_i cos(θ_i),   θ_i = k_i x − δ ω_i t + φ_i   (δ = +1: travels +x, −1: −x),
//   p = ρ g (−y + r Σ a_i cos(θ_i) f_i(y))   for y ≤ 0 and y ≤ ζ,
//       f_i = e^{k_i y} (deep) or cosh(k_i (y + d)) / cosh(k_i d) (depth d),
//   p = ρ g (ζ − y)   for 0 < y ≤ ζ (the total elevation's hydrostatic extension up to the crest),
//   p = 0             above ζ (also in a trough, where linear theory would give p < 0).
// Velocity (u, v) = r Σ a_i ω_i (δ cos θ_i g_i(y), sin θ_i h_i(y)), g_i = cosh(k(y+d))/sinh(kd),
// h_i = sinh(k(y+d))/sinh(kd) (deep: both e^{ky}), held at their y = 0 values above still water.
// The regular Airy wave is the one-component field. Cost: linear in the component count.
// Reference: Faltinsen, Sea Loads on Ships and Offshore Structures (1990), §2; docs/theory.md §6.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <limits>
#include <vector>

namespace ffrf::sea {

struct WaveComponent {
  double amplitude = 0.0;          // a_i [m]
  double angular_frequency = 0.0;  // ω_i [rad/s]
  double wave_number = 0.0;        // k_i [1/m], from the dispersion relation
  double phase = 0.0;              // φ_i [rad]
};

// One component as given by a spectrum: ω, amplitude, phase (the wave number follows from ω).
struct ComponentSpec {
  double angular_frequency;  // [rad/s] (≥ 0)
  double amplitude;          // [m] (≥ 0)
  double phase = 0.0;        // [rad]
};

class WaveField {
 public:
  WaveField() = default;  // no components: calm water

  // Regular wave of height H (crest to trough) and period T, zero phase (a crest at x = 0 at t = 0);
  // ramp over ramp_periods · T; depth = +inf for deep water. Throws std::invalid_argument on H < 0,
  // T ≤ 0, direction ∉ {−1, +1}, ramp_periods < 0, depth ≤ 0 or NaN, gravity ≤ 0 (value named).
  static WaveField regular(double height, double period, double direction, double ramp_periods, double depth,
                           double gravity);
  // Superposition of the given components (wave numbers from the dispersion relation), ramped over
  // ramp_duration [s] (≤ 0: none). Throws std::invalid_argument naming the component and value.
  static WaveField from_components(const std::vector<ComponentSpec>& components, double direction,
                                   double ramp_duration, double depth, double gravity);
  // Solves ω² = g k tanh(k d) for k (d = +inf: k = ω² / g). Throws std::invalid_argument on bad input.
  static double wave_number_from_dispersion(double angular_frequency, double depth, double gravity);

  const std::vector<WaveComponent>& components() const { return components_; }
  double direction() const { return direction_; }
  double ramp_duration() const { return ramp_duration_; }
  double depth() const { return depth_; }
  bool deep() const { return depth_ == std::numeric_limits<double>::infinity(); }
  double gravity() const { return gravity_; }

  double ramp(double t) const;                 // 0 for t ≤ 0, ½(1 − cos(π t / t_r)), 1 for t ≥ t_r: C¹
  double elevation(double x, double t) const;  // ζ [m]
  double elevation_slope(double x, double t) const;  // ∂ζ/∂x [-]
  // Bounds over all x at time t: |ζ| ≤ r Σ a_i, |∂ζ/∂x| ≤ r Σ a_i k_i, |∂²ζ/∂x²| ≤ r Σ a_i k_i²,
  // |∂³ζ/∂x³| ≤ r Σ a_i k_i³.
  double elevation_bound(double t) const { return ramp(t) * amplitude_sum_; }
  double slope_bound(double t) const { return ramp(t) * slope_sum_; }
  double curvature_bound(double t) const { return ramp(t) * curvature_sum_; }
  double third_derivative_bound(double t) const { return ramp(t) * third_derivative_sum_; }
  double max_wave_number() const { return max_wave_number_; }  // the largest k_i [1/m] (0: calm)
  // a_i e^{iφ_i}, the time-independent factor of every component sum.
  const std::vector<std::complex<double>>& complex_amplitudes() const { return complex_amplitudes_; }

  // Components on whole multiples of one frequency step, ω_i = (n0 + i) Δω for i = 0 … N−1 (N ≥ 2,
  // as hydro::synthesize makes them; checked to 4 ulp), in deep water, so k_i = (n0 + i)² Δω²/g:
  // sums over them run by recurrence (sea/component_phasors.hpp). active = false otherwise.
  struct HarmonicGrid {
    bool active = false;
    double first_harmonic = 0.0;    // n0
    double frequency_step = 0.0;    // Δω [rad/s]
    double wave_number_step = 0.0;  // Δω²/g [1/m]
  };
  const HarmonicGrid& harmonic_grid() const { return harmonic_grid_; }
  // The same field with its sums taken component by component by the direct formula (the reference
  // for the recurrence: tests, benchmarks).
  WaveField with_direct_sums() const {
    WaveField copy = *this;
    copy.harmonic_grid_ = HarmonicGrid{};
    return copy;
  }
  // Total pressure [Pa] (the formula is only meaningful above the sea bed).
  double pressure(double x, double y, double t, double density) const;
  // f_i(y) of component i for y ≤ 0: e^{k y} or cosh(k(y + d)) / cosh(k d).
  double depth_attenuation(const WaveComponent& component, double y) const;
  // Particle velocity and (local) acceleration ∂/∂t of the velocity at (x, y) [m/s, m/s²]; the ramp
  // factor multiplies both (its own rate is left out: the field is a linear-wave solution once ramped in).
  Eigen::Vector2d velocity(double x, double y, double t) const;
  Eigen::Vector2d acceleration(double x, double y, double t) const;

 private:
  std::vector<WaveComponent> components_;
  double direction_ = 1.0;      // +1 travels +x (following sea), −1 travels −x (head sea)
  double ramp_duration_ = 0.0;  // [s]; ≤ 0 = no ramp (full amplitude from t = −∞)
  double depth_ = std::numeric_limits<double>::infinity();  // [m]; +inf = deep water
  double gravity_ = 9.81;       // [m/s²]
  double amplitude_sum_ = 0.0, slope_sum_ = 0.0, curvature_sum_ = 0.0, third_derivative_sum_ = 0.0;
  double max_wave_number_ = 0.0;
  std::vector<std::complex<double>> complex_amplitudes_;
  HarmonicGrid harmonic_grid_;
};

}  // namespace ffrf::sea
