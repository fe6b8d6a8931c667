// Power spectral density of a sampled record by Welch's method (Welch 1967, IEEE Trans. Audio
// Electroacoust. 15): the record (mean removed) is cut into segments of L samples overlapping by a
// fraction, each multiplied by a Hann window w and transformed by FFTW (real-to-complex); the
// one-sided density in angular frequency is
//   S(ω_k) = c_k dt |Σ_j w_j x_j e^{−2πijk/L}|² / (2π Σ_j w_j²),  ω_k = 2πk/(L dt), k = 0..L/2,
// averaged over the segments, c_k = 2 except c_0 = c_{L/2} = 1. Then Σ_k S(ω_k) Δω equals the
// window-weighted mean square (Parseval), ≈ the variance. Units: [x]² s/rad. Resolution Δω = 2π/(L dt);
// each bin scatters like χ² with about 2 × segments degrees of freedom (less with overlap).
// FFTW plans are created under a mutex (FFTW's planner is not thread-safe), executed without it.
#pragma once

#include <cstddef>
#include <vector>

namespace ffrf::hydro {

struct WelchOptions {
  std::size_t segment_length = 0;  // L; 0 = the largest power of two ≤ n/8 (at least 16)
  double overlap = 0.5;            // in [0, 0.9]
};

struct PowerSpectrum {
  std::vector<double> frequency;  // ω_k [rad/s]
  std::vector<double> density;    // S(ω_k) [unit² s/rad]
  std::size_t segments = 0;
  double resolution = 0.0;        // Δω [rad/s]
};

// Throws std::invalid_argument when dt ≤ 0, the record is shorter than 16 samples or the segment,
// or a sample is not finite (index named).
PowerSpectrum welch_spectrum(const std::vector<double>& record, double dt, const WelchOptions& options = {});

// m_n = Σ_k ω_k^n S(ω_k) Δω (trapezoid: half weights at k = 0 and L/2).
double spectral_moment(const PowerSpectrum& spectrum, int order);
double peak_frequency(const PowerSpectrum& spectrum);  // ω of the largest S (parabolic refinement)

}  // namespace ffrf::hydro
