// A record of harmonic sums sampled once and interpolated: channels
//   s_c(t) = Σ_i a_{c,i} e^{i δ ω_i t},   ω_i = (n0 + i) Δω   (whole multiples of one frequency step),
// sampled at t_j = j Δt with Δt = T / N (T = 2π/Δω, the sums' period) by one inverse FFT of length N
// per channel (FFTW), together with their first and second time derivatives (coefficients × iδω_i
// and × −ω_i², two more FFTs), and read back by quintic Hermite interpolation between samples (C² in
// t). Channels of which only the real part is wanted, r_c(t) = Re Σ_i b_{c,i} e^{iδω_i t}, are
// recorded two to a complex channel, r_a + i r_b, from the two-sided sum
//   ½ Σ_i (b_a + i b_b) e^{iδω_i t} + ½ Σ_i (b̄_a + i b̄_b) e^{−iδω_i t}
// (bins n and N − n of the same transform; N > 2 n_max keeps the two sides apart): half the memory
// and half the transforms of recording them as complex channels.
// The interpolation error of a quintic Hermite segment is s⁽⁶⁾(ξ) τ³(1 − τ)³ Δt⁶ / 720 (τ ∈ [0, 1]
// the position in the segment): largest near the midpoint, where the exact sums are known from a
// fourth FFT (coefficients × e^{iδω_i Δt/2}). The record measures that error at the midpoint of every
// segment of every channel and chooses N so that it stays below the requested tolerance (a stated,
// measured bound, not an estimate from Σ|a|ω⁶, which grows with the component count while the sums
// grow with its root). Quintic rather than cubic: for the same error the step is about 5× longer at
// a sea's ω Δt, so the record takes a quarter of the memory of a cubic one.
// The sums repeat with period T: a record asked to cover T or more holds one period (N + 1 samples)
// and answers any t ≥ 0 from t mod T.
// Cost to build: 4 FFTs of length N per recorded channel (plus a retry with a finer N when the first
// guess misses); to read: one segment lookup and 6 multiply–adds per channel. Memory: 48 bytes per
// recorded channel and sample (value and two derivatives), stated before it is allocated.
// Reference: FFT synthesis of irregular seas (Faltinsen 1990 §2.2; DNV-RP-C205 §3.3).
#pragma once

#include <complex>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace ffrf::hydro {

// FFTW's planner is not thread-safe: every planning call in ffrf holds this lock.
std::mutex& fftw_planner_mutex();

// Harmonic sums to record: coefficients[c][i] = a_{c,i} for component i (frequency (n0 + i) Δω).
struct HarmonicSums {
  double frequency_step = 0.0;       // Δω [rad/s] > 0
  std::int64_t first_harmonic = 0;   // n0 ≥ 0
  int time_sign = -1;                // δ: +1 or −1 (the sign of ω t in the exponent)
  std::vector<std::vector<std::complex<double>>> coefficients;  // complex channels × components
  // Channels recorded by their real part only (Re Σ b e^{iδωt}), two to a complex channel after the
  // complex ones: real channel r is the real part of record channel C + r/2 for even r, its imaginary
  // part for odd r (C = coefficients.size()). Every channel of either kind has the same length.
  std::vector<std::vector<std::complex<double>>> real_parts;
};

struct HarmonicRecordOptions {
  double duration = 0.0;          // [s] > 0: samples cover [0, duration] (and one segment beyond; one
                                  // period, read periodically, when duration reaches the period)
  double tolerance = 1e-9;        // largest interpolation error allowed at a segment midpoint, any channel
  std::size_t memory_limit = std::size_t{4} << 30;  // [bytes] refuse (std::length_error) above this
  double largest_time_step = 1.0; // [s] Δt never exceeds this (a ceiling for very smooth sums)
};

// The real channels of `sums` (sums.real_parts; no complex channel) sampled exactly (to round-off) at
// t_j = j Δt over one period, Δt = T/N ≤ largest_step, by one FFT per two channels: for bounds and
// statistics that need the values at the samples and no interpolant. Throws as HarmonicRecord::build.
struct HarmonicSamples {
  double time_step = 0.0;                     // Δt [s]
  std::vector<std::vector<double>> channels;  // [real channel][j], j = 0 … N − 1 (periodic: j mod N)
  std::vector<double> magnitude_sums;         // Σ_i |b_{c,i}| per channel: the largest |r_c| can be
};
HarmonicSamples sample_real_parts(const HarmonicSums& sums, double largest_step);

class HarmonicRecord {
 public:
  HarmonicRecord() = default;
  // Throws std::invalid_argument naming the field and value (Δω ≤ 0, n0 < 0, δ ∉ {±1}, no channel,
  // channels of unequal length, duration ≤ 0 or not finite, tolerance ≤ 0), std::length_error when
  // the samples would take more than options.memory_limit bytes (the message gives the size), and
  // std::runtime_error when FFTW cannot plan a transform.
  static HarmonicRecord build(const HarmonicSums& sums, const HarmonicRecordOptions& options);
  // Bytes the record of these sums would take at the time step the tolerance needs (without
  // building it): the check a caller makes before it commits to the fast path.
  static std::size_t predicted_memory(const HarmonicSums& sums, const HarmonicRecordOptions& options);

  std::size_t channels() const { return channels_; }                  // recorded (complex) channels
  std::size_t complex_channels() const { return complex_channels_; }  // of which the complex ones come first
  std::size_t real_channels() const { return real_channels_; }        // packed two to a channel after them
  std::size_t samples() const { return samples_; }
  double time_step() const { return time_step_; }
  double duration() const { return duration_; }        // t covered: [0, duration] (+inf when periodic)
  bool periodic() const { return periodic_; }          // one whole period recorded: any t ≥ 0
  std::size_t fft_size() const { return fft_size_; }   // N of the transforms
  double midpoint_error() const { return midpoint_error_; }  // measured, largest over channels and segments
  double build_seconds() const { return build_seconds_; }
  std::size_t memory_bytes() const {
    return (values_.size() + rates_.size() + accelerations_.size()) * sizeof(std::complex<double>);
  }
  bool covers(double t) const { return t >= 0.0 && t <= duration_; }

  // s_c(t) into out[0 … channels − 1]; t must be covered (not checked on this hot path). Real channel
  // r is then real_channel(out, r).
  void evaluate(double t, std::complex<double>* out) const;
  // s_c(t) and ṡ_c(t).
  void evaluate(double t, std::complex<double>* out, std::complex<double>* rate) const;
  double real_channel(const std::complex<double>* out, std::size_t r) const {
    const std::complex<double>& packed = out[complex_channels_ + r / 2];
    return r % 2 == 0 ? packed.real() : packed.imag();
  }

 private:
  // Σ of the segment j's six Hermite terms (value, rate, acceleration at its two ends) with `weights`.
  void combine(std::size_t j, const double (&weights)[6], std::complex<double>* out) const;
  // The segment holding t and the position τ ∈ [0, 1] in it.
  std::size_t segment(double t, double& tau) const;

  std::size_t channels_ = 0, complex_channels_ = 0, real_channels_ = 0, samples_ = 0, fft_size_ = 0;
  double time_step_ = 0.0, duration_ = 0.0, period_ = 0.0, midpoint_error_ = 0.0, build_seconds_ = 0.0;
  bool periodic_ = false;
  std::vector<std::complex<double>> values_, rates_, accelerations_;  // [sample × channels + channel]
};

}  // namespace ffrf::hydro
