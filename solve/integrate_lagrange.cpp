// IDA (variable-order BDF for DAEs) on a system in full coordinates with its constraints, in the stabilized index-2 form of Gear, Gupta & Leimkuhler (1985):
//   q̇ − v + C_qᵀμ = 0,   M(q) v̇ − Q(q, v, t) + C_qᵀλ = 0,   C(q, t) = 0,   C_q v + C_t = 0,
// with λ, μ algebraic and excluded from the error test (IDASetSuppressAlg). μ vanishes on the
// exact solution and keeps the position constraint from drifting. Consistent initial values come
// from the augmented system [M C_qᵀ; C_q 0][v̇; λ] = [Q; −(C_q v)_q v].
// Newton systems: the structured solve of solve/ida_newton.hpp (bordered band, linear in the
// element count). Outputs: λ at an output time from the state and IDA's interpolated v̇ (IDAGetDky),
// by least squares on C_qᵀλ = Q − M v̇ — no solve per sample.
#include <ida/ida.h>
#include <ida/ida_ls.h>

#include <chrono>
#include <cmath>
#include <string>

#include "solve/constrained_newton.hpp"
#include "solve/ida_newton.hpp"
#include "solve/integration.hpp"
#include "solve/solver_steps.hpp"
#include "solve/sundials_support.hpp"

