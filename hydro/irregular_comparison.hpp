// Error metrics of an irregular-sea run against a reference run of the same sea (docs/hydrodynamics.md
// §5.3). In an irregular sea a small phase drift makes time histories disagree while every
// statistic an engineer uses agrees, so besides the normalized RMS of the time histories the
// comparison is made on statistics and spectra:
//   relative errors of σ (= of 4σ, the significant value), of the Rayleigh MPM, of the mean, of the
//   spectral moments m0 and m2 and of Tz = 2π sqrt(m0/m2) (both from Welch spectra), the peak
//   frequency error relative to the reference's, and the spectral distance
//   D = ∫|S − S_ref| dω / ∫ S_ref dω (0: equal spectra; 2: disjoint).
#pragma once

#include <vector>

#include "hydro/spectral_estimate.hpp"

namespace ffrf::hydro {

struct IrregularComparison {
  double time_history_nrms = 0.0;    // RMS(x − x_ref) / σ_ref
  double mean_error = 0.0;           // (mean − mean_ref) / σ_ref
  double sigma_error = 0.0;          // σ/σ_ref − 1
  double most_probable_maximum_error = 0.0;  // Rayleigh MPM / MPM_ref − 1
  double m0_error = 0.0, m2_error = 0.0, zero_crossing_period_error = 0.0, peak_frequency_error = 0.0;
  double spectral_distance = 0.0;
  double worst_statistic() const;    // the largest |relative error| among σ, MPM, m0, m2, Tz, peak
};

// Both records sampled at dt over the same times (equal sizes); throws std::invalid_argument
// otherwise, or when the reference has zero variance.
IrregularComparison compare_irregular(const std::vector<double>& run, const std::vector<double>& reference, double dt,
                                      const WelchOptions& welch = {});

}  // namespace ffrf::hydro
