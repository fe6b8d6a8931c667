// Statistics of a crane run in an irregular sea (docs/hydrodynamics.md §5): over the
// window after the wave ramp, per response: mean, standard deviation σ and the significant value
// 4σ, the zero up-crossing period, the response spectrum by Welch's method (peak frequency,
// m0), and the most probable maximum over the record three ways — Rayleigh (narrow-band Gaussian,
// N = zero up-crossing waves), a maximum-likelihood Weibull fit to the peaks and a Gumbel fit to
// block maxima (hydro/extreme_values.hpp) — next to the observed maximum; the incident elevation
// at the hull's reference point (its 4σ is the realised Hs); the wire tension's dynamic
// amplification factor (observed and Rayleigh-MPM). Compare: statistics and spectra of each model
// against the reference (hydro/irregular_comparison.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "multibody/crane_equations.hpp"
#include "hydro/extreme_values.hpp"
#include "hydro/irregular_comparison.hpp"
#include "hydro/spectral_estimate.hpp"
#include "scene/scene.hpp"

namespace ffrf::study {

struct ResponseStatistics {
  std::string_view column;  // output_series column ("cargo_heave_m"); "wave_elevation_m" for the sea
  std::string_view unit;
  double mean = 0.0, standard_deviation = 0.0, significant = 0.0;  // 4σ
  double zero_crossing_period = 0.0;  // Tz from the up-crossings [s]
  double peak_frequency = 0.0;        // of the Welch spectrum [rad/s]; NaN when its resolution is coarser than ω_z/4
  double observed_maximum = 0.0;      // largest value over the window (a level)
  bool extremes = false;              // MPMs below are valid (the window holds ≥ 10 waves)
  double rayleigh = 0.0, weibull = 0.0, gumbel = 0.0;  // most probable maxima, as levels (mean added)
  double weibull_shape = 0.0;
  hydro::PowerSpectrum spectrum;
};

struct IrregularStatistics {
  double window_start = 0.0;     // [s]
  double record_length = 0.0;    // [s] of the window
  double ramp_end = 0.0;         // [s] the wave ramp-in ends (scene::wave_ramp_duration)
  bool after_ramp = false;       // the window starts after the ramp; false: a run that ends within the
                                 // ramp, whose statistics are over the whole run, ramp included
  double sample_interval = 0.0;  // [s]
  // The synthesized sea: its band, component count and the share of the spectrum's m0 it holds.
  double band_lower = 0.0, band_upper = 0.0;  // [rad/s]
  std::size_t components = 0;
  double band_share = 0.0;       // Σ S(ω_n) Δω / m0 of the spectrum (1 for user components)
  ResponseStatistics elevation;  // the incident wave at x = 0 (G1 at rest)
  std::vector<ResponseStatistics> responses;  // statistics_columns() order
  hydro::TensionAmplification wire;           // DAF (crane with a wire)
  std::string note;              // why extremes are missing, when they are
};

// The outputs whose statistics a report gives: the judged rows of the output-channel table.
std::vector<std::string_view> statistics_columns();

// Nothing for a scene without an irregular sea or a window of fewer than 32 samples. The samples
// must be uniform at `sample_interval` from time[first] on.
std::optional<IrregularStatistics> irregular_statistics(const scene::Scene& scene, const std::vector<double>& time,
                                                        const std::vector<multibody::CraneOutputs>& samples,
                                                        const multibody::CraneOutputs& statics, std::size_t first,
                                                        double sample_interval);

// Statistics and spectra of a run against the reference, per statistics_columns() entry.
struct IrregularErrors {
  std::vector<hydro::IrregularComparison> responses;
  double worst_statistic = 0.0;  // the largest over the responses
};
std::optional<IrregularErrors> irregular_errors(const scene::Scene& scene, const std::vector<multibody::CraneOutputs>& run,
                                                const multibody::CraneOutputs& run_statics,
                                                const std::vector<multibody::CraneOutputs>& reference,
                                                const multibody::CraneOutputs& reference_statics, std::size_t first,
                                                double sample_interval);

}  // namespace ffrf::study
