// The time domain against the frequency domain (each method checks the other, `ffrf rao
// --check-time-domain`): regular-wave runs of the crane through the one run pipeline at several
// periods, small wave height (linear), and the response amplitudes they settle to compared with the
// RAOs of study/rao.hpp within a tolerance (1 %).
// The amplitude at ω is measured by least squares over the samples after the ramp, on the basis
//   1, cos ωt, sin ωt, cos 2ωt, sin 2ωt (the mean offset and second harmonic of the nonlinear
//   hydrostatics), and e^{σ_j t} cos ω_j t, e^{σ_j t} sin ω_j t for the linearised system's free modes
//   still alive in the window (λ_j = σ_j + iω_j from the natural modes),
// because after the ramp a linear system's response is exactly the steady harmonic plus its free
// modes: the transients need not have died out (the cargo swing and the moored surge decay over
// hundreds of seconds). The fit's residual (RMS over the amplitude) is reported beside each value.
// A [bem] hull: the RAO is the files' (the physical one, study/rao_bem.hpp), the free modes are the
// roots of the radiation model's own det(s²M + sC + K + Z(s)) (a memory hull's transient is not that of
// the constant system), the runs sample (and record the memory) at the kernel's time step or finer,
// and each channel also carries the RAO of the model's own radiation (the consistent comparison).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "coupling/linearisation.hpp"
#include "coupling/simulation.hpp"
#include "modal/mode_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"

namespace ffrf::study {

struct TimeDomainCheckRequest {
  std::vector<double> periods{8.0, 10.0, 14.0};  // [s]
  double wave_height = 0.2;    // [m] small: the hull pressure stays linear
  double ramp_periods = 3.0;   // [-]
  double window_periods = 12.0;  // fitted periods after the ramp [-]
  double relative_tolerance = 1e-8;  // of the integrator (CVODE BDF, minimal coordinates)
  double tolerance = 0.01;     // relative amplitude deviation that passes
  bool memory_free_modes = true;  // [bem]: fit the memory hull's own free modes (false: the constant system's)
};

// The judged channels: hull heave and pitch, cargo heave.
std::vector<coupling::LinearOutput> checked_outputs();

struct ChannelCheck {
  coupling::LinearOutput output;
  double frequency_domain = 0.0;  // |RAO| per metre of wave amplitude (as `ffrf rao` gives it)
  // [bem] scenes: |RAO| with the hull's radiation as the run's radiation model realises it (A∞ and the
  // transform of its kernel; study/rao_bem.hpp) — the consistent comparison; 0 without [bem].
  double model_frequency_domain = 0.0;
  double time_domain = 0.0;       // fitted amplitude / wave amplitude
  double phase_difference = 0.0;  // time-domain phase − RAO phase [rad], wrapped to (−π, π]
  double fit_residual = 0.0;      // RMS of the fit's residual / fitted amplitude [-]
  double deviation() const { return time_domain / frequency_domain - 1.0; }
  double model_deviation() const { return model_frequency_domain > 0.0 ? time_domain / model_frequency_domain - 1.0 : 0.0; }
};

struct PeriodCheck {
  double period = 0.0;  // [s]
  double duration = 0.0;  // simulated [s]
  double window_start = 0.0;  // [s]
  int fitted_modes = 0;   // free modes in the fit basis
  std::vector<ChannelCheck> channels;
  coupling::SolverStats stats;
};

struct TimeDomainCheck {
  scene::BoomChoice choice;
  TimeDomainCheckRequest request;
  std::vector<PeriodCheck> periods;
  double worst_deviation() const;  // max |deviation| over every period and channel
  bool passed() const { return worst_deviation() <= request.tolerance; }
};

// Throws scene::SceneError, coupling::SolverFailure, std::invalid_argument (a period ≤ 0, a wave
// height ≤ 0, a tolerance outside (0, 1)). `progress` is told each period as it starts.
TimeDomainCheck check_time_domain(const scene::Scene& scene, const scene::BoomChoice& choice,
                                  const TimeDomainCheckRequest& request,
                                  const std::function<void(double period)>& progress = {}, modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
