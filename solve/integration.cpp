// Dispatch to the integrator of a run (its row in integrator_table.cpp), the terminal progress line and
// the time-reached sink of this thread (time_reached.hpp).
#include "solve/integration.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "solve/integrator_table.hpp"
#include "solve/stop_request.hpp"
#include "solve/sundials_support.hpp"
#include "solve/time_reached.hpp"

namespace ffrf::solve {

namespace {

// A fully prescribed system (e.g. a rigid boom on a driven hub without cargo) has no minimal
// coordinates: its motion is kinematics, sampled at the output times (the reactions follow from the
// driving constraint). The full-coordinate formulations still solve for the frame and its multipliers.
IntegrationRecord kinematic_run(OutputSink& sink, const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  IntegrationRecord result;
  const Eigen::VectorXd none(0);
  const long outputs = std::lround(settings.duration / settings.output_interval);
  try {
    for (long k = 0; k <= outputs; ++k) {
      const double t = static_cast<double>(k) * settings.output_interval;
      throw_if_stop_requested();
      result.time.push_back(t);
      sink.minimal_sample(t, none, none);
    }
  } catch (SolverFailure& failure) {  // a watch on a sample: the samples so far
    failure.attach_partial(std::make_shared<const IntegrationRecord>(result));
    throw;
  }
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

IntegrationRecord integrate(SecondOrderSystem& system, OutputSink& sink, const Eigen::VectorXd& z0,
                            const IntegratorSettings& settings) {
  if (!is_valid(settings.kind)) {
    throw SolverFailure(FailureKind::setup, "integrator", InvalidIntegrator(settings.kind).what(), 0.0,
                        "choose one of the valid formulation × solver pairs");
  }
  // The solvers hold constraint- and event-sized values in storage of fixed capacity.
  if (system.constraint_count() > max_constraints || system.event_count() > max_events) {
    throw SolverFailure(FailureKind::setup, "integrator",
                        "the system has " + std::to_string(system.constraint_count()) + " constraints and " +
                            std::to_string(system.event_count()) + " event functions; the solvers hold at most " +
                            std::to_string(max_constraints) + " and " + std::to_string(max_events),
                        0.0, "raise solve::max_constraints or solve::max_events (solve/second_order_system.hpp)");
  }
  const IntegratorEntry& entry = integrator_entry(settings.kind);
  if (system.minimal_size() == 0 && settings.kind.formulation == Formulation::minimal) return kinematic_run(sink, settings);
  return entry.integrate(system, sink, z0, settings);
}

namespace {
thread_local std::atomic<double>* time_reached_sink = nullptr;
}  // namespace

TimeReachedSink::TimeReachedSink(std::atomic<double>* time_reached) : previous_(time_reached_sink) {
  time_reached_sink = time_reached;
}

TimeReachedSink::~TimeReachedSink() { time_reached_sink = previous_; }

void store_time_reached(double t) noexcept {
  if (time_reached_sink != nullptr) time_reached_sink->store(t, std::memory_order_relaxed);
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
}  // namespace ffrf::solve
