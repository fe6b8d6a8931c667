// Settings, results and failures of a crane run: which integrator with which tolerances, the
// sampled outputs, the solver statistics every run must record, and the wire's slack/taut events.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "coupling/crane_equations.hpp"

namespace ffrf::coupling {

enum class Integrator { ida, cvode };
std::string_view to_string(Integrator integrator);
std::optional<Integrator> parse_integrator(std::string_view text);
std::string integrator_choices();  // "ida|cvode"

struct IntegratorSettings {
  Integrator kind = Integrator::cvode;
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-8;  // scaled by CraneEquations::coordinate_scale()
  double duration = 120.0;           // [s]
  double output_interval = 0.05;     // [s]
  long max_steps = 500000;
  bool progress = false;             // print progress on stderr (callers set it for terminals only)
};

struct SolverStats {
  long steps = 0;
  long function_evaluations = 0;   // RHS (CVODE) or residual (IDA), including those for Jacobians
  long jacobian_evaluations = 0;
  long newton_iterations = 0;
  long error_test_failures = 0;
  long convergence_failures = 0;
  double wall_seconds = 0.0;
};

struct WireEvent {
  double time;
  bool slack;  // true: went slack (ℓ ↓ L0); false: became taut again
};

struct RunResult {
  std::vector<double> time;
  std::vector<CraneOutputs> samples;
  SolverStats stats;
  std::vector<WireEvent> wire_events;
};

// A solver that could not finish: which solver, what failed, when, and what to try.
class SolverFailure : public std::runtime_error {
 public:
  SolverFailure(std::string solver, std::string cause, double time, std::string remedy);
  const std::string& solver() const { return solver_; }
  const std::string& cause() const { return cause_; }
  double time() const { return time_; }
  const std::string& remedy() const { return remedy_; }

 private:
  std::string solver_, cause_, remedy_;
  double time_;
};

// CVODE (BDF, Newton, dense Jacobian) on the minimal-coordinate ODE from z0 (ż0 = 0).
RunResult integrate_minimal(CraneEquations& equations, const Eigen::VectorXd& z0, const IntegratorSettings& settings);
// IDA on the stabilized index-2 (Gear–Gupta–Leimkuhler) DAE in full coordinates from z0 at rest.
RunResult integrate_lagrange(CraneEquations& equations, const Eigen::VectorXd& z0, const IntegratorSettings& settings);
// Dispatch on settings.kind.
RunResult integrate(CraneEquations& equations, const Eigen::VectorXd& z0, const IntegratorSettings& settings);

}  // namespace ffrf::coupling
