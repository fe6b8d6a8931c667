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
// recorded once per record by FFT and cubic Hermite interpolation (hydro/harmonic_record.hpp).
// Truncation: for |z − c| ≤ ρ the error of F is at most Σ_n |A_n| e^{k_n Re c} R_M(k_n ρ),
// R_M(x) = Σ_{m>M} x^m/m! (that of G at most ρ times it, of H ρ² times it); M is the smallest
// degree that keeps it below a quarter of the tolerance. Time interpolation: measured at every
// segment midpoint. Both are stated with the record. Elevation and slope bounds over the whole x
// range of the hull (for the keel and the deck, which lie outside the patches): sampled on a grid
// by FFT over the record, kept per window of `bound_window` seconds (a keel that the record's
// deepest trough might reach is still certainly wet in the calmer minutes), with a stated margin
// for the values between samples.
// Needs deep water and components on a harmonic grid (ω_n = n Δω); otherwise the exact sums are the
// only path (coupling/wave_field.hpp). Reference: docs/hydrodynamics.md ("The sea evaluated once").
#pragma once

#include <algorithm>
#include <complex>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "coupling/wave_field.hpp"
#include "hydro/harmonic_record.hpp"

namespace ffrf::coupling {

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

// What the record is and what it cost: stated in the run header and summary.json.
struct IncidentWaveRecordStats {
  std::size_t patches = 0, degree = 0, channels = 0, samples = 0, components = 0;
  double time_step = 0.0;            // [s] of the Hermite segments
  double truncation_bound = 0.0;     // [m] Taylor remainder bound of F in a patch
  double interpolation_error = 0.0;  // [m] measured at segment midpoints (F units)
  double elevation_bound = 0.0;      // [m] |ζ| ≤ this over [x_min, x_max] × record, before the ramp
  double slope_bound = 0.0;          // [-] |∂ζ/∂x| ≤ this, likewise
  double bound_window = 0.0;         // [s] the bounds are also kept per window of this length
  double memory_bytes = 0.0;
  double build_seconds = 0.0;
};

// The polynomials of every patch at one time t (filled by IncidentWaveRecord::at; reused across
// calls: sized once, then no allocation).
struct WavePolynomials {
  std::vector<std::complex<double>> elevation;  // f̂_j = F Taylor coefficients × ρ^j, per patch (M + 1 each)
  std::vector<std::complex<double>> potential;  // η_m, per patch (M + 3 each)
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
  double duration() const { return record_.duration(); }
  double x_min() const { return x_min_; }
  double x_max() const { return x_max_; }
  // |ζ| and |∂ζ/∂x| over the x range in the bound window holding t, times the ramp r(t).
  double elevation_bound(double t, double ramp) const { return ramp * window_bound(window_elevation_, t); }
  double slope_bound(double t, double ramp) const { return ramp * window_bound(window_slope_, t); }

  // The polynomials at t ∈ [0, duration] (the ramp of the wave field included in `ramp`).
  void at(double t, double ramp, WavePolynomials& out) const;

  // The patch holding (x, y), or −1.
  int patch_of(double x, double y) const;
  // r Re-less values at z = y + i x in patch p: F and dF/dz; G and H. Not ramped.
  void elevation_terms(const WavePolynomials& p, int patch, double x, double y, std::complex<double>& f,
                       std::complex<double>& f_rate) const;
  void antiderivatives(const WavePolynomials& p, int patch, double x, double y, std::complex<double>& g,
                       std::complex<double>& h) const;

 private:
  std::vector<WavePatch> patches_;
  std::size_t degree_ = 0;  // M
  double x_min_ = 0.0, x_max_ = 0.0;
  std::vector<double> channel_scale_;  // η_m = channel_m × channel_scale_[m]
  double window_bound(const std::vector<double>& bounds, double t) const {
    const auto w = static_cast<std::size_t>(std::max(t, 0.0) / stats_.bound_window);
    return w < bounds.size() ? bounds[w] : bounds.back();
  }

  hydro::HarmonicRecord record_;
  IncidentWaveRecordStats stats_;
  std::vector<double> window_elevation_, window_slope_;  // per bound window, margin included
};

}  // namespace ffrf::coupling
