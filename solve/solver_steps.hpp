// The run's step budget and the failure a solver's error flag means, handled the same way by the
// CVODE, IDA and ARKODE (ERKStep) adapters: each solver's step functions have one shape
// (CVodeGetNumSteps / IDAGetNumSteps / ERKStepGetNumSteps, ...), so one object does the per-call
// step limit within the run's limit (WorkLimits::max_steps), the events' directions after a root
// return, and the failure with the steps taken so far and the step last attempted.
#pragma once

#include <sundials/sundials_types.h>

#include <string>

#include "solve/integration.hpp"

namespace ffrf::solve::sundials {

// The solver's own flag values for too much work, a repeated error-test failure and a repeated
// Newton convergence failure.
struct SolverFlags {
  int too_much_work, error_test_failure, convergence_failure;
};

// One SUNDIALS integrator's functions for steps, roots and flag names.
struct SolverCalls {
  int (*get_num_steps)(void*, long*);
  int (*set_max_num_steps)(void*, long);
  int (*get_current_step)(void*, sunrealtype*);
  int (*get_root_info)(void*, int*);
  char* (*return_flag_name)(long);
  SolverFlags flags;
};

// The steps the next solver call may take: the per-output-interval limit, within what is left of
// the run's step limit; 0 when the run's limit is spent (the adapter then reports the solver's
// too-much-work flag without calling it: a call allowed even one step could reach its output time).
long call_step_limit(const IntegratorSettings& settings, long steps_so_far);

// What a solver's error flag means: the failure kind from the solver's own flag values, the cause
// (the flag's name, the step limit that was reached, or the step-size floor the step fell to), and
// the remedy of the kind. `last_step`: the step size last attempted.
SolverFailure solver_failure(const std::string& solver, const IntegratorSettings& settings, int flag,
                             const std::string& flag_text, SolverFlags flags, long steps, double last_step, double t);

// A running solver's steps (`memory`: CVODE's, IDA's or ERKStep's memory).
class SolverSteps {
 public:
  SolverSteps(void* memory, const SolverCalls& calls, const IntegratorSettings& settings)
      : memory_(memory), calls_(calls), settings_(settings) {}
  // Before each solver call: sets the call's step limit and returns true; false when the run's
  // step limit is spent (return the solver's too-much-work flag instead of calling it).
  bool allow_call() const;
  // After a root return: per event function, the direction of its crossing (< 0: falling, > 0:
  // rising, 0: none), into directions[0 .. event_count).
  void root_directions(int* directions) const;
  // The flag's name as SUNDIALS spells it (CV_TOO_MUCH_WORK, ...).
  std::string flag_name(int flag) const;
  // After a failed call at t: the steps taken so far into `stats` (the partial result's statistics),
  // and the failure the flag means; `library_message`: SUNDIALS' own message, appended to the cause.
  SolverFailure failure(const std::string& solver, int flag, double t, const std::string& library_message,
                        SolverStats& stats) const;

 private:
  void* memory_;
  SolverCalls calls_;
  const IntegratorSettings& settings_;
};

// CVODE's functions (the minimal-coordinate and the index-1 adapters).
extern const SolverCalls cvode_calls;

}  // namespace ffrf::solve::sundials
