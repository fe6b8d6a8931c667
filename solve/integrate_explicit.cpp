// ARKODE ERKStep (explicit Runge–Kutta, Zonneveld 4(3), ARKODE_ZONNEVELD_5_3_4) on the
// minimal-coordinate ODE y = (z, ż), ẏ = (ż, M_z⁻¹Q_z): adaptive with the tolerances, or with a
// fixed step (outputs from ARKODE's Hermite interpolant). The system's events by root finding.
// Fixed-step runs beyond the explicit stability limit grow without bound; a per-step check stops
// them before overflow: the kinetic energy must stay below 10⁶ × (E_ref + E_floor), E_ref the kinetic
// energy at the first output, E_floor = ½ Σ M_ii (1 s⁻¹)² (every coordinate moving at one unit per
// second). The failure names the linearized stability limit (explicit_stable_step).
// Adaptive runs on a stiff model take steps bound by stability (h ≤ h*), not accuracy: before the
// first step, the linearized limit h* (for models up to stiff_check_max_size coordinates: a dense
// eigenproblem of size 2n) gives the steps the run needs, N ≈ duration / h*; during the run, the
// mean step of the steps taken so far does, every stiff_check_interval steps. A run that needs more
// than stiff_steps_per_output steps per output interval (steps set by the boom's fastest modes, not
// by the motion the outputs resolve) stops at once as too much work naming h* and N: an implicit
// solver's steps follow the motion instead. (A run that merely needs more steps than its step limit
// runs into the limit and keeps its samples, as every integrator does.)
#include <arkode/arkode_erkstep.h>

#include <Eigen/Eigenvalues>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <string>

#include "solve/erk_stability_region.hpp"
#include "solve/integration.hpp"
#include "solve/solver_steps.hpp"
#include "solve/sundials_support.hpp"
#include "linalg/dense_solvers.hpp"

namespace ffrf::solve {
namespace {

constexpr double energy_growth_bound = 1e6;
constexpr int stiff_check_max_size = 300;
constexpr long stiff_check_interval = 1000;
constexpr double stiff_steps_per_output = 1000.0;
constexpr const char* solver_name = "ARKODE ERK";
const sundials::SolverCalls erk_calls{ERKStepGetNumSteps,  ERKStepSetMaxNumSteps,    ERKStepGetCurrentStep,
                                      ERKStepGetRootInfo,  ERKStepGetReturnFlagName, {ARK_TOO_MUCH_WORK, ARK_ERR_FAILURE, ARK_CONV_FAILURE}};

struct ErkData {
  SecondOrderSystem* equations;
  int size;
  int events = 0;
  double energy_bound = std::numeric_limits<double>::infinity();
  double energy_reference = 0.0;  // E_ref + E_floor
  double diverged_energy = 0.0, diverged_time = 0.0;
  sundials::CallbackGuard* guard = nullptr;  // every callback runs inside it
  // Adaptive steps: the stiffness watch (see the file comment).
  double output_interval = 0.0;
  long steps = 0;
  double stiff_mean_step = 0.0;  // > 0: the watch stopped the run with this mean step [s]
};

// Steps finer than the output interval by more than stiff_steps_per_output.
bool stiff_for_explicit(const ErkData& data, double step) { return data.output_interval / step > stiff_steps_per_output; }

// After every adaptive step: the mean step so far against the run's needs.
int stiffness_watch(sunrealtype t, N_Vector, void* user) {
  auto* data = static_cast<ErkData*>(user);
  if (++data->steps % stiff_check_interval != 0 || !(t > 0.0)) return 0;
  const double mean_step = t / static_cast<double>(data->steps);
  if (!stiff_for_explicit(*data, mean_step)) return 0;
  data->stiff_mean_step = mean_step;
  return 1;
}

int erk_rhs(sunrealtype t, N_Vector y, N_Vector y_dot, void* user) {
  auto* data = static_cast<ErkData*>(user);
  return (*data->guard)([&] {
    const auto state = sundials::Vector::view(y);
    auto rate = sundials::Vector::view(y_dot);
    const int n = data->size;
    if (!state.allFinite()) return 1;  // recoverable: adaptive ERK retries with a smaller step
    rate.head(n) = state.tail(n);
    data->equations->minimal_accelerations(t, state.head(n), state.tail(n), rate.tail(n));
    return rate.allFinite() ? 0 : 1;
  });
}

// After every fixed step: stop when the kinetic energy leaves the bound (or is not finite).
int energy_watch(sunrealtype t, N_Vector y, void* user) {
  auto* data = static_cast<ErkData*>(user);
  return (*data->guard)([&] {
    const auto state = sundials::Vector::view(y);
    const int n = data->size;
    const double energy = state.allFinite() ? data->equations->minimal_kinetic_energy(t, state.head(n), state.tail(n))
                                            : std::numeric_limits<double>::infinity();
    if (std::isfinite(energy) && energy <= data->energy_bound) return 0;
    data->diverged_energy = energy;
    data->diverged_time = t;
    return 1;
  });
}

}  // namespace

double explicit_stable_step(SecondOrderSystem& equations, const Eigen::VectorXd& z0) {
  const int n = equations.minimal_size();
  // A system with nothing free to move (a rigid boom on a driven hub) sets no step limit.
  if (n == 0) return std::numeric_limits<double>::infinity();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * n), f0(2 * n), f1(2 * n);
  y.head(n) = z0;
  const Eigen::VectorXd scale = equations.coordinate_scale();
  const auto rhs = [&](const Eigen::VectorXd& state, Eigen::VectorXd& rate) {
    rate.head(n) = state.tail(n);
    equations.minimal_accelerations(0.0, state.head(n), state.tail(n), rate.tail(n));
  };
  rhs(y, f0);
  Eigen::MatrixXd jacobian(2 * n, 2 * n);
  for (int j = 0; j < 2 * n; ++j) {
    const double increment = 1e-7 * std::max(std::abs(y(j)), scale(j % n));
    const double saved = y(j);
    y(j) = saved + increment;
    rhs(y, f1);
    jacobian.col(j) = (f1 - f0) / increment;
    y(j) = saved;
  }
  const Eigen::VectorXcd eigenvalues = Eigen::EigenSolver<Eigen::MatrixXd>(jacobian, false).eigenvalues();
  const double largest = eigenvalues.cwiseAbs().maxCoeff();
  double limit = std::numeric_limits<double>::infinity();
  for (const std::complex<double> mu : eigenvalues) {
    if (std::abs(mu) < 1e-2 * largest) continue;  // slow modes never bind
    limit = std::min(limit, explicit_ray_boundary(mu) / std::abs(mu));
  }
  return limit;
}

