// The step budget and solver-flag failures shared by the SUNDIALS integrator adapters
// (solve/solver_steps.hpp).
#include "solve/solver_steps.hpp"

#include <cvode/cvode.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "solve/sundials_support.hpp"

namespace ffrf::solve::sundials {

long call_step_limit(const IntegratorSettings& settings, long steps_so_far) {
  return std::max(0L, std::min(settings.max_steps, settings.work.max_steps - steps_so_far));
}

SolverFailure solver_failure(const std::string& solver, const IntegratorSettings& settings, int flag,
                             const std::string& flag_text, SolverFlags flags, long steps, double last_step, double t) {
  char cause[320];
  if (flag == flags.too_much_work) {
    if (steps >= settings.work.max_steps) {
      std::snprintf(cause, sizeof cause, "%s: the run's step limit of %ld steps was reached", flag_text.c_str(),
                    settings.work.max_steps);
    } else {
      std::snprintf(cause, sizeof cause, "%s: more than %ld steps within one output interval (%ld steps in all)",
                    flag_text.c_str(), settings.max_steps, steps);
    }
    return {FailureKind::too_much_work, solver, cause, t};
  }
  const bool at_floor = settings.work.min_step > 0.0 && std::abs(last_step) <= settings.work.min_step * (1.0 + 1e-6);
  if ((flag == flags.error_test_failure || flag == flags.convergence_failure) && at_floor) {
    std::snprintf(cause, sizeof cause, "%s: the step fell to the step-size floor %.3g s and failed there",
                  flag_text.c_str(), settings.work.min_step);
    return {FailureKind::step_size_collapse, solver, cause, t};
  }
  if (flag == flags.error_test_failure) return {FailureKind::step_size_collapse, solver, flag_text, t};
  if (flag == flags.convergence_failure) return {FailureKind::newton_divergence, solver, flag_text, t};
  return {FailureKind::model_error, solver, flag_text, t};
}

bool SolverSteps::allow_call() const {
  long steps = 0;
  calls_.get_num_steps(memory_, &steps);
  const long allowed = call_step_limit(settings_, steps);
  if (allowed == 0) return false;
  calls_.set_max_num_steps(memory_, allowed);
  return true;
}

void SolverSteps::root_directions(int* directions) const { calls_.get_root_info(memory_, directions); }

std::string SolverSteps::flag_name(int flag) const {
  return sundials::flag_name(calls_.return_flag_name(flag));
}

SolverFailure SolverSteps::failure(const std::string& solver, int flag, double t, const std::string& library_message,
                                   SolverStats& stats) const {
  long steps = 0;
  sunrealtype last_step = 0.0;
  calls_.get_num_steps(memory_, &steps);
  stats.steps = steps;
  calls_.get_current_step(memory_, &last_step);
  return solver_failure(solver, settings_, flag, flag_name(flag) + library_message, calls_.flags, steps, last_step, t);
}

const SolverCalls cvode_calls{CVodeGetNumSteps,       CVodeSetMaxNumSteps,   CVodeGetCurrentStep,
                              CVodeGetRootInfo,       CVodeGetReturnFlagName, {CV_TOO_MUCH_WORK, CV_ERR_FAILURE, CV_CONV_FAILURE}};

}  // namespace ffrf::solve::sundials
