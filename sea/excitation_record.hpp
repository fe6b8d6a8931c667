// The first-order BEM wave excitation of the hull (sea/bem_excitation.hpp) sampled once over a
// record and read back by interpolation, so that an irregular sea costs what a regular wave does on
// every right-hand-side evaluation. The exact excitation at G1, channel c ∈ {surge, heave, pitch},
//   F_c(t) = Σ_i Re{F_{c,i} e^{i(ω_i t + ψ_i)}} = Re{s_c(t)},   s_c(t) = Σ_i (F_{c,i} e^{iψ_i}) e^{+iω_i t},
// is a harmonic sum when the components lie on one frequency grid, ω_i = (n0 + i) Δω (as
// hydro::synthesize makes them; WaveField::harmonic_grid() recognises the grid, in deep water only, so a
// finite-depth sea keeps the exact sum). Then hydro::HarmonicRecord samples s_c by
// FFT at a step Δt and interpolates it by quintic Hermite segments, with the interpolation error measured
// at every segment midpoint (where the segment's error τ³(1 − τ)³ s⁽⁶⁾ Δt⁶/720 peaks).
//
// Tolerance, per channel and absolute: ε_c [N, N, N m]. The channels are recorded divided by ε_c and
// the record is asked for a midpoint error ≤ 1, so one measured fraction e ≤ 1 bounds every channel:
// |F_c,record − F_c| ≤ e ε_c at the midpoints (the Hermite error elsewhere in a segment is at most the
// midpoint's up to the change of s⁽⁶⁾ over one segment). The suggested ε_c is a fraction of the channel's
// standard deviation σ_c = √(½ Σ_i |F_{c,i}|²) (excitation_tolerance): σ_c is the scale of the force
// itself and does not depend on the component count, unlike the amplitude sum Σ_i |F_{c,i}|, which grows
// with √N while the force does not.
//
// Outside the recorded interval [0, duration] the record answers with the exact sum (the fallback).
// The wave field's ramp r(t) is not part of the record, as it is not part of BemExcitation::at.
// Reference: FFT synthesis of irregular seas (Faltinsen 1990 §2.2; DNV-RP-C205 §3.3).
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <optional>
#include <string>

#include "sea/bem_excitation.hpp"
#include "sea/wave_field.hpp"
#include "hydro/harmonic_record.hpp"

namespace ffrf::sea {

struct ExcitationRecordOptions {
  double duration = 0.0;                                // [s] > 0: the record covers [0, duration]
  Eigen::Vector3d tolerance = Eigen::Vector3d::Zero();  // ε_c [N, N, N m] > 0 (0 only for a channel that is zero)
  std::size_t memory_limit = std::size_t{1} << 30;      // [bytes]: refuse a record larger than this
};

// The fraction of the standard deviation this module suggests: 1e-8 σ_c, two orders of magnitude
// under the integrators' default relative tolerance (1e-6), so the record never decides a run's error.
inline constexpr double kDefaultExcitationFraction = 1e-8;

// σ_c = √(½ Σ_i |F_{c,i}|²) [N, N, N m]: the standard deviation of each channel over a record.
Eigen::Vector3d excitation_standard_deviation(const BemExcitation& excitation);
// ε_c = fraction × σ_c.
Eigen::Vector3d excitation_tolerance(const BemExcitation& excitation, double fraction = kDefaultExcitationFraction);

struct ExcitationRecordOutcome;

class ExcitationRecord {
 public:
  // Records `excitation` (built for `wave` by bem_excitation) over [0, options.duration]. Refuses
  // (outcome without record, reason given) when the wave's components are not on a harmonic grid,
  // when the excitation's component count or frequencies differ from the grid's ω_i = (n0 + i) Δω
  // (to 4 ulp, the grid's own test), when the samples would exceed options.memory_limit or the
  // tolerance is not reached. Throws std::invalid_argument (value named) when the excitation's
  // vectors differ in length, the duration is not finite and > 0, or a non-zero channel's tolerance
  // is not finite and > 0.
  static ExcitationRecordOutcome build(const BemExcitation& excitation, const WaveField& wave,
                                       const ExcitationRecordOptions& options);

  // The excitation at G1 (surge, heave, pitch) [N, N, N m] at t, without the ramp: the record for
  // 0 ≤ t ≤ duration(), BemExcitation::at(t) outside.
  Eigen::Vector3d at(double t) const;

  double duration() const { return record_.duration(); }  // [s] ≥ the requested duration
  double time_step() const { return record_.time_step(); }  // Δt [s]
  std::size_t samples() const { return record_.samples(); }
  std::size_t memory_bytes() const { return record_.memory_bytes(); }
  double build_seconds() const { return build_seconds_; }  // the whole build: coefficients, FFTs, checks
  const Eigen::Vector3d& tolerance() const { return tolerance_; }  // ε_c [N, N, N m]
  // e: the largest measured midpoint error over all channels and segments as a fraction of ε_c (≤ 1).
  double midpoint_error_fraction() const { return record_.midpoint_error(); }
  // e ε_c [N, N, N m]: the measured bound on each channel's midpoint error.
  Eigen::Vector3d midpoint_error() const { return record_.midpoint_error() * tolerance_; }

 private:
  hydro::HarmonicRecord record_;
  Eigen::Vector3d channel_scale_ = Eigen::Vector3d::Ones();  // the recorded channel times this is the force
  Eigen::Vector3d tolerance_ = Eigen::Vector3d::Zero();
  BemExcitation exact_;  // the fallback outside [0, duration]
  double build_seconds_ = 0.0;
};

// The record, or why there is none (refusal: not on a harmonic grid, the excitation's frequencies not
// the grid's, the memory limit, the tolerance not reached).
struct ExcitationRecordOutcome {
  std::optional<ExcitationRecord> record;
  std::string refusal;  // empty when there is a record
};

}  // namespace ffrf::sea
