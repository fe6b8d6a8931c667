// A crane run: the solvers' integration (solve/integration.hpp) of the crane's equations with the
// crane's own recorder (its outputs at every output time, the divergence and capsize watch on each
// sample), the wire's slack/taut events from the located events, and the post-run detectors
// (multibody/run_monitor.hpp) — the run result every study and report reads.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "multibody/boom_stress_profile.hpp"
#include "multibody/crane_equations.hpp"
#include "multibody/run_monitor.hpp"
#include "solve/integration.hpp"

namespace ffrf::multibody {

using solve::Integrator;
using solve::SolverStats;
using solve::WorkLimits;

// The integrator's settings and the failure detectors' bounds of one crane run.
struct RunSettings : solve::IntegratorSettings {
  MonitorLimits monitor = {};  // the failure detectors' bounds (multibody/run_monitor.hpp)
};

struct WireEvent {
  double time;
  bool slack;    // true: went slack (ℓ ↓ L0); false: became taut again
  int wire = 0;  // the wire (CraneEquations::wire_name)
};

// The integration's record (output times, statistics, events) with the crane's samples at those
// times, the wire's events and what the run ran into (non-fatal detections).
struct RunResult : solve::IntegrationRecord {
  std::vector<CraneOutputs> samples;
  std::vector<WireEvent> wire_events;     // the hoist wire's (the cargo's)
  std::vector<WireEvent> luffing_events;  // a pinned boom's luffing wires'
  std::vector<WireEvent> backstay_events;  // an A-frame's backstays'
  std::vector<std::string> wire_names;    // by wire index
  std::vector<Detection> detections;
  // The stresses along the boom over the samples, by the model's recovery (empty when it recovers none).
  BoomStressEnvelope boom_stress;
};

// Integrates `equations` from z0 at rest with settings.kind (solve::integrate), sampling the crane's
// outputs and watching each sample; then the post-run detectors fill RunResult::detections. A
// SolverFailure thrown from here carries the crane's partial RunResult (partial_run).
RunResult simulate(CraneEquations& equations, const Eigen::VectorXd& z0, const RunSettings& settings);

// The crane run up to a failure thrown by simulate (nullptr when none was attached).
std::shared_ptr<const RunResult> partial_run(const solve::SolverFailure& failure);

}  // namespace ffrf::multibody
