// KINSOL adapter for the static equilibrium Q_z(z, 0) = 0 (see header).
#include "coupling/static_equilibrium.hpp"

#include <kinsol/kinsol.h>
#include <kinsol/kinsol_ls.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "coupling/simulation.hpp"
#include "coupling/sundials_support.hpp"

namespace ffrf::coupling {
namespace {

std::string format_residual(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// KINSOL's own error messages go nowhere: failures are reported once, as a SolverFailure, and a
// line-search stall at a converged residual is not a failure at all (see below).
void quiet_errors(int, const char*, const char*, char*, void*) {}

struct StaticData {
  CraneEquations* equations;
  std::string model_error;
  FailureKind model_error_kind = FailureKind::model_error;
};

int static_forces(N_Vector u, N_Vector f, void* user) {
  auto* data = static_cast<StaticData*>(user);
  auto residual = sundials::Vector::view(f);
  if (!sundials::Vector::view(u).allFinite()) return 1;
  try {
    data->equations->static_residual(sundials::Vector::view(u), residual);
  } catch (const std::exception& error) {
    data->model_error = error.what();
    data->model_error_kind = model_failure_kind(error);
    return -1;
  }
  return residual.allFinite() ? 0 : 1;
}

}  // namespace

// KINSOL limits a Newton step to 1000 × ‖D_u u0‖ by default: from a zero guess (a boom on a held hub
// without cargo, all coordinates elastic) that cap stops the one long step this nearly linear problem
// needs (KIN_MXNEWT_5X_EXCEEDED). The scaled step is bounded instead by 1e8 typical sizes.
constexpr double kMaxScaledNewtonStep = 1e8;

StaticEquilibrium solve_static_equilibrium(CraneEquations& equations, const Eigen::VectorXd& guess, double tolerance) {
  const auto start = std::chrono::steady_clock::now();
  const int n = equations.minimal_size();
  if (n == 0) {  // fully prescribed (a rigid boom on a held or driven hub): nothing to solve
    StaticEquilibrium rest;
    rest.z = Eigen::VectorXd(0);
    rest.outputs = equations.minimal_outputs(0.0, rest.z, rest.z);
    rest.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return rest;
  }
  sundials::Context context;
  sundials::Vector u(n, context.ctx), u_scale(n, context.ctx), f_scale(n, context.ctx);
  u.map() = guess;
  u_scale.map() = equations.coordinate_scale().cwiseInverse();
  f_scale.map() = equations.static_residual_scale();

  std::unique_ptr<void, void (*)(void*)> memory(KINCreate(context.ctx), [](void* p) { KINFree(&p); });
  void* kinsol = memory.get();
  StaticData data{&equations, {}};
  sundials::DenseSolver linear(u.v, context.ctx);
  if (KINInit(kinsol, static_forces, u.v) != KIN_SUCCESS || KINSetErrHandlerFn(kinsol, quiet_errors, nullptr) != KIN_SUCCESS || KINSetUserData(kinsol, &data) != KIN_SUCCESS ||
      KINSetLinearSolver(kinsol, linear.solver, linear.matrix) != KIN_SUCCESS ||
      KINSetFuncNormTol(kinsol, tolerance) != KIN_SUCCESS || KINSetScaledStepTol(kinsol, 1e-14) != KIN_SUCCESS ||
      KINSetMaxNewtonStep(kinsol, kMaxScaledNewtonStep) != KIN_SUCCESS ||
      KINSetMaxSetupCalls(kinsol, 1) != KIN_SUCCESS || KINSetNumMaxIters(kinsol, 200) != KIN_SUCCESS) {
    throw SolverFailure(FailureKind::setup, "KINSOL", "set-up failed", 0.0, "report this as a bug");
  }
  const int flag = KINSol(kinsol, u.v, KIN_LINESEARCH, u_scale.v, f_scale.v);
  StaticEquilibrium result;
  KINGetNumNonlinSolvIters(kinsol, &result.newton_iterations);
  long jacobian_evaluations = 0;
  KINGetNumFuncEvals(kinsol, &result.function_evaluations);
  KINGetNumLinFuncEvals(kinsol, &jacobian_evaluations);  // the difference-quotient Jacobian's
  result.function_evaluations += jacobian_evaluations;
  Eigen::VectorXd residual(n);
  equations.static_residual(u.map(), residual);
  result.scaled_residual = residual.cwiseProduct(f_scale.map()).cwiseAbs().maxCoeff();
  // Near the solution the line search can stall at round-off (KIN_LINESEARCH_NONCONV) although the
  // residual is converged: the residual, not the flag, decides.
  if (!(result.scaled_residual < 1e2 * tolerance)) {
    throw SolverFailure(!data.model_error.empty() ? data.model_error_kind : FailureKind::newton_divergence,
                        "KINSOL (static equilibrium)",
                        (!data.model_error.empty() ? "the model failed: " + data.model_error
                                                       : flag < 0 ? sundials::flag_name(KINGetReturnFlagName(flag)) : std::string("no convergence")) +
                            " after " + std::to_string(result.newton_iterations) + " Newton iterations, scaled residual " +
                            format_residual(result.scaled_residual),
                        0.0,
                        "check that the hull can float the load (mass vs. buoyancy), that the wire is not slack at rest "
                        "(cargo hanging) and that the boom is not near buckling");
  }
  result.z = u.map();
  if (equations.wire_stretch_minimal(0.0, result.z) <= 0.0) {
    throw SolverFailure(FailureKind::wire_slack, "KINSOL (static equilibrium)", "the wire is slack at rest (stretch " +
                        format_residual(equations.wire_stretch_minimal(0.0, result.z)) + " m)", 0.0,
                        "hang the cargo below the boom tip: check the wire's unstretched length and the hook position");
  }
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(n);
  result.outputs = equations.minimal_outputs(0.0, result.z, rest);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::coupling
