// The incident sea of one record evaluated once, so that a hull load costs what the hull costs and
// not what the sea's thousands of components cost. In deep water the dynamic pressure and the
// elevation are real parts of one function analytic in z = y + i x (y up, x along the wave):
//   F(z, t) = Σ_n A_n e^{k_n z} e^{−iδω_n t},   A_n = a_n e^{iφ_n},
//   p_dynamic/(ρg) = r(t) Re F(y + i x, t)   (y ≤ 0),    ζ(x, t) = r(t) Re F(i x, t),
// with the antiderivatives G = ∫F dz = Σ A_n e^{k_n z}/k_n … and H = ∫G dz = Σ A_n e^{k_n z}/k_n² …,
// so the pressure integral along a straight wetted piece from z0 to z1 (direction w, z = z0 + u w) is
//   ∫₀ʰ F du = (G(z1) − G(z0))/w,   ∫₀ʰ u F du = h G(z1)/w − (H(z1) − H(z0))/w²:
// a hull load needs F, G and H at a few points only (corners, waterline and still-water crossings).
// Around each patch centre c (a disc of radius ρ covering where those points can lie: a hull side
// from below the keel to the surface, with a motion margin) H is a Taylor polynomial in
// w = (z − c)/ρ of degree M + 2, whose coefficients are harmonic sums in t:
//   H(z, t) = ρ² Σ_m η_m(t) w^m,   η_m = Σ_n A_n e^{k_n c} (k_n ρ)^{m−2}/m! e^{−iδω_n t},
// recorded once per record by FFT and quintic Hermite interpolation (hydro/harmonic_record.hpp).
// Truncation: for |z − c| ≤ ρ the error of F is at most Σ_n |A_n| e^{k_n Re c} R_M(k_n ρ),
// R_M(x) = Σ_{m>M} x^m/m! (that of G at most ρ times it, of H ρ² times it); M is the smallest
// degree that keeps it below a quarter of the tolerance. Time interpolation: measured at every
// segment midpoint. Both are stated with the record. Along still water over the hull's whole x range
// [x_min, x_max] (where the keel's and the deck's waterline crossings lie, outside the patches) the
// elevation is also recorded as a Chebyshev series in x̂ = (x − x_c)/(L/2):
//   ζ(x, t) = Σ_d c_d(t) T_d(x̂),   c_d = Re Σ_n A_n e^{ik_n x_c} ε_d i^d J_d(k_n L/2) e^{−iδω_n t}
// (Jacobi–Anger: e^{ia x̂} = J_0(a) + 2 Σ_{d≥1} i^d J_d(a) T_d(x̂); ε_0 = 1, ε_d = 2), truncated where
// Σ_n |A_n| Σ_{d>D} 2|J_d(k_n L/2)| falls below a quarter of the tolerance; its x-derivatives and
// antiderivatives are Chebyshev series too (real coefficients: recorded two to a complex channel).
// Elevation and its x-derivative bounds over [x_min, x_max]: sampled on a grid
// by FFT over the record, kept per window of `bound_window` seconds (a keel that the record's
// deepest trough might reach is still certainly wet in the calmer minutes), with a stated margin
// for the values between samples.
// Needs deep water and components on a harmonic grid (ω_n = n Δω); otherwise the exact sums are the
// only path (sea/wave_field.hpp). Reference: docs/hydrodynamics.md ("The sea evaluated once").
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sea/incident_wave_record_stats.hpp"
#include "sea/wave_field.hpp"
#include "hydro/harmonic_record.hpp"

