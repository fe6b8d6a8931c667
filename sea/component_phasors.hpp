// The phasors e^{k_i z − i δ ω_i t}, i = 0 … N−1 in order, of a wave field's components at one complex
// point z (z = y + i x: depth factor e^{k y} and phase k x; z = i x for the elevation; any z for the
// closed-form pressure integral's e^{λ h}) and time t (t = 0: no time factor). Multiplied by the
// complex amplitudes a_i e^{iφ_i} (WaveField::complex_amplitudes) they are the terms of every
// elevation, slope and pressure sum: a_i e^{k_i y} e^{iθ_i}, θ_i = k_i x − δ ω_i t + φ_i.
//
// Off a harmonic grid (arbitrary components, finite depth) each phasor is the direct formula: one
// exponential, sine and cosine. On a harmonic grid in deep water (WaveField::harmonic_grid():
// ω_i = n Δω, k_i = n² κ with κ = Δω²/g, n = n0 + i) the exponent κ z n² − i δ Δω t n is quadratic
// in n, and the phasors follow by recurrence, two complex products per component:
//   P_{n+1} = P_n R_n,   R_n = e^{κ z (2n + 1) − i δ Δω t},   R_{n+1} = R_n e^{2κz}.
// Round-off: the rounding of e^{2κz} is raised to the power j in R after j steps and summed again in
// P, so P drifts by about j²/2 ulp; every `reseed_interval`-th phasor is therefore taken from the
// direct formula (relative error ≤ 64²/2 ulp ≈ 5e-13 between seeds, ~|k z| ulp at a seed, as the
// direct formula itself). The seeds use the field's own ω_i and k_i, so the recurrence never drifts
// from the component list over a long record. docs/hydrodynamics.md §7 ("Cost").
#pragma once

#include <cmath>
#include <complex>
#include <cstddef>

#include "sea/wave_field.hpp"

namespace ffrf::sea {

using Complex = std::complex<double>;

// a · b written out (std::complex's operator* checks every product for inf/NaN).
inline Complex times(Complex a, Complex b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

class ComponentPhasors {
 public:
  static constexpr std::size_t reseed_interval = 64;

  ComponentPhasors(const WaveField& wave, Complex z, double t)
      : wave_(wave), z_(z), time_phase_(-wave.direction() * t), grid_(wave.harmonic_grid()) {
    if (grid_.active) quotient_ = exponential(2.0 * grid_.wave_number_step * z_);
  }

  // The phasor of the next component (the first call gives component 0). At most N calls.
  Complex next() {
    if (index_ == next_seed_) seed();
    const Complex out = value_;
    value_ = times(value_, ratio_);
    ratio_ = times(ratio_, quotient_);
    ++index_;
    return out;
  }

 private:
  static Complex exponential(Complex w) {
    const double magnitude = w.real() == 0.0 ? 1.0 : std::exp(w.real());
    return {magnitude * std::cos(w.imag()), magnitude * std::sin(w.imag())};
  }

  // The direct formula for the current component; on the grid also the ratio to the next one.
  void seed() {
    const WaveComponent& c = wave_.components()[index_];
    value_ = exponential(c.wave_number * z_ + Complex(0.0, time_phase_ * c.angular_frequency));
    if (!grid_.active) {
      next_seed_ = index_ + 1;
      return;
    }
    const double twice_n_plus_1 = 2.0 * (grid_.first_harmonic + static_cast<double>(index_)) + 1.0;
    ratio_ = exponential(twice_n_plus_1 * grid_.wave_number_step * z_ + Complex(0.0, time_phase_ * grid_.frequency_step));
    next_seed_ = index_ + reseed_interval;
  }

  const WaveField& wave_;
  Complex z_;
  double time_phase_;  // −δ t
  const WaveField::HarmonicGrid& grid_;
  Complex value_, ratio_{1.0, 0.0}, quotient_{1.0, 0.0};
  std::size_t index_ = 0, next_seed_ = 0;
};

}  // namespace ffrf::sea
