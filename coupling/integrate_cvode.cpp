// CVODE (variable-order BDF, Newton iteration) on the minimal-coordinate ODE y = (z, ż),
// ẏ = (ż, M_z⁻¹Q_z). The wire's slack/taut transitions are located by CVODE's root finding on ℓ − L0
// and counted.
// Newton systems: the structured solve of coupling/second_order_newton.hpp — S = M + γD + γ²K from
// the equations' own blocks (CraneEquations::minimal_jacobian: analytic elastic columns, differences
// of the residual for the hull and cargo columns only), bordered band for a nodal boom, dense for a
// modal one — instead of SUNDIALS' dense LU of the (2n)² I − γJ with a difference-quotient J.
// Outputs: the state at an output time is CVODE's interpolant, and the accelerations the joint
// reaction needs are its derivative (CVodeGetDky, k = 1), so no right-hand side is evaluated per
// sample (docs/theory.md §8.1).
#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "coupling/second_order_newton.hpp"
#include "coupling/simulation.hpp"
#include "coupling/sundials_support.hpp"

namespace ffrf::coupling {
namespace {

struct OdeData {
  CraneEquations* equations;
  int size;
  std::string model_error;  // an exception the model threw inside a callback (never crosses C code)
  FailureKind model_error_kind = FailureKind::model_error;
};

int ode_rhs(sunrealtype t, N_Vector y, N_Vector y_dot, void* user) {
  auto* data = static_cast<OdeData*>(user);
  const auto state = sundials::Vector::view(y);
  auto rate = sundials::Vector::view(y_dot);
  if (!state.allFinite()) return 1;  // recoverable: CVODE retries with a smaller step
  const int n = data->size;
  try {
    rate.head(n) = state.tail(n);
    data->equations->minimal_accelerations(t, state.head(n), state.tail(n), rate.tail(n));
  } catch (const std::exception& error) {
    data->model_error = error.what();
    data->model_error_kind = model_failure_kind(error);
    return -1;
  }
  return rate.allFinite() ? 0 : 1;
}

// The structured Newton blocks at a state (coupling/second_order_newton.hpp).
int newton_blocks(OdeData& data, double t, CraneEquations::ConstRef z, CraneEquations::ConstRef z_dot,
                  CraneEquations::ConstRef z_ddot, SecondOrderJacobian& blocks) {
  if (!z.allFinite() || !z_dot.allFinite() || !z_ddot.allFinite()) return 1;
  try {
    data.equations->minimal_jacobian(t, z, z_dot, z_ddot, blocks);
  } catch (const std::exception& error) {
    data.model_error = error.what();
    data.model_error_kind = model_failure_kind(error);
    return -1;
  }
  return 0;
}

int wire_root(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
  auto* data = static_cast<OdeData*>(user);
  g[0] = sundials::wire_event(data->equations->wire_stretch_minimal(t, sundials::Vector::view(y).head(data->size)));
  return 0;
}

std::string remedy_for(int flag) {
  switch (flag) {
    case CV_TOO_MUCH_WORK: return "raise the step limit, or loosen --rtol/--atol; a very stiff model (many elements) needs more steps";
    case CV_ERR_FAILURE: return "repeated error-test failures (step-size collapse): check for a discontinuity (wire snap) or tighten --atol";
    case CV_CONV_FAILURE: return "Newton did not converge (step-size collapse): tighten tolerances or reduce the element count";
    case CV_RHSFUNC_FAIL:
    case CV_REPTD_RHSFUNC_ERR:
    case CV_UNREC_RHSFUNC_ERR: return "the model produced non-finite accelerations (divergence): check the scene's stiffness and mass values";
    default: return "check the scene and the tolerances";
  }
}

}  // namespace

RunResult integrate_minimal(CraneEquations& equations, const Eigen::VectorXd& z0, const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const int n = equations.minimal_size();
  sundials::Context context;
  sundials::Vector y(2 * n, context.ctx), tolerance(2 * n, context.ctx);
  y.map().head(n) = z0;
  y.map().tail(n).setZero();
  const Eigen::VectorXd scale = equations.coordinate_scale();
  tolerance.map().head(n) = settings.absolute_tolerance * scale;
  tolerance.map().tail(n) = settings.absolute_tolerance * scale;

  OdeData data{&equations, n, {}, FailureKind::model_error};
  sundials::SecondOrderNewton newton(equations.minimal_structure(), context.ctx,
                                     [&data](double t, auto z, auto z_dot, auto z_ddot, SecondOrderJacobian& blocks) {
                                       return newton_blocks(data, t, z, z_dot, z_ddot, blocks);
                                     });
  std::unique_ptr<void, void (*)(void*)> memory(CVodeCreate(CV_BDF, context.ctx), [](void* p) { CVodeFree(&p); });
  void* cvode = memory.get();
  if (CVodeInit(cvode, ode_rhs, 0.0, y.v) != CV_SUCCESS || CVodeSVtolerances(cvode, settings.relative_tolerance, tolerance.v) != CV_SUCCESS ||
      CVodeSetUserData(cvode, &data) != CV_SUCCESS || CVodeSetLinearSolver(cvode, newton.solver(), newton.matrix()) != CV_SUCCESS ||
      CVodeSetLinSysFn(cvode, sundials::SecondOrderNewton::linear_system) != CV_SUCCESS ||
      CVodeSetMaxNumSteps(cvode, settings.max_steps) != CV_SUCCESS || CVodeSetMaxOrd(cvode, settings.max_order) != CV_SUCCESS || CVodeRootInit(cvode, 1, wire_root) != CV_SUCCESS) {
    throw SolverFailure(FailureKind::setup, "CVODE", "set-up failed", 0.0, "report this as a bug");
  }
  CVodeSetNoInactiveRootWarn(cvode);

  RunResult result;
  DivergenceWatch watch(settings.monitor, "CVODE");
  sundials::Vector derivative(2 * n, context.ctx);
  const auto record = [&](double t) {
    const auto state = y.map();
    result.time.push_back(t);
    // At t = 0 CVODE has no interpolant yet: the one sample that solves for the accelerations.
    if (t > 0.0 && CVodeGetDky(cvode, t, 1, derivative.v) == CV_SUCCESS) {
      result.samples.push_back(
          equations.minimal_outputs_with_accelerations(t, state.head(n), state.tail(n), derivative.map().tail(n)));
    } else {
      result.samples.push_back(equations.minimal_outputs(t, state.head(n), state.tail(n)));
    }
    watch.observe(t, result.samples.back());
  };
  sundials::sample_outputs_keeping_partial(
      result, settings, "cvode", CV_ROOT_RETURN, [&](double t_out, double& t) { return CVode(cvode, t_out, y.v, &t, CV_NORMAL); },
      [&] {
        int direction = 0;
        CVodeGetRootInfo(cvode, &direction);
        return direction;
      },
      [&](int flag, double t) {
        if (!data.model_error.empty()) {
          throw SolverFailure(data.model_error_kind, "CVODE", "the model failed: " + data.model_error, t,
                              "check the scene's values; tighten --rtol/--atol");
        }
        throw SolverFailure(sundials::failure_kind(flag, CV_TOO_MUCH_WORK, CV_ERR_FAILURE, CV_CONV_FAILURE), "CVODE",
                            sundials::flag_name(CVodeGetReturnFlagName(flag)), t, remedy_for(flag));
      },
      record,
      result.wire_events);

  sundials::cvode_statistics(cvode, 0, result.stats);
  result.stats.function_evaluations += result.stats.jacobian_evaluations * equations.minimal_jacobian_evaluations();
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::coupling
