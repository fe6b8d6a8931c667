// The failure detectors every run carries, so that a run that goes wrong says how and when: while the run goes, a divergence watch on the
// boom tip's elastic deflection (the linear floating-frame model is meaningless once it is a sizeable
// fraction of the boom length) and, for a floating hull, a capsize watch (pitch past 90°); after the
// run, a deck edge or the cargo under water (what the model does not describe), the wire's slack
// intervals and snap loads (tension from zero back to a peak above the static tension), the clamp's
// constraint drift, the boom's compression against its Euler buckling load π²EI/(4L²)
// (clamped-free), and a high rate of rejected steps. Solver failures
// (step-size collapse, Newton divergence, non-positive-definite mass matrix, explicit instability)
// are named by the integrators themselves (solve/failure.hpp). docs/stability.md explains each.
#pragma once

#include <limits>
#include <vector>

#include "multibody/crane_equations.hpp"
#include "solve/failure.hpp"

namespace ffrf::multibody {

using solve::Detection;
using solve::FailureKind;
using solve::SolverFailure;

struct RunResult;

// A floating hull's box (relative to G1, hull frame) and the cargo's, for the capsize, deck and
// cargo-in-water watch; the surface lies within ±wave_amplitude of still water (y = 0).
struct WaterLimits {
  bool floating = false;  // false: no water (a hub)
  double hull_stern_x = 0.0, hull_bow_x = 0.0, hull_deck_y = 0.0;  // [m]
  double cargo_half_length = 0.0, cargo_half_height = 0.0;          // [m]; 0: no cargo
  double wave_amplitude = 0.0;                                      // ζ_a [m]
};

struct MonitorLimits {
  double boom_length = 0.0;               // L [m]; 0: no deflection watch
  double deflection_limit = 0.2;          // divergence bound on |tip deflection| / L [-]
  double constraint_drift_limit = 1e-3;   // [m]
  double buckling_load = std::numeric_limits<double>::infinity();  // Euler load of the boom [N]
  double buckling_warning_ratio = 0.5;    // warn from this fraction of the buckling load
  double wire_unstretched_length = 0.0;   // L0 [m]; 0: no wire
  double static_tension = 0.0;            // the wire's tension at rest [N] (snap ratio); 0: unknown
  // A snap load is a peak above this multiple of the static tension after a slack interval: the wire
  // caught the falling cargo and overshot its load at rest. A lower peak is the cargo settling back on
  // the wire (the slack interval is reported, not a snap).
  double snap_load_factor = 1.0;
  double error_test_failure_ratio = 0.3;  // warn when rejected steps exceed this fraction of steps
  WaterLimits water = {};                 // capsize, deck submerged, cargo in water
  double cargo_pitch_limit = 1.5707963267948966;  // |cargo pitch| [rad] beyond which the cargo has overturned
};

// Watches each output sample (the integrators check for a stop request before it): for a floating
// hull, capsize (|pitch| ≥ 90°: SolverFailure(capsize)); then throws SolverFailure(divergence) with
// the growth rate σ of the deflection: the least-squares slope of ln|δ| over its envelope (the record highs since |δ| passed
// 10 % of the bound, kept through the dips of an oscillation until it decays below 1 %), NaN
// ("unresolved") when the bound was passed within one output interval
// when |δ| exceeds deflection_limit · L, or when a sample is not finite.
class DivergenceWatch {
 public:
  DivergenceWatch(const MonitorLimits& limits, const char* solver) : limits_(limits), solver_(solver) {}
  void observe(double t, const CraneOutputs& sample);

 private:
  MonitorLimits limits_;
  const char* solver_;
  std::vector<double> times_, log_deflections_;  // the growth window
};

struct SlackInterval {
  double start = 0.0;
  double end = std::numeric_limits<double>::infinity();  // inf: still slack at the end of the run
};
struct SnapLoad {
  double time = 0.0;          // the wire became taut again [s]
  double peak_tension = 0.0;  // largest sampled tension before it goes slack again [N]
  double peak_time = 0.0;     // [s]
  double ratio = 0.0;         // peak / static tension (0 when the static tension is unknown)
};

// Slack intervals from the located wire events (a run that starts slack opens one at t = 0).
std::vector<SlackInterval> slack_intervals(const RunResult& result, const MonitorLimits& limits);
// The snap loads: for each slack interval that ends within the run, the peak sampled tension until
// the next slack interval, when it exceeds snap_load_factor × static_tension (every such peak when
// the static tension is unknown).
std::vector<SnapLoad> snap_loads(const RunResult& result, const MonitorLimits& limits);
// Largest |C| and the buckling load ratio (largest root compression / Euler load) over the samples.
double max_constraint_drift(const RunResult& result);
double max_buckling_load_ratio(const RunResult& result, const MonitorLimits& limits);
// The post-run detections (non-fatal): wire slack, snap loads, constraint drift, buckling, a deck
// edge or the cargo below the lowest wave trough (deck submerged, cargo in water), the cargo pitched
// past cargo_pitch_limit about its hook (cargo overturned: the hook is a frictionless pin, the cargo's
// rocking mode is lightly damped), rejected steps.
std::vector<Detection> post_run_detections(const RunResult& result, const MonitorLimits& limits);

}  // namespace ffrf::multibody
