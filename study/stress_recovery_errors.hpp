// The boom's peak fibre stress of a model against the reference's, recovered both ways from the same
// run (multibody/boom_stress.hpp: every sample holds the peak by mode displacement and by mode
// acceleration; a nodal model's two are its own displacements', a rigid boom's mode displacement is
// zero): per recovery the normalized RMS error of the peak-stress history over the error window
// (the verdicts' measure, multibody/error_metrics.hpp) and the error of its largest value over the
// window, the design value |max σ − max σ_ref| / max σ_ref.
#pragma once

#include <array>
#include <vector>

#include "multibody/stress_recovery.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {

struct PeakStressError {
  double normalized_rms = 0.0;
  double design_peak = 0.0;  // relative error of the largest peak over the window
  double peak = 0.0;         // the model's largest peak over the window [Pa]
};

struct StressRecoveryErrors {
  std::array<PeakStressError, multibody::all_stress_recoveries.size()> by{};  // by StressRecovery
  double reference_peak = 0.0;  // the reference's largest peak over the window [Pa]
  const PeakStressError& operator[](multibody::StressRecovery method) const { return by[static_cast<std::size_t>(method)]; }
};

// Throws std::invalid_argument when the runs are not sampled at the same times.
StressRecoveryErrors stress_recovery_errors(const multibody::RunResult& run, const multibody::RunResult& reference,
                                            double window_start);

}  // namespace ffrf::study
