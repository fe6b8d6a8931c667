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
#include <optional>
#include <string>
#include <vector>

#include "multibody/linearisation.hpp"
#include "multibody/crane_run.hpp"
#include "modal/mode_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"
#include "study/natural_mode.hpp"

namespace ffrf::study {

struct TimeDomainCheckRequest {
  std::vector<double> periods{8.0, 10.0, 14.0};  // [s]
  double wave_height = 0.2;    // [m] small: the hull pressure stays linear
  double ramp_periods = 3.0;   // [-]
  double window_periods = 12.0;  // fitted periods after the ramp [-]
  double relative_tolerance = 1e-8;  // of the integrator (CVODE BDF, minimal coordinates)
  double tolerance = 0.01;     // relative amplitude deviation that passes
  bool memory_free_modes = true;  // [bem]: fit the memory hull's own free modes (false: the constant system's)
  // A period that fails is run again at half the wave height (nonlinearity_probe below).
  bool probe_nonlinearity = true;
};

// The judged channels: hull heave and pitch, cargo heave.
std::vector<multibody::LinearOutput> checked_outputs();

struct ChannelCheck {
  multibody::LinearOutput output;
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

// Why a period may fail: the linear theory's error of a small wave grows with its height (the hull
// pressure on the moving wetted box, the wire's and the cargo's swing are nonlinear), a numerical
// error (integrator tolerance, the fit) does not. A failed period is run again at half the height:
// the deviation is amplitude-dependent when it falls to at most `amplitude_dependent_ratio` of the
// full height's (a quadratic error falls to 1/4, a linear one to 1/2). Near a resonance the
// response to a given wave is largest, so the nearest resonant mode is named, and whether the
// period lies inside its half-power band.
constexpr double amplitude_dependent_ratio = 0.6;

struct NonlinearityProbe {
  double wave_height = 0.0;      // the probe's (half the check's) [m]
  double worst_deviation = 0.0;  // max |deviation| over the channels at that height
  double exponent = 0.0;         // p of deviation ∝ Hᵖ, log₂(full / half) (0 when the deviation did not fall)
};

struct PeriodCheck {
  double period = 0.0;  // [s]
  double duration = 0.0;  // simulated [s]
  double window_start = 0.0;  // [s]
  int fitted_modes = 0;   // free modes in the fit basis
  std::vector<ChannelCheck> channels;
  solve::SolverStats stats;
  std::optional<NaturalMode> nearest_mode;  // the resonant natural mode nearest in frequency
  bool in_half_power_band = false;          // the wave's ω within the nearest mode's half-power band
  std::optional<NonlinearityProbe> probe;   // a failed period with probe_nonlinearity
  double worst_deviation() const;           // max |deviation| over the channels
  // The failure shrinks with the wave height (see above).
  bool amplitude_dependent() const;
};

struct TimeDomainCheck {
  scene::BoomChoice choice;
  TimeDomainCheckRequest request;
  std::vector<PeriodCheck> periods;
  double worst_deviation() const;  // max |deviation| over every period and channel
  bool passed() const { return worst_deviation() <= request.tolerance; }
  // The largest wave height [m] (two significant digits, rounded down) at which every
  // amplitude-dependent failed period is expected to deviate at most half the tolerance, by its
  // measured deviation ∝ Hᵖ (p clamped to [1, 3]); empty when no failed period is amplitude-dependent.
  std::optional<double> suggested_wave_height() const;
};

// Throws scene::SceneError, solve::SolverFailure, std::invalid_argument (a period ≤ 0, a wave
// height ≤ 0, a tolerance outside (0, 1)). `progress` is told each run's period and wave height as it starts.
TimeDomainCheck check_time_domain(const scene::Scene& scene, const scene::BoomChoice& choice,
                                  const TimeDomainCheckRequest& request,
                                  const std::function<void(double period, double wave_height)>& progress = {}, modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