namespace ffrf::sea {

// A disc of the (x, y) plane in which F, G and H are recorded: centre (x, y) and radius [m].
struct WavePatch {
  double x = 0.0, y = 0.0, radius = 0.0;
};

struct IncidentWaveRecordOptions {
  double duration = 0.0;        // [s] the record: t ∈ [0, duration]
  double tolerance = 1e-6;      // [m] largest error of F (elevation units) inside the patches
  double x_min = 0.0, x_max = 0.0;  // [m] the x range the hull can reach (elevation and slope bounds)
  std::size_t memory_limit = std::size_t{4} << 30;  // [bytes] refuse above this (std::length_error)
};

// The polynomials of every patch at one time t (filled by IncidentWaveRecord::at; reused across
// calls: sized once, then no allocation).
struct WavePolynomials {
  std::vector<std::complex<double>> elevation;  // f̂_j = F Taylor coefficients × ρ^j, per patch (M + 1 each)
  std::vector<std::complex<double>> potential;  // η_m, per patch (M + 3 each), then the line's channels
  // Chebyshev coefficients in x̂ along still water, ramp included: ζ, dζ/dx̂, d²ζ/dx̂², ∫ζ dx̂, ∫∫ζ dx̂².
  std::vector<double> line, line_rate, line_curvature, line_integral, line_second_integral;
  double ramp = 0.0;
  double time = 0.0;
};

class IncidentWaveRecord {
 public:
  // std::nullopt with `why` set when the field has no harmonic grid, is not deep water, or has a
  // component of zero frequency. Throws std::invalid_argument on bad options (named), and
  // std::length_error when the record would exceed the memory limit (size in the message).
  static std::optional<IncidentWaveRecord> build(const WaveField& wave, const std::vector<WavePatch>& patches,
                                                 const IncidentWaveRecordOptions& options, std::string* why = nullptr);
  // Bytes the record would take, without building it (the same checks as build).
  static std::size_t predicted_memory(const WaveField& wave, const std::vector<WavePatch>& patches,
                                      const IncidentWaveRecordOptions& options);

  const IncidentWaveRecordStats& stats() const { return stats_; }
  const std::vector<WavePatch>& patches() const { return patches_; }
  double duration() const { return record_.duration(); }  // +inf: one whole period recorded, read periodically
  double x_min() const { return x_min_; }
  double x_max() const { return x_max_; }
  // |ζ| and |∂ζ/∂x| over the x range in the bound window holding t, times the ramp r(t).
  double elevation_bound(double t, double ramp) const { return ramp * window_bound(window_elevation_, t); }
  double slope_bound(double t, double ramp) const { return ramp * window_bound(window_slope_, t); }
  double curvature_bound(double t, double ramp) const { return ramp * window_bound(window_curvature_, t); }
  double third_derivative_bound(double t, double ramp) const { return ramp * window_bound(window_third_, t); }
  double max_wave_number() const { return max_wave_number_; }

  // The polynomials at t ∈ [0, duration] (the ramp of the wave field included in `ramp`).
  void at(double t, double ramp, WavePolynomials& out) const;

  // The patch holding (x, y), or −1.
  int patch_of(double x, double y) const;
  // r Re-less values at z = y + i x in patch p: F and dF/dz; G and H. Not ramped.
  void elevation_terms(const WavePolynomials& p, int patch, double x, double y, std::complex<double>& f,
                       std::complex<double>& f_rate) const;
  void antiderivatives(const WavePolynomials& p, int patch, double x, double y, std::complex<double>& g,
                       std::complex<double>& h) const;
  // Along still water, x ∈ [x_min, x_max], ramp included: ζ, ∂ζ/∂x, ∂²ζ/∂x²; and ∫ζ dx, ∫∫ζ dx² (one
  // fixed antiderivative of each, the same for every x at one time).
  void line_elevation(const WavePolynomials& p, double x, double& zeta, double& slope, double& curvature) const;
  void line_elevation(const WavePolynomials& p, double x, double& zeta, double& slope) const;  // ζ and ∂ζ/∂x only
  void line_antiderivatives(const WavePolynomials& p, double x, double& first, double& second) const;

 private:
  std::vector<WavePatch> patches_;
  std::size_t degree_ = 0;  // M
  std::size_t line_degree_ = 0;  // D
  double max_wave_number_ = 0.0;
  double period_ = 0.0;  // 2π/Δω: the sums repeat
  double x_min_ = 0.0, x_max_ = 0.0;
  std::vector<double> channel_scale_;  // η_m = channel_m × channel_scale_[m]
  double window_bound(const std::vector<double>& bounds, double t) const {
    if (record_.periodic() && t >= period_) t -= std::floor(t / period_) * period_;  // the sea repeats
    const auto w = static_cast<std::size_t>(std::max(t, 0.0) / stats_.bound_window);
    return w < bounds.size() ? bounds[w] : bounds.back();
  }

  hydro::HarmonicRecord record_;
  IncidentWaveRecordStats stats_;
  std::vector<double> window_elevation_, window_slope_, window_curvature_, window_third_;  // per bound window, margin included
};

}  // namespace ffrf::sea
