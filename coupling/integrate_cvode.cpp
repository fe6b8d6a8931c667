// CVODE (variable-order BDF, Newton iteration with a dense difference-quotient Jacobian) on the
// minimal-coordinate ODE y = (z, ż), ẏ = (ż, M_z⁻¹Q_z). The wire's slack/taut transitions are
// located by CVODE's root finding on ℓ − L0 and counted.
#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>

#include <chrono>
#include <cmath>

#include "coupling/simulation.hpp"
#include "coupling/sundials_support.hpp"

namespace ffrf::coupling {
namespace {

struct OdeData {
  CraneEquations* equations;
  int size;
  bool failed = false;
};

int ode_rhs(sunrealtype t, N_Vector y, N_Vector y_dot, void* user) {
  auto* data = static_cast<OdeData*>(user);
  const auto state = sundials::Vector::view(y);
  auto rate = sundials::Vector::view(y_dot);
  const int n = data->size;
  rate.head(n) = state.tail(n);
  data->equations->minimal_accelerations(t, state.head(n), state.tail(n), rate.tail(n));
  return rate.allFinite() ? 0 : 1;  // recoverable: CVODE retries with a smaller step
}

int wire_root(sunrealtype, N_Vector y, sunrealtype* g, void* user) {
  auto* data = static_cast<OdeData*>(user);
  g[0] = data->equations->wire_stretch_minimal(sundials::Vector::view(y).head(data->size));
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

  OdeData data{&equations, n};
  std::unique_ptr<void, void (*)(void*)> memory(CVodeCreate(CV_BDF, context.ctx), [](void* p) { CVodeFree(&p); });
  void* cvode = memory.get();
  sundials::DenseSolver linear(y.v, context.ctx);
  if (CVodeInit(cvode, ode_rhs, 0.0, y.v) != CV_SUCCESS || CVodeSVtolerances(cvode, settings.relative_tolerance, tolerance.v) != CV_SUCCESS ||
      CVodeSetUserData(cvode, &data) != CV_SUCCESS || CVodeSetLinearSolver(cvode, linear.solver, linear.matrix) != CV_SUCCESS ||
      CVodeSetMaxNumSteps(cvode, settings.max_steps) != CV_SUCCESS || CVodeRootInit(cvode, 1, wire_root) != CV_SUCCESS) {
    throw SolverFailure("CVODE", "set-up failed", 0.0, "report this as a bug");
  }
  CVodeSetNoInactiveRootWarn(cvode);

  RunResult result;
  sundials::Progress progress(settings.progress, settings.duration, "cvode");
  const auto record = [&](double t) {
    const auto state = y.map();
    result.time.push_back(t);
    result.samples.push_back(equations.minimal_outputs(t, state.head(n), state.tail(n)));
  };
  record(0.0);
  const long outputs = std::lround(settings.duration / settings.output_interval);
  double t = 0.0;
  for (long k = 1; k <= outputs; ++k) {
    const double t_out = static_cast<double>(k) * settings.output_interval;
    while (true) {
      const int flag = CVode(cvode, t_out, y.v, &t, CV_NORMAL);
      if (flag == CV_ROOT_RETURN) {
        int direction = 0;
        CVodeGetRootInfo(cvode, &direction);
        result.wire_events.push_back({t, direction < 0});
        continue;
      }
      if (flag < 0) {
        progress.finish();
        throw SolverFailure("CVODE", CVodeGetReturnFlagName(flag), t, remedy_for(flag));
      }
      break;
    }
    record(t_out);
    progress.update(t_out);
  }
  progress.finish();

  long nfe = 0, nfe_ls = 0;
  CVodeGetNumSteps(cvode, &result.stats.steps);
  CVodeGetNumRhsEvals(cvode, &nfe);
  CVodeGetNumLinRhsEvals(cvode, &nfe_ls);
  result.stats.function_evaluations = nfe + nfe_ls;
  CVodeGetNumJacEvals(cvode, &result.stats.jacobian_evaluations);
  CVodeGetNumNonlinSolvIters(cvode, &result.stats.newton_iterations);
  CVodeGetNumErrTestFails(cvode, &result.stats.error_test_failures);
  CVodeGetNumNonlinSolvConvFails(cvode, &result.stats.convergence_failures);
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::coupling