double explicit_imaginary_axis_boundary() { return explicit_ray_boundary({0.0, 1.0}); }

IntegrationRecord integrate_explicit(SecondOrderSystem& equations, OutputSink& sink, const Eigen::VectorXd& z0,
                                     const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const int n = equations.minimal_size();
  const bool fixed = settings.fixed_step > 0.0;
  if (settings.fixed_step < 0.0 || !std::isfinite(settings.fixed_step)) {
    throw SolverFailure(FailureKind::setup, solver_name, "invalid fixed step " + std::to_string(settings.fixed_step), 0.0,
                        "give a fixed step > 0, or 0 for adaptive steps");
  }
  sundials::Context context;
  sundials::Vector y(2 * n, context.ctx), tolerance(2 * n, context.ctx);
  sundials::start_at_rest(z0, equations.coordinate_scale(), settings.absolute_tolerance, y, tolerance);

  sundials::CallbackGuard guard(solver_name, settings.work);
  ErkData data{&equations, n};
  data.events = equations.event_count();
  data.guard = &guard;
  data.output_interval = settings.output_interval;
  // Explicit RK on a stiff model: the steps it would need, named with the limit that sets them.
  const auto too_stiff = [&](double t, double step_limit, const std::string& measured) {
    char cause[400];
    std::snprintf(cause, sizeof cause,
                  "the explicit step limit ~%.2g s (%s) needs ~%.2g steps over %g s, %.2g per output interval of %g s: "
                  "explicit RK's steps are bound by the model's fastest modes, not by its motion",
                  step_limit, measured.c_str(), settings.duration / step_limit, settings.duration,
                  settings.output_interval / step_limit, settings.output_interval);
    return SolverFailure(FailureKind::too_much_work, solver_name, cause, t,
                         "use cvode (implicit BDF: its steps follow the motion), or fewer elements or modes", step_limit);
  };
  {
    Eigen::VectorXd q(equations.full_size()), v(equations.full_size());
    equations.full_from_minimal(0.0, z0, Eigen::VectorXd::Zero(n), q, v);
    data.energy_reference = 0.5 * equations.full_mass_matrix(q).diagonal().sum();  // E_floor
    data.energy_bound = energy_growth_bound * data.energy_reference;
  }
  sundials::LibraryMessage message;
  const sundials::SetupCheck check(solver_name, ERKStepGetReturnFlagName, message);
  std::unique_ptr<void, void (*)(void*)> memory(ERKStepCreate(erk_rhs, 0.0, y.v, context.ctx),
                                               [](void* p) { ERKStepFree(&p); });
  void* erk = memory.get();
  check(erk, "ERKStepCreate");
  check(ERKStepSetErrHandlerFn(erk, sundials::LibraryMessage::handler, &message), "ERKStepSetErrHandlerFn");
  check(ERKStepSVtolerances(erk, settings.relative_tolerance, tolerance.v), "ERKStepSVtolerances");
  check(ERKStepSetTableNum(erk, explicit_table_id), "ERKStepSetTableNum");
  check(ERKStepSetUserData(erk, &data), "ERKStepSetUserData");
  check(ERKStepSetMaxNumSteps(erk, settings.max_steps), "ERKStepSetMaxNumSteps");
  if (!fixed && settings.work.min_step > 0.0) check(ERKStepSetMinStep(erk, settings.work.min_step), "ERKStepSetMinStep");
  if (data.events > 0) check(ERKStepRootInit(erk, data.events, sundials::minimal_event_root<ErkData>), "ERKStepRootInit");
  if (fixed) {
    check(ERKStepSetFixedStep(erk, settings.fixed_step), "ERKStepSetFixedStep");
    check(ERKStepSetPostprocessStepFn(erk, energy_watch), "ERKStepSetPostprocessStepFn");
  } else {
    check(ERKStepSetPostprocessStepFn(erk, stiffness_watch), "ERKStepSetPostprocessStepFn");
  }
  if (data.events > 0) ERKStepSetNoInactiveRootWarn(erk);
  if (!fixed && n <= stiff_check_max_size) {  // before the first step: the linearized limit
    const double limit = explicit_stable_step(equations, z0);
    if (stiff_for_explicit(data, limit)) throw too_stiff(0.0, limit, "the linearized system's fastest eigenvalue");
  }

  IntegrationRecord result;
  result.stats.step = fixed ? settings.fixed_step : 0.0;
  const auto unstable = [&](double t, double energy) {
    const double limit = explicit_stable_step(equations, z0);
    char cause[320];
    if (!fixed) {
      std::snprintf(cause, sizeof cause, "unstable: the solution grew without bound with adaptive steps (kinetic energy %.3g J)", energy);
      return SolverFailure(FailureKind::unstable_explicit, solver_name, cause, t,
                           "use an implicit solver (bdf) or tighten the tolerances");
    }
    std::snprintf(cause, sizeof cause,
                  "unstable: the step h = %.3g s exceeds the explicit stability limit ≈ %.3g s of the linearized system "
                  "(kinetic energy grew to %.3g J, %.3g × its reference %.3g J)",
                  settings.fixed_step, limit, energy, energy / data.energy_reference, data.energy_reference);
    char remedy[320];
    std::snprintf(remedy, sizeof remedy,
                  "reduce the fixed step below ≈ %.3g s (≈ %.2f/ω_max for undamped modes), use fewer elements or "
                  "modes, or an implicit solver (bdf)",
                  limit, explicit_imaginary_axis_boundary());
    return SolverFailure(FailureKind::unstable_explicit, solver_name, cause, t, remedy, limit);
  };
  const auto record = [&](double t) {
    const auto state = y.map();
    const double energy = equations.minimal_kinetic_energy(t, state.head(n), state.tail(n));
    if (!state.allFinite() || !(energy <= data.energy_bound)) throw unstable(t, energy);
    result.time.push_back(t);
    sink.minimal_sample(t, state.head(n), state.tail(n));
    return energy;
  };
  const auto record_and_calibrate = [&](double t) {
    const double energy = record(t);
    if (result.time.size() == 2) {  // E_ref: the kinetic energy at the first output
      data.energy_reference += energy;
      data.energy_bound = energy_growth_bound * data.energy_reference;
    }
  };
  const sundials::SolverSteps steps(erk, erk_calls, settings);
  sundials::sample_outputs_keeping_partial(
      result, settings, solver_name, ARK_ROOT_RETURN,
      [&](double t_out, double& t) {
        if (!steps.allow_call()) return ARK_TOO_MUCH_WORK;
        return ERKStepEvolve(erk, t_out, y.v, &t, ARK_NORMAL);
      },
      [&](int* directions) { steps.root_directions(directions); },
      [&](int flag, double t) {
        if (flag == ARK_POSTPROCESS_STEP_FAIL && data.stiff_mean_step > 0.0) {
          throw too_stiff(t, data.stiff_mean_step, "the mean of the first " + std::to_string(data.steps) + " steps");
        }
        if (flag == ARK_POSTPROCESS_STEP_FAIL && !guard.failed()) throw unstable(data.diverged_time, data.diverged_energy);
        guard.rethrow(t);
        if (fixed && flag != ARK_TOO_MUCH_WORK) throw unstable(t, std::numeric_limits<double>::infinity());
        SolverFailure failure = steps.failure(solver_name, flag, t, message.suffix(), result.stats);
        if (failure.kind() != FailureKind::too_much_work) throw failure;
        // Explicit RK on a stiff model takes steps bounded by stability, not accuracy: say which.
        char remedy[400];
        std::snprintf(remedy, sizeof remedy,
                      "explicit RK on a stiff model takes steps bounded by stability, not accuracy (the linearized "
                      "stability limit is ≈ %.3g s): use an implicit solver (bdf), fewer elements or modes, or raise "
                      "the step or wall-clock limit",
                      explicit_stable_step(equations, z0));
        throw SolverFailure(FailureKind::too_much_work, solver_name, failure.cause(), t, remedy);
      },
      record_and_calibrate, data.events, result.events);

  ERKStepGetNumSteps(erk, &result.stats.steps);
  ERKStepGetNumRhsEvals(erk, &result.stats.function_evaluations);
  ERKStepGetNumErrTestFails(erk, &result.stats.error_test_failures);
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::solve
