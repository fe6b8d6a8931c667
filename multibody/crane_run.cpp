// A crane run (multibody/crane_run.hpp): the crane's recorder as the integrators' output sink, the
// wire's events from the located events, and the partial run a failure carries.
#include "multibody/crane_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "solve/integrator_table.hpp"

namespace ffrf::multibody {
namespace {

// The crane's outputs at each output time, each watched as it is taken.
class CraneRecorder final : public solve::OutputSink {
 public:
  CraneRecorder(CraneEquations& equations, const MonitorLimits& limits, const char* solver, RunResult& result)
      : equations_(equations), watch_(limits, solver), result_(result) {}

  void minimal_sample(double t, ConstRef z, ConstRef z_dot) override { keep(t, equations_.minimal_outputs(t, z, z_dot)); }
  void minimal_sample(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot) override {
    keep(t, equations_.minimal_outputs_with_accelerations(t, z, z_dot, z_ddot));
  }
  void full_sample(double t, ConstRef q, ConstRef v, ConstRef lambda) override {
    keep(t, equations_.full_outputs(t, q, v, lambda));
  }

 private:
  void keep(double t, const CraneOutputs& sample) {
    result_.samples.push_back(sample);
    if (const BoomStressProfile* profile = equations_.boom_stress_profile()) result_.boom_stress.add(t, *profile);
    watch_.observe(t, result_.samples.back());
  }

  CraneEquations& equations_;
  DivergenceWatch watch_;
  RunResult& result_;
};

// The integration's record into the crane's result, with the wires' events (event function i is wire
// i's stretch), by the wires' roles: the hoist wire's, the luffing wires', the backstays'.
void take_record(solve::IntegrationRecord&& record, const CraneEquations& equations, RunResult& result) {
  static_cast<solve::IntegrationRecord&>(result) = std::move(record);
  result.wire_events.clear();
  result.luffing_events.clear();
  result.backstay_events.clear();
  result.wire_names.clear();
  for (int wire = 0; wire < equations.wire_count(); ++wire) result.wire_names.push_back(equations.wire_name(wire));
  for (const solve::Event& event : result.events) {
    const WireEvent wire_event{event.time, event.falling, event.index};
    switch (equations.wire_role(event.index)) {
      case WireRole::hoist: result.wire_events.push_back(wire_event); break;
      case WireRole::luffing: result.luffing_events.push_back(wire_event); break;
      case WireRole::backstay: result.backstay_events.push_back(wire_event); break;
    }
  }
}

}  // namespace

RunResult simulate(CraneEquations& equations, const Eigen::VectorXd& z0, const RunSettings& settings) {
  RunResult result;
  if (settings.output_interval > 0.0 && std::isfinite(settings.duration / settings.output_interval)) {
    result.samples.reserve(static_cast<std::size_t>(std::max(0L, std::lround(settings.duration / settings.output_interval))) + 1);
  }
  const std::string solver(solve::is_valid(settings.kind) ? solve::integrator_entry(settings.kind).label : "integrator");
  CraneRecorder recorder(equations, settings.monitor, solver.c_str(), result);
  try {
    take_record(solve::integrate(equations, recorder, z0, settings), equations, result);
  } catch (SolverFailure& failure) {
    if (failure.partial() != nullptr) {
      auto partial = std::make_shared<RunResult>();
      partial->samples = std::move(result.samples);
      partial->boom_stress = std::move(result.boom_stress);
      take_record(solve::IntegrationRecord(*failure.partial()), equations, *partial);
      failure.attach_partial(std::move(partial));
    }
    throw;
  }
  result.detections = post_run_detections(result, settings.monitor);
  return result;
}

std::shared_ptr<const RunResult> partial_run(const SolverFailure& failure) {
  return std::dynamic_pointer_cast<const RunResult>(failure.partial());
}

}  // namespace ffrf::multibody
