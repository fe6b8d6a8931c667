// A model's peak boom stress by both recoveries against the reference (see header).
#include "study/stress_recovery_errors.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ffrf::study {

StressRecoveryErrors stress_recovery_errors(const multibody::RunResult& run, const multibody::RunResult& reference,
                                            double window_start) {
  if (run.samples.size() != reference.samples.size() || run.time.size() != reference.time.size()) {
    throw std::invalid_argument("stress_recovery_errors: the runs are not sampled at the same times");
  }
  StressRecoveryErrors errors;
  double mean = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < reference.time.size(); ++i) {
    if (reference.time[i] < window_start) continue;
    mean += reference.samples[i].boom_peak_stress;
    errors.reference_peak = std::max(errors.reference_peak, reference.samples[i].boom_peak_stress);
    ++count;
  }
  if (count == 0) throw std::invalid_argument("stress_recovery_errors: the window is empty");
  mean /= count;
  for (const multibody::StressRecovery method : multibody::all_stress_recoveries) {
    const std::size_t m = static_cast<std::size_t>(method);
    double squared_error = 0.0, squared_signal = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < reference.time.size(); ++i) {
      if (reference.time[i] < window_start) continue;
      const double r = reference.samples[i].boom_peak_stress, x = run.samples[i].boom_peak_stress_by[m];
      squared_error += (x - r) * (x - r);
      squared_signal += (r - mean) * (r - mean);
      peak = std::max(peak, x);
    }
    PeakStressError& e = errors.by[m];
    e.normalized_rms = squared_signal > 0.0 ? std::sqrt(squared_error / squared_signal) : std::sqrt(squared_error / count);
    e.peak = peak;
    e.design_peak = errors.reference_peak > 0.0 ? std::abs(peak - errors.reference_peak) / errors.reference_peak : 0.0;
  }
  return errors;
}

}  // namespace ffrf::study
