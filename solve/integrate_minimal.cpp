// CVODE (variable-order BDF, Newton iteration) on the minimal-coordinate ODE y = (z, ż),
// ẏ = (ż, M_z⁻¹Q_z). The system's events are located by CVODE's root finding and recorded.
// Newton systems: the structured solve of solve/second_order_newton.hpp — S = M + γD + γ²K from
// the system's own blocks (SecondOrderSystem::minimal_jacobian: e.g. the crane's analytic elastic
// columns with differences of the residual for the hull and cargo columns only), bordered band for a nodal boom, dense for a
// modal one — instead of SUNDIALS' dense LU of the (2n)² I − γJ with a difference-quotient J.
// Outputs: the state at an output time is CVODE's interpolant, and the accelerations are its
// derivative (CVodeGetDky, k = 1), handed to the sink, so no right-hand side is evaluated per sample
// (docs/theory.md §8.1).
#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "solve/second_order_newton.hpp"
#include "solve/integration.hpp"
#include "solve/solver_steps.hpp"
#include "solve/sundials_support.hpp"

namespace ffrf::solve {
namespace {

struct OdeData {
  SecondOrderSystem* equations;
  int events;
  int size;
  sundials::CallbackGuard* guard;  // every callback runs inside it
};

int ode_rhs(sunrealtype t, N_Vector y, N_Vector y_dot, void* user) {
  auto* data = static_cast<OdeData*>(user);
  return (*data->guard)([&] {
    const auto state = sundials::Vector::view(y);
    auto rate = sundials::Vector::view(y_dot);
    if (!state.allFinite()) return 1;  // recoverable: CVODE retries with a smaller step
    const int n = data->size;
    rate.head(n) = state.tail(n);
    data->equations->minimal_accelerations(t, state.head(n), state.tail(n), rate.tail(n));
    return rate.allFinite() ? 0 : 1;
  });
}

// The structured Newton blocks at a state (solve/second_order_newton.hpp).
int newton_blocks(OdeData& data, double t, SecondOrderSystem::ConstRef z, SecondOrderSystem::ConstRef z_dot,
                  SecondOrderSystem::ConstRef z_ddot, SecondOrderJacobian& blocks) {
  return (*data.guard)([&] {
    if (!z.allFinite() || !z_dot.allFinite() || !z_ddot.allFinite()) return 1;
    data.equations->minimal_jacobian(t, z, z_dot, z_ddot, blocks);
    return 0;
  });
}

}  // namespace

IntegrationRecord integrate_minimal(SecondOrderSystem& equations, OutputSink& sink, const Eigen::VectorXd& z0,
                                    const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const int n = equations.minimal_size();
  sundials::Context context;
  sundials::Vector y(2 * n, context.ctx), tolerance(2 * n, context.ctx);
  sundials::start_at_rest(z0, equations.coordinate_scale(), settings.absolute_tolerance, y, tolerance);

  sundials::CallbackGuard guard("CVODE", settings.work);
  OdeData data{&equations, equations.event_count(), n, &guard};
  sundials::SecondOrderNewton newton(equations.minimal_structure(), context.ctx,
                                     [&data](double t, auto z, auto z_dot, auto z_ddot, SecondOrderJacobian& blocks) {
                                       return newton_blocks(data, t, z, z_dot, z_ddot, blocks);
                                     });
  sundials::LibraryMessage message;
  const sundials::SetupCheck check("CVODE", CVodeGetReturnFlagName, message);
  std::unique_ptr<void, void (*)(void*)> memory(CVodeCreate(CV_BDF, context.ctx), [](void* p) { CVodeFree(&p); });
  void* cvode = memory.get();
  check(cvode, "CVodeCreate");
  check(CVodeSetErrHandlerFn(cvode, sundials::LibraryMessage::handler, &message), "CVodeSetErrHandlerFn");
  check(CVodeInit(cvode, ode_rhs, 0.0, y.v), "CVodeInit");
  check(CVodeSVtolerances(cvode, settings.relative_tolerance, tolerance.v), "CVodeSVtolerances");
  check(CVodeSetUserData(cvode, &data), "CVodeSetUserData");
  check(CVodeSetLinearSolver(cvode, newton.solver(), newton.matrix()), "CVodeSetLinearSolver");
  check(CVodeSetLinSysFn(cvode, sundials::SecondOrderNewton::linear_system), "CVodeSetLinSysFn");
  check(CVodeSetMaxNumSteps(cvode, settings.max_steps), "CVodeSetMaxNumSteps");
  check(CVodeSetMaxOrd(cvode, settings.max_order), "CVodeSetMaxOrd");
  if (settings.work.min_step > 0.0) check(CVodeSetMinStep(cvode, settings.work.min_step), "CVodeSetMinStep");
  if (data.events > 0) {
    check(CVodeRootInit(cvode, data.events, sundials::minimal_event_root<OdeData>), "CVodeRootInit");
    CVodeSetNoInactiveRootWarn(cvode);
  }

  IntegrationRecord result;
  sundials::Vector derivative(2 * n, context.ctx);
  const auto record = [&](double t) {
    const auto state = y.map();
    result.time.push_back(t);
    // At t = 0 CVODE has no interpolant yet: the one sample that solves for the accelerations.
    if (t > 0.0 && CVodeGetDky(cvode, t, 1, derivative.v) == CV_SUCCESS) {
      sink.minimal_sample(t, state.head(n), state.tail(n), derivative.map().tail(n));
    } else {
      sink.minimal_sample(t, state.head(n), state.tail(n));
    }
  };
  const sundials::SolverSteps steps(cvode, sundials::cvode_calls, settings);
  sundials::sample_outputs_keeping_partial(
      result, settings, "cvode", CV_ROOT_RETURN,
      [&](double t_out, double& t) {
        if (!steps.allow_call()) return CV_TOO_MUCH_WORK;
        return CVode(cvode, t_out, y.v, &t, CV_NORMAL);
      },
      [&](int* directions) { steps.root_directions(directions); },
      [&](int flag, double t) {
        guard.rethrow(t);
        throw steps.failure("CVODE", flag, t, message.suffix(), result.stats);
      },
      record, data.events, result.events);

  sundials::cvode_statistics(cvode, 0, result.stats);
  result.stats.function_evaluations += result.stats.jacobian_evaluations * equations.minimal_jacobian_evaluations();
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::solve
