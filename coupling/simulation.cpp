// Dispatch to the integrator of a run (its row in integrator_table.cpp), the terminal progress line and
// the time-reached sink of this thread (time_reached.hpp).
#include "coupling/simulation.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "coupling/integrator_table.hpp"
#include "coupling/sundials_support.hpp"
#include "coupling/time_reached.hpp"

namespace ffrf::coupling {

namespace {

thread_local std::atomic<double>* time_reached_sink = nullptr;

// A fully prescribed system (a rigid boom on a driven hub without cargo) has no minimal coordinates:
// its motion is kinematics, sampled at the output times (the reactions follow from the driving
// constraint). The full-coordinate formulations still solve for the frame and its multipliers.
RunResult kinematic_run(CraneEquations& equations, const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  RunResult result;
  const Eigen::VectorXd none(0);
  const long outputs = std::lround(settings.duration / settings.output_interval);
  for (long k = 0; k <= outputs; ++k) {
    const double t = static_cast<double>(k) * settings.output_interval;
    result.time.push_back(t);
    result.samples.push_back(equations.minimal_outputs(t, none, none));
  }
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

RunResult dispatch(CraneEquations& equations, const Eigen::VectorXd& z0, const IntegratorSettings& settings) {
  if (!is_valid(settings.kind)) {
    throw SolverFailure(FailureKind::setup, "integrator", InvalidIntegrator(settings.kind).what(), 0.0,
                        "choose one of the valid formulation × solver pairs");
  }
  const IntegratorEntry& entry = integrator_entry(settings.kind);
  if (equations.minimal_size() == 0 && settings.kind.formulation == Formulation::minimal) return kinematic_run(equations, settings);
  return entry.integrate(equations, z0, settings);
}

}  // namespace

TimeReachedSink::TimeReachedSink(std::atomic<double>* time_reached) : previous_(time_reached_sink) {
  time_reached_sink = time_reached;
}

TimeReachedSink::~TimeReachedSink() { time_reached_sink = previous_; }

void store_time_reached(double t) noexcept {
  if (time_reached_sink != nullptr) time_reached_sink->store(t, std::memory_order_relaxed);
}

RunResult integrate(CraneEquations& equations, const Eigen::VectorXd& z0, const IntegratorSettings& settings) {
  RunResult result = dispatch(equations, z0, settings);
  result.detections = post_run_detections(result, settings.monitor);
  return result;
}

namespace sundials {

void Progress::update(double t) {
  store_time_reached(t);
  if (!enabled_) return;
  const int percent = static_cast<int>(100.0 * t / end_);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  std::fprintf(stderr, "\r%s: t = %7.2f / %.2f s (%3d %%)", label_, t, end_, percent);
  std::fflush(stderr);
}

void Progress::finish() {
  if (enabled_) std::fprintf(stderr, "\r\033[K");
}

}  // namespace sundials
}  // namespace ffrf::coupling