namespace ffrf::solve {
namespace {

const sundials::SolverCalls ida_calls{IDAGetNumSteps,  IDASetMaxNumSteps,    IDAGetCurrentStep,
                                     IDAGetRootInfo,  IDAGetReturnFlagName, {IDA_TOO_MUCH_WORK, IDA_ERR_FAIL, IDA_CONV_FAIL}};

struct DaeData {
  SecondOrderSystem* equations;
  int events;
  int size;                  // nq
  int constraints;           // m
  Eigen::MatrixXd jacobian;  // C_q workspace (m × nq)
  Eigen::VectorXd forces, mass_times, c, c_t;
  sundials::CallbackGuard* guard;  // every callback runs inside it
};

int dae_residual(sunrealtype t, N_Vector y, N_Vector y_dot, N_Vector r, void* user) {
  auto* d = static_cast<DaeData*>(user);
  return (*d->guard)([&] {
    if (!sundials::Vector::view(y).allFinite()) return 1;
    const int n = d->size, constraints = d->constraints;
    const auto s = sundials::Vector::view(y);
    const auto s_dot = sundials::Vector::view(y_dot);
    auto res = sundials::Vector::view(r);
    const auto q = s.head(n), v = s.segment(n, n), lambda = s.segment(2 * n, constraints), mu = s.tail(constraints);
    d->equations->constraint_jacobian(q, d->jacobian);
    res.head(n) = s_dot.head(n) - v + d->jacobian.transpose() * mu;
    d->equations->full_mass_times(q, s_dot.segment(n, n), d->mass_times);
    d->equations->full_forces(t, q, v, d->forces);
    res.segment(n, n) = d->mass_times - d->forces + d->jacobian.transpose() * lambda;
    d->equations->constraint(t, q, d->c);
    res.segment(2 * n, constraints) = d->c;
    d->equations->constraint_time_derivative(t, d->c_t);
    res.tail(constraints).noalias() = d->jacobian * v;
    res.tail(constraints) += d->c_t;
    return res.allFinite() ? 0 : 1;
  });
}

int dae_jacobian(double t, double cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix J, void* user, N_Vector t1,
                 N_Vector t2, N_Vector t3) {
  auto* d = static_cast<DaeData*>(user);
  return (*d->guard)([&] { return sundials::IndexTwoNewton::jacobian(t, cj, y, yp, r, J, user, t1, t2, t3); });
}

int event_root(sunrealtype t, N_Vector y, N_Vector, sunrealtype* g, void* user) {  // IDA's signature
  return sundials::full_event_root<DaeData>(t, y, g, user);
}

}  // namespace

IntegrationRecord integrate_lagrange(SecondOrderSystem& equations, OutputSink& sink, const Eigen::VectorXd& z0,
                                     const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const int n = equations.full_size();
  const int constraints = equations.constraint_count();
  const int total = 2 * n + 2 * constraints;
  sundials::Context context;
  sundials::Vector y(total, context.ctx), y_dot(total, context.ctx), tolerance(total, context.ctx), id(total, context.ctx);
  sundials::CallbackGuard guard("IDA", settings.work);
  DaeData data{&equations, equations.event_count(), n, constraints, Eigen::MatrixXd(constraints, n), Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(constraints), Eigen::VectorXd(constraints), &guard};

  // Consistent initial values at rest.
  auto s = y.map();
  auto s_dot = y_dot.map();
  s.setZero();
  s_dot.setZero();
  equations.full_from_minimal(0.0, z0, Eigen::VectorXd::Zero(z0.size()), s.head(n), s.segment(n, n));
  consistent_accelerations(equations, 0.0, s.head(n), s.segment(n, n), s_dot.segment(n, n), s.segment(2 * n, constraints));
  s_dot.head(n) = s.segment(n, n);

  // Tolerances and the differential/algebraic split.
  const Eigen::VectorXd full_scale = full_coordinate_scale(equations);
  auto tol = tolerance.map();
  tol.head(n) = settings.absolute_tolerance * full_scale;
  tol.segment(n, n) = settings.absolute_tolerance * full_scale;
  tol.tail(2 * constraints).setConstant(1.0);
  auto kind = id.map();
  kind.head(2 * n).setOnes();
  kind.tail(2 * constraints).setZero();

  sundials::IndexTwoNewton newton(equations, context.ctx, full_scale);
  sundials::LibraryMessage message;
  const sundials::SetupCheck check("IDA", IDAGetReturnFlagName, message);
  std::unique_ptr<void, void (*)(void*)> memory(IDACreate(context.ctx), [](void* p) { IDAFree(&p); });
  void* ida = memory.get();
  check(ida, "IDACreate");
  check(IDASetErrHandlerFn(ida, sundials::LibraryMessage::handler, &message), "IDASetErrHandlerFn");
  check(IDAInit(ida, dae_residual, 0.0, y.v, y_dot.v), "IDAInit");
  check(IDASVtolerances(ida, settings.relative_tolerance, tolerance.v), "IDASVtolerances");
  check(IDASetUserData(ida, &data), "IDASetUserData");
  check(IDASetLinearSolver(ida, newton.solver(), newton.matrix()), "IDASetLinearSolver");
  check(IDASetJacFn(ida, dae_jacobian), "IDASetJacFn");
  check(IDASetId(ida, id.v), "IDASetId");
  check(IDASetSuppressAlg(ida, SUNTRUE), "IDASetSuppressAlg");
  check(IDASetMaxNumSteps(ida, settings.max_steps), "IDASetMaxNumSteps");
  check(IDASetMaxOrd(ida, settings.max_order), "IDASetMaxOrd");
  if (settings.work.min_step > 0.0) check(IDASetMinStep(ida, settings.work.min_step), "IDASetMinStep");
  if (data.events > 0) {
    check(IDARootInit(ida, data.events, event_root), "IDARootInit");
    IDASetNoInactiveRootWarn(ida);
  }

  IntegrationRecord result;
  ConstraintVector lambda = s.segment(2 * n, constraints);
  sundials::Vector derivative(total, context.ctx);
  const auto record = [&](double t) {
    const auto state = y.map();
    // λ at the output time from the state and v̇, not IDA's interpolant of the algebraic λ: λ is left
    // out of the error test, and where the differential states are polynomials in t (a hub spinning
    // at a constant rate) IDA's steps grow long while the reaction still turns with the hub. v̇ is the
    // derivative of IDA's interpolant of v (a differential variable under error control).
    if (t > 0.0 && IDAGetDky(ida, t, 1, derivative.v) == IDA_SUCCESS) {
      multipliers_from_accelerations(equations, t, state.head(n), state.segment(n, n), derivative.map().segment(n, n), lambda);
    }
    result.time.push_back(t);
    sink.full_sample(t, state.head(n), state.segment(n, n), lambda);
  };
  const sundials::SolverSteps steps(ida, ida_calls, settings);
  sundials::sample_outputs_keeping_partial(
      result, settings, "ida", IDA_ROOT_RETURN,
      [&](double t_out, double& t) {
        if (!steps.allow_call()) return IDA_TOO_MUCH_WORK;
        return IDASolve(ida, t_out, &t, y.v, y_dot.v, IDA_NORMAL);
      },
      [&](int* directions) { steps.root_directions(directions); },
      [&](int flag, double t) {
        guard.rethrow(t);
        throw steps.failure("IDA", flag, t, message.suffix(), result.stats);
      },
      record, data.events, result.events);

  long nre = 0, nre_ls = 0;
  IDAGetNumSteps(ida, &result.stats.steps);
  IDAGetNumResEvals(ida, &nre);
  IDAGetNumLinResEvals(ida, &nre_ls);
  IDAGetNumJacEvals(ida, &result.stats.jacobian_evaluations);
  result.stats.function_evaluations = nre + nre_ls + result.stats.jacobian_evaluations * equations.full_jacobian_evaluations();
  IDAGetNumLinSolvSetups(ida, &result.stats.linear_setups);
  IDAGetNumNonlinSolvIters(ida, &result.stats.newton_iterations);
  IDAGetNumErrTestFails(ida, &result.stats.error_test_failures);
  IDAGetNumNonlinSolvConvFails(ida, &result.stats.convergence_failures);
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::solve
