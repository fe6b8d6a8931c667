// The failure detectors every run carries (issue 5): while the run goes, a divergence watch on the
// boom tip's elastic deflection (the linear floating-frame model is meaningless once it is a sizeable
// fraction of the boom length); after the run, the wire's slack intervals and snap loads (tension
// from zero back to a peak), the clamp's constraint drift, the boom's compression against its Euler
// buckling load π²EI/(4L²) (clamped-free), and a high rate of rejected steps. Solver failures
// (step-size collapse, Newton divergence, non-positive-definite mass matrix, explicit instability)
// are named by the integrators themselves (coupling/failure.hpp). docs/stability.md explains each.
#pragma once

#include <limits>
#include <vector>

#include "coupling/crane_equations.hpp"
#include "coupling/failure.hpp"

namespace ffrf::coupling {

struct RunResult;
struct SolverStats;

struct MonitorLimits {
  double boom_length = 0.0;               // L [m]; 0: no deflection watch
  double deflection_limit = 0.2;          // divergence bound on |tip deflection| / L [-]
  double constraint_drift_limit = 1e-3;   // [m]
  double buckling_load = std::numeric_limits<double>::infinity();  // Euler load of the boom [N]
  double buckling_warning_ratio = 0.5;    // warn from this fraction of the buckling load
  double wire_unstretched_length = 0.0;   // L0 [m]; 0: no wire
  double static_tension = 0.0;            // the wire's tension at rest [N] (snap ratio); 0: unknown
  double error_test_failure_ratio = 0.3;  // warn when rejected steps exceed this fraction of steps
};

// Watches each output sample; throws SolverFailure(divergence) with the growth rate σ of the
// deflection: the least-squares slope of ln|δ| over its envelope (the record highs since |δ| passed
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
// One snap per slack interval that ends within the run: the peak sampled tension that follows.
std::vector<SnapLoad> snap_loads(const RunResult& result, const MonitorLimits& limits);
// Largest |C| and the buckling load ratio (largest root compression / Euler load) over the samples.
double max_constraint_drift(const RunResult& result);
double max_buckling_load_ratio(const RunResult& result, const MonitorLimits& limits);
// The post-run detections (non-fatal): wire slack, snap loads, constraint drift, buckling, rejected steps.
std::vector<Detection> post_run_detections(const RunResult& result, const MonitorLimits& limits);

}  // namespace ffrf::coupling
