// How a run fails or what it runs into, by name: the failure kinds every run is watched for (the
// solvers' own, and those of the model's detectors, e.g. multibody/run_monitor.hpp: one catalogue,
// so that exit codes and the user guide come from one list), one detection (kind, time, cause with its numbers, remedy), and the
// exception a solver that could not finish throws — naming the kind, and carrying the samples up
// to the failure so a report can chart how it failed (never as if they were a complete run).
// Remedies are keyed by the failure kind and worded neutrally ("tighten the tolerances"); each names
// the adjustments it involves, which a front end maps to its own options (the command line to
// --rtol/--atol, ...). failure.cpp holds the names and the remedy table.
#pragma once

#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ffrf::solve {

enum class FailureKind {
  divergence,                  // deflection grew beyond its bound (or non-finite states)
  step_size_collapse,          // repeated error-test failures at the smallest step
  error_test_failures,         // many rejected steps (warning)
  newton_divergence,           // the nonlinear (Newton) iteration did not converge
  too_much_work,               // the step limit was reached
  constraint_drift,            // |C| beyond its bound (full coordinates)
  mass_not_positive_definite,  // loss of positive definiteness of the mass matrix
  unstable_explicit,           // an explicit step beyond the stability limit
  wire_slack,                  // the wire went slack
  luffing_slack,               // a luffing wire went slack: the boom hung on its heel pin alone
  backstay_slack,              // a backstay went slack: the A-frame swung on its deck pin
  snap_load,                   // the wire snapped taut again after slack
  buckling,                    // compression near or beyond the boom's Euler load
  capsize,                     // the hull pitched past 90°
  deck_submerged,              // a deck edge went under water (no green water or flooding modelled)
  cargo_in_water,              // the cargo dipped into the water (no water forces on it modelled)
  cargo_overturned,            // the cargo pitched past the limit (90°) about its hook
  model_error,                 // the model refused a state (e.g. a hull out of the water)
  setup,                       // invalid settings or a solver set-up failure
};
std::string_view to_string(FailureKind kind);  // "divergence", "step-size collapse", ...
// Every kind, in declaration order (the user guide lists each: tests/app/test_user_guide_errors.cpp).
inline constexpr FailureKind all_failure_kinds[] = {
    FailureKind::divergence,     FailureKind::step_size_collapse, FailureKind::error_test_failures,
    FailureKind::newton_divergence, FailureKind::too_much_work,   FailureKind::constraint_drift,
    FailureKind::mass_not_positive_definite, FailureKind::unstable_explicit, FailureKind::wire_slack,
    FailureKind::luffing_slack,  FailureKind::backstay_slack,
    FailureKind::snap_load,      FailureKind::buckling,           FailureKind::capsize,
    FailureKind::deck_submerged, FailureKind::cargo_in_water,     FailureKind::cargo_overturned,
    FailureKind::model_error,    FailureKind::setup,
};

// What a user can change about a run, in neutral words.
enum class Adjustment {
  tolerances,        // the relative and absolute tolerances
  fixed_step,        // the fixed step of a fixed-step solver
  step_limit,        // the largest number of steps of a run
  wall_clock_limit,  // the largest wall-clock time of a run
  step_floor,        // the smallest step an adaptive solver may take
  solver,            // the time integrator (bdf, explicit-rk, generalized-alpha)
  formulation,       // the constraint formulation (minimal coordinates, Lagrange multipliers ...)
  stiffening,        // geometric stiffening of the boom
  model_size,        // elements or modes of the boom
  scene_values,      // the scene's physical values (loads, masses, stiffnesses, the sea)
};
inline constexpr Adjustment all_adjustments[] = {
    Adjustment::tolerances, Adjustment::fixed_step, Adjustment::step_limit,  Adjustment::wall_clock_limit,
    Adjustment::step_floor, Adjustment::solver,     Adjustment::formulation, Adjustment::stiffening,
    Adjustment::model_size, Adjustment::scene_values,
};
std::string_view to_string(Adjustment adjustment);  // "the tolerances", ...

// What to try after a failure of this kind, in neutral words (no option names), and the
// adjustments it involves.
std::string_view remedy(FailureKind kind);
std::vector<Adjustment> adjustments(FailureKind kind);

struct Detection {
  FailureKind kind;
  double time = 0.0;   // when [s]
  bool fatal = false;  // the run stopped there
  std::string cause;   // what happened, with the numbers
  std::string remedy;  // what to try
  double value = 0.0;  // the number behind it: growth rate [1/s], peak tension [N], drift [m], load ratio [-]
};

struct IntegrationRecord;  // solve/integration.hpp

// A solver that could not finish: which solver, which failure, what, when, and what to try.
class SolverFailure : public std::runtime_error {
 public:
  // The remedy of the kind (remedy(kind)) ...
  SolverFailure(FailureKind kind, std::string solver, std::string cause, double time);
  // ... or a specific one (neutral words, e.g. with the number to aim for).
  SolverFailure(FailureKind kind, std::string solver, std::string cause, double time, std::string remedy,
                double value = 0.0);
  FailureKind kind() const { return kind_; }
  const std::string& solver() const { return solver_; }
  const std::string& cause() const { return cause_; }
  double time() const { return time_; }
  const std::string& remedy() const { return remedy_; }
  double value() const { return value_; }
  std::vector<Adjustment> adjustments() const { return solve::adjustments(kind_); }
  Detection detection() const { return {kind_, time_, true, cause_, remedy_, value_}; }
  // The run up to the failure (may be null): the integrator attaches its IntegrationRecord, and the
  // system's run function replaces it with its own result type, which extends IntegrationRecord
  // with the samples (e.g. multibody::partial_run).
  const std::shared_ptr<const IntegrationRecord>& partial() const { return partial_; }
  void attach_partial(std::shared_ptr<const IntegrationRecord> partial) { partial_ = std::move(partial); }

 private:
  FailureKind kind_;
  std::string solver_, cause_, remedy_;
  double time_, value_;
  std::shared_ptr<const IntegrationRecord> partial_;
};

// The failure kind of an exception the model threw inside a solver callback.
FailureKind model_failure_kind(const std::exception& error);

}  // namespace ffrf::solve
