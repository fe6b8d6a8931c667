// Radiation memory of the Cummins equation (Cummins 1962; Ogilvie 1964; docs/hydrodynamics.md §3):
//   (M + A∞) ẍ + ∫₀^t K(t − τ) ẋ(τ) dτ + C x = F(t),
//   K(t) = (2/π) ∫₀^∞ B(ω) cos(ωt) dω,
//   A(ω) = A∞ − (1/ω) ∫₀^∞ K(t) sin(ωt) dt,   B(ω) = ∫₀^∞ K(t) cos(ωt) dt.
// From tabulated B(ω_1..ω_N): B is linear between the samples, linear from B(0) = 0 to the first
// sample when ω_1 > 0 (a hull radiates no waves at zero frequency; a table may start at ω = 0
// instead) and beyond ω_N follows the tail
// B_N (ω_N/ω)^n, n fitted by least squares to log|B| of the last `tail_points` samples (n clamped to
// [2, 12]; no tail when those samples change sign or are below 1e-9 of the largest |B_ii|, i.e.
// noise). The tail is integrated on a geometric grid (ratio 1.01) up to Ω where its remaining
// integral is below 1e-9 of ∫B. Every piece is integrated exactly against cos(ωt)
// (linear_fourier.hpp), so the error is the interpolation of B alone: |δK| ≤ (2/π)(Δω²/8)∫|B''|dω.
// K is sampled at t_k = k dt up to the truncation time T_c: given, or the first time after which
// every entry stays below `truncation_tolerance` of sqrt(max|K_ii| max|K_jj|) (scanned to
// `max_time`).
#pragma once

#include <vector>

#include "hydro/planar_coefficients.hpp"

namespace ffrf::hydro {

struct RetardationOptions {
  double time_step = 0.05;               // dt [s]
  double truncation_time = 0.0;          // T_c [s]; 0 = automatic
  double truncation_tolerance = 1e-3;    // automatic T_c criterion
  double max_time = 120.0;               // automatic T_c scan limit [s]
  int tail_points = 5;                   // samples fitted for the high-frequency tail
  bool high_frequency_tail = true;       // false: B = 0 beyond ω_N
};

struct RetardationFunction {
  double time_step = 0.0;
  double truncation_time = 0.0;
  std::vector<PlanarMatrix> kernel;      // K(k dt), k = 0..N, N dt = T_c
  PlanarMatrix tail_exponent = PlanarMatrix::Zero();  // n per entry (0: no tail)
  PlanarMatrix tail_share = PlanarMatrix::Zero();     // tail's share of ∫B (per entry)
  PlanarMatrix infinite_frequency_added_mass = PlanarMatrix::Zero();  // A∞ (from the data)
  double truncated_peak = 0.0;           // max over t ≥ T_c of |K_ij| / sqrt(max|K_ii| max|K_jj|)
  double at(std::size_t k, int i, int j) const { return kernel[k](i, j); }
};

// The model of B_ij(ω) described above, as the nodes of a piecewise-linear function on [0, Ω]
// (B = 0 beyond): the one K(t) transforms, and the Kramers–Kronig estimate of A∞ integrates
// (infinite_frequency.hpp).
struct DampingModel {
  std::vector<double> omega, value;
  double tail_exponent = 0.0, tail_share = 0.0;  // 0: no tail
};
DampingModel damping_model(const PlanarRadiation& radiation, int i, int j, const RetardationOptions& options = {});

// Throws std::invalid_argument for dt ≤ 0, T_c < 0, fewer than 2 frequencies, or no A∞ in the data
// (has_infinite_frequency false: set one from estimate_infinite_frequency_added_mass).
RetardationFunction retardation_function(const PlanarRadiation& radiation, const RetardationOptions& options = {});

// K(t) at any t ≥ 0 from the same model of B (the sampled kernel's source).
PlanarMatrix retardation_at(const PlanarRadiation& radiation, double t, const RetardationOptions& options = {});

// Back-transforms of the sampled kernel (K linear between samples, exact Fourier integrals):
//   B(ω) = ∫₀^{T_c} K cos ωt dt,   A(ω) − A∞ = −(1/ω) ∫₀^{T_c} K sin ωt dt.
PlanarMatrix damping_from_kernel(const RetardationFunction& kernel, double omega);
PlanarMatrix added_mass_from_kernel(const RetardationFunction& kernel, double omega);  // includes A∞

// Ogilvie's relation as a consistency check: A∞ estimated at every tabulated ω as
// A(ω) + (1/ω) ∫ K sin ωt dt. Returns the estimates (per frequency); their spread and their
// difference to the file's A∞ measure how consistent A, B and A∞ are.
std::vector<PlanarMatrix> infinite_frequency_estimates(const PlanarRadiation& radiation, const RetardationFunction& kernel);

}  // namespace ffrf::hydro
