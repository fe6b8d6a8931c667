// Irregular long-crested sea as a sum of regular components (docs/hydrodynamics.md §2.2):
//   η(x = 0, t) = Σ_n a_n cos(ω_n t + φ_n)
// at the reference point; a component travelling along +x (following sea) is a_n cos(ω_n t − k_n x
// + φ_n), along −x (head sea) a_n cos(ω_n t + k_n x + φ_n) — wave numbers, kinematics and pressure
// belong to the consumer (the coupling wave field); this file knows only (ω, a, φ).
// Synthesis from a spectrum: ω_n = n Δω (whole multiples, so the sea repeats exactly after
// T_repeat = 2π/Δω), n over the band that holds all but `tail_fraction` of m0; deterministic
// amplitudes a_n = sqrt(2 S(ω_n) Δω) or Rayleigh amplitudes a_n = sqrt(2 S(ω_n) Δω E_n) with E_n
// unit exponential; phases φ_n = 2π U_n. U_n, E_n are draws 2n and 2n + 1 of the stream
// (seed, realisation) (random_stream.hpp): a component's phase depends on its harmonic number n
// only, not on the band, the thread or the order of computation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hydro/wave_spectrum.hpp"

namespace ffrf::hydro {

enum class WaveHeading { following, head };  // travels +x / −x (ffrf: the boom overhangs the bow at +x)

struct WaveComponents {
  std::vector<double> frequency;  // ω_n [rad/s] > 0
  std::vector<double> amplitude;  // a_n [m] ≥ 0
  std::vector<double> phase;      // φ_n [rad]
  WaveHeading heading = WaveHeading::following;
  double frequency_step = 0.0;    // Δω [rad/s] when the components lie on a grid n Δω, else 0

  std::size_t size() const { return frequency.size(); }
  double variance() const;        // Σ a_n² / 2: the variance of η over a whole repeat period
  double repeat_period() const;   // 2π/Δω, +inf when frequency_step = 0
};

// User components. Throws std::invalid_argument (index, value, valid range) on unequal sizes, an
// empty set, ω ≤ 0, a < 0 or non-finite values. frequency_step: give Δω when ω_n = n Δω (checked to
// 1e-9 relative), or 0.
WaveComponents user_components(std::vector<double> frequency, std::vector<double> amplitude,
                               std::vector<double> phase, WaveHeading heading, double frequency_step = 0.0);

struct SynthesisOptions {
  double record_length = 10800.0;  // [s] the simulated duration the sea must not repeat within
  double frequency_step = 0.0;     // Δω [rad/s]; 0 = 2π / record_length (the largest that does not repeat)
  double omega_min = 0.0;          // band [rad/s]; both 0 = energy_band(spectrum, tail_fraction)
  double omega_max = 0.0;
  double tail_fraction = 1e-3;     // of m0 left outside an automatic band
  std::uint64_t seed = 0;
  std::uint64_t realisation = 0;
  bool random_amplitudes = false;  // Rayleigh amplitudes (a Gaussian sea also in its energy)
  WaveHeading heading = WaveHeading::following;
};

struct SeaRealisation {
  WaveComponents components;
  double spectrum_m0 = 0.0;          // ∫ S dω of the spectrum (whole axis)
  double band_m0 = 0.0;              // Σ S(ω_n) Δω: the expected variance of the synthesis
  double repeat_period = 0.0;        // 2π/Δω [s]
  bool repeats_within_record = false;
  std::string warning;               // non-empty when the sea repeats within the record
};

// Throws std::invalid_argument naming the option, its value and the valid range (record_length > 0,
// Δω > 0, 0 ≤ ω_min < ω_max, tail fraction in (0, 0.5), at most 2e6 components).
SeaRealisation synthesize(const WaveSpectrum& spectrum, const SynthesisOptions& options);

// η at the reference point (x = 0) by direct superposition.
double elevation(const WaveComponents& components, double t);
// η(t0 + k dt), k = 0..count−1. Components on a harmonic grid whose period 2π/Δω is a whole number N
// of steps dt: one FFT of length N (bins a_n e^{i(ω_n t0 + φ_n)} at n mod N), O(N log N) instead of
// O(components × count); otherwise by rotating phasors (re-anchored every 1024 samples: error ~1e-13 a).
std::vector<double> elevation_record(const WaveComponents& components, double t0, double dt, std::size_t count);

}  // namespace ffrf::hydro
