// KINSOL adapter for the static equilibrium Q_z(z, 0) = 0: stiffness-scaled residuals, Newton
// from the guess, Newton homotopy as the fallback, and a failure that names the unbalanced row
// (see header).
#include "solve/static_equilibrium.hpp"

#include <kinsol/kinsol.h>
#include <kinsol/kinsol_ls.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "solve/integration.hpp"
#include "solve/sundials_support.hpp"

namespace ffrf::solve {
namespace {

std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// KINSOL's own error messages go nowhere: failures are reported once, as a SolverFailure, and a
// line-search stall at a converged residual is not a failure at all (see below).
void quiet_errors(int, const char*, const char*, char*, void*) {}

// The residual KINSOL sees: Q_z(z) − offset (offset = (1 − λ) Q_z(z0) in the continuation, else 0).
struct StaticData {
  SecondOrderSystem* equations;
  const Eigen::VectorXd* offset;
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
  residual -= *data->offset;
  return residual.allFinite() ? 0 : 1;
}

// KINSOL's scaling of the residual rows: 1 / (|∂Q_i/∂z_i| s_i), at least 10⁻³ of the row's weight
// scale (header). The diagonal by forward differences at the guess.
Eigen::VectorXd stiffness_residual_scale(SecondOrderSystem& equations, const Eigen::VectorXd& guess) {
  const int n = equations.minimal_size();
  const Eigen::VectorXd typical = equations.coordinate_scale();
  const Eigen::VectorXd weight_scale = equations.static_residual_scale();
  Eigen::VectorXd base(n), moved(n), scale(n);
  equations.static_residual(guess, base);
  Eigen::VectorXd z = guess;
  for (int j = 0; j < n; ++j) {
    const double step = 1e-7 * std::max(std::abs(guess(j)), typical(j));
    z(j) = guess(j) + step;
    equations.static_residual(z, moved);
    z(j) = guess(j);
    const double stiffness_force = std::abs((moved(j) - base(j)) / step) * typical(j);
    const double floor = 1e-3 / weight_scale(j);
    scale(j) = 1.0 / (std::isfinite(stiffness_force) ? std::max(stiffness_force, floor) : floor);
  }
  // A rigid body's rows share its stiffest translation: a wire's tension acts along the wire, so a
  // trial point that stretches it by a centimetre pushes the cargo sideways as hard as down once the
  // wire leans, and turns it about G2 with the hook's lever, however soft the pendulum's own
  // sideways (T/ℓ) and rocking (T·lever) stiffnesses are. The pitch row takes that stiffness's
  // moment at a 1 m lever over the pitch's typical angle.
  for (const int body : equations.rigid_body_blocks()) {
    const double shared = std::min(scale(body), scale(body + 1));  // the larger force
    scale(body) = scale(body + 1) = shared;
    const double moment = typical(body + 2) / (shared * typical(body + 1));  // N/m × m × rad × 1 m
    scale(body + 2) = std::min(scale(body + 2), 1.0 / moment);
  }
  return scale;
}

// KINSOL limits a Newton step to 1000 × ‖D_u u0‖ by default: from a zero guess (a boom on a held hub
// without cargo, all coordinates elastic) that cap stops the one long step this nearly linear problem
// needs (KIN_MXNEWT_5X_EXCEEDED). The scaled step is bounded instead by 1e8 typical sizes.
constexpr double kMaxScaledNewtonStep = 1e8;
constexpr int kMaxNewtonIterations = 200;
constexpr int kMaxContinuationSteps = 200;

struct NewtonOutcome {
  bool converged = false;
  long iterations = 0, evaluations = 0;
  double scaled_residual = 0.0;  // of Q_z(z) − offset
  std::string flag;              // KINSOL's return flag name
  std::string model_error;
  FailureKind model_error_kind = FailureKind::model_error;
};

// One KINSOL solve of Q_z(z) = offset from z (updated in place, also when it fails).
NewtonOutcome newton(SecondOrderSystem& equations, Eigen::VectorXd& z, const Eigen::VectorXd& offset,
                     const Eigen::VectorXd& residual_scale, double tolerance, int max_iterations) {
  const int n = equations.minimal_size();
  sundials::Context context;
  sundials::Vector u(n, context.ctx), u_scale(n, context.ctx), f_scale(n, context.ctx);
  u.map() = z;
  u_scale.map() = equations.coordinate_scale().cwiseInverse();
  f_scale.map() = residual_scale;
  std::unique_ptr<void, void (*)(void*)> memory(KINCreate(context.ctx), [](void* p) { KINFree(&p); });
  void* kinsol = memory.get();
  StaticData data{&equations, &offset, {}};
  sundials::DenseSolver linear(u.v, context.ctx);
  if (KINInit(kinsol, static_forces, u.v) != KIN_SUCCESS || KINSetErrHandlerFn(kinsol, quiet_errors, nullptr) != KIN_SUCCESS ||
      KINSetUserData(kinsol, &data) != KIN_SUCCESS || KINSetLinearSolver(kinsol, linear.solver, linear.matrix) != KIN_SUCCESS ||
      KINSetFuncNormTol(kinsol, tolerance) != KIN_SUCCESS || KINSetScaledStepTol(kinsol, 1e-14) != KIN_SUCCESS ||
      KINSetMaxNewtonStep(kinsol, kMaxScaledNewtonStep) != KIN_SUCCESS || KINSetMaxSetupCalls(kinsol, 1) != KIN_SUCCESS ||
      KINSetNumMaxIters(kinsol, max_iterations) != KIN_SUCCESS) {
    throw SolverFailure(FailureKind::setup, "KINSOL", "set-up failed", 0.0, "report this as a bug");
  }
  const int flag = KINSol(kinsol, u.v, KIN_LINESEARCH, u_scale.v, f_scale.v);
  NewtonOutcome outcome;
  KINGetNumNonlinSolvIters(kinsol, &outcome.iterations);
  long jacobian_evaluations = 0;
  KINGetNumFuncEvals(kinsol, &outcome.evaluations);
  KINGetNumLinFuncEvals(kinsol, &jacobian_evaluations);  // the difference-quotient Jacobian's
  outcome.evaluations += jacobian_evaluations;
  outcome.flag = flag < 0 ? sundials::flag_name(KINGetReturnFlagName(flag)) : "";
  outcome.model_error = data.model_error;
  outcome.model_error_kind = data.model_error_kind;
  z = u.map();
  if (!z.allFinite() || !data.model_error.empty()) return outcome;
  Eigen::VectorXd residual(n);
  equations.static_residual(z, residual);
  outcome.scaled_residual = (residual - offset).cwiseProduct(residual_scale).cwiseAbs().maxCoeff();
  // Near the solution the line search can stall at round-off (KIN_LINESEARCH_NONCONV) although the
  // residual is converged: the residual, not the flag, decides.
  outcome.converged = outcome.scaled_residual < 1e2 * tolerance;
  return outcome;
}

}  // namespace

StaticSolution solve_static_equilibrium(SecondOrderSystem& equations, const Eigen::VectorXd& guess, double tolerance) {
  StaticSolvePath path;
  return solve_static_equilibrium(equations, guess, path, tolerance);
}

StaticSolution solve_static_equilibrium(SecondOrderSystem& equations, const Eigen::VectorXd& guess, StaticSolvePath& path,
                                        double tolerance) {
  path = StaticSolvePath{};
  const auto start = std::chrono::steady_clock::now();
  const int n = equations.minimal_size();
  StaticSolution result;
  const auto finish = [&](StaticSolution& done) {
    done.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return done;
  };
  if (n == 0) {  // fully prescribed (e.g. a rigid boom on a held or driven hub): nothing to solve
    result.z = Eigen::VectorXd(0);
    return finish(result);
  }
  const Eigen::VectorXd residual_scale = stiffness_residual_scale(equations, guess);
  const Eigen::VectorXd no_offset = Eigen::VectorXd::Zero(n);
  const auto count = [&](const NewtonOutcome& outcome) {
    result.newton_iterations += outcome.iterations;
    result.function_evaluations += outcome.evaluations;
  };

  Eigen::VectorXd z = guess;
  NewtonOutcome direct = newton(equations, z, no_offset, residual_scale, tolerance, kMaxNewtonIterations);
  count(direct);
  NewtonOutcome last = direct;
  bool continued = false;
  if (!direct.converged) {
    // Newton homotopy from the guess: Q_z(z) = (1 − λ) Q_z(z0).
    Eigen::VectorXd initial_force(n);
    equations.static_residual(guess, initial_force);
    Eigen::VectorXd solved = guess;
    double lambda = 0.0, step = 0.1;
    while (lambda < 1.0 && path.continuation_steps < kMaxContinuationSteps && step >= 1e-4) {
      const double next = std::min(1.0, lambda + step);
      const Eigen::VectorXd offset = (1.0 - next) * initial_force;
      Eigen::VectorXd trial = solved;
      last = newton(equations, trial, offset, residual_scale, tolerance, 50);
      count(last);
      ++path.continuation_steps;
      if (!last.model_error.empty()) break;
      if (last.converged) {
        solved = trial;
        lambda = next;
        step = std::min(0.5, 2.0 * step);
      } else {
        step *= 0.5;
      }
    }
    continued = lambda >= 1.0;
    if (continued || lambda > 0.0) z = solved;  // a failure is reported where the continuation got to
  }
  Eigen::VectorXd residual = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  if (z.allFinite()) equations.static_residual(z, residual);
  const bool converged = direct.converged || continued;
  if (!converged) {
    if (!last.model_error.empty() || !residual.allFinite()) {
      const NewtonOutcome& failed = !last.model_error.empty() ? last : direct;
      throw SolverFailure(failed.model_error_kind, "KINSOL (static equilibrium)",
                          "the model failed: " + (failed.model_error.empty() ? std::string("non-finite forces") : failed.model_error),
                          0.0, equations.static_model_check());
    }
    // The rigid bodies' balance names the cause when it fails: an elastic body's own rows balance
    // under whatever load the rigid bodies put on it, unless the elastic body cannot carry it.
    const Eigen::VectorXd scaled_rows = residual.cwiseProduct(residual_scale).cwiseAbs();
    Eigen::Index worst = 0;
    const double scaled = scaled_rows.maxCoeff(&worst);
    int worst_rigid = -1;
    for (int i = 0; i < n; ++i) {
      if (equations.residual_row(i).rigid && (worst_rigid < 0 || scaled_rows(i) > scaled_rows(worst_rigid))) worst_rigid = i;
    }
    if (worst_rigid >= 0 && scaled_rows(worst_rigid) >= 1e2 * tolerance) worst = worst_rigid;
    const ResidualRow row = equations.residual_row(static_cast<int>(worst));
    throw SolverFailure(FailureKind::newton_divergence, "KINSOL (static equilibrium)",
                        "no static equilibrium: " + row.what + " stays out of balance by " +
                            format_number(std::abs(residual(worst))) + (row.moment ? " N m" : " N") +
                            " (Newton from the rest-pose guess: " + (direct.flag.empty() ? "no convergence" : direct.flag) +
                            " after " + std::to_string(direct.iterations) + " iterations; continuation in the load: " +
                            std::to_string(path.continuation_steps) + " steps; scaled residual " + format_number(scaled) + ")",
                        0.0, row.check);
  }
  result.z = z;
  result.scaled_residual = residual.cwiseProduct(residual_scale).cwiseAbs().maxCoeff();
  for (int i = 0; i < n; ++i) {
    const ResidualRow row = equations.residual_row(i);
    if (!row.rigid) continue;
    double& largest = row.moment ? path.max_moment_residual : path.max_force_residual;
    largest = std::max(largest, std::abs(residual(i)));
  }
  return finish(result);
}

}  // namespace ffrf::solve
