// CVODE (variable-order BDF, Newton with a dense Jacobian) on a system in full coordinates as an
// ODE y = (q, v): q̇ = v, and v̇, λ from the index-1 system (the constraints differentiated twice)
//   [M(q) C_qᵀ; C_q 0] [v̇; λ] = [Q(q, v, t); γ − 2αĊ − β²C],  γ = −(C_q v)_q v − C_tt,  Ċ = C_q v + C_t,
// solved through the Schur complement S = C_q M⁻¹ C_qᵀ (3 × 3). Three constraint treatments:
//  * index1     α = β = 0: only C̈ = 0 is imposed, so the integration errors in the invariants C and
//               Ċ are never corrected: Ċ random-walks (grows like t) and C like t²;
//  * baumgarte  α = β = ω_b: the drift obeys C̈ + 2ω_b Ċ + ω_b² C = 0, critically damped;
//  * projection α = β = 0 plus CVODE's projection (CVodeSetProjFn) after every step: q onto C(q) = 0
//               by Gauss–Newton in the mass-weighted norm ‖Δq‖_M, then v onto C_q v = 0 (the
//               M-orthogonal projection, which never raises the kinetic energy); CVODE's error
//               estimate is projected with the same linear projector.
// The Jacobian is the forward difference of integrate_minimal.cpp (increments 10⁻⁷·max(|y_j|, 1); see
// the comment there). All constraint calls are in constraint_terms(), project_positions() and
// project_velocities().
#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "linalg/dense_solvers.hpp"
#include "solve/integration.hpp"
#include "solve/solver_steps.hpp"
#include "solve/sundials_support.hpp"

namespace ffrf::solve {
namespace {

constexpr int max_projection_iterations = 10;

// Workspace of one run (allocated once; the mass matrix itself comes by value from the model).
struct Index1Data {
  SecondOrderSystem* equations;
  int size;        // nq
  int events = 0;  // event functions
  double alpha;    // Baumgarte velocity gain [1/s]
  double beta;     // Baumgarte position gain [1/s]
  void* cvode = nullptr;
  N_Vector error_weights = nullptr;  // CVODE's error weights, read by the projection
  Eigen::MatrixXd jacobian;        // C_q (m × nq)
  Eigen::MatrixXd mass_matrix;     // M(q) workspace
  Eigen::LLT<Eigen::MatrixXd> mass;  // M = LLᵀ
  Eigen::MatrixXd mass_inverse_jacobian_t;  // Y = M⁻¹C_qᵀ (nq × m)
  ConstraintMatrix schur;          // S = C_q Y
  Eigen::VectorXd forces, free_acceleration, weights, work;
  ConstraintVector c, c_t, c_dot, gamma, lambda;
  long jacobian_rhs_evaluations = 0;
  sundials::CallbackGuard* guard;  // every callback runs inside it

  Index1Data(SecondOrderSystem& e, int n, double a, double b, sundials::CallbackGuard& g)
      : equations(&e), size(n), alpha(a), beta(b), jacobian(e.constraint_count(), n), mass_matrix(n, n), mass(n),
        mass_inverse_jacobian_t(n, e.constraint_count()), schur(e.constraint_count(), e.constraint_count()), forces(n),
        free_acceleration(n), weights(2 * n), work(n), c(e.constraint_count()), c_t(e.constraint_count()),
        c_dot(e.constraint_count()), gamma(e.constraint_count()), lambda(e.constraint_count()), guard(&g) {}
};

// C, C_q, Ċ = C_q v and γ at (q, v): the one place the constraint is evaluated for the dynamics.
void constraint_terms(Index1Data& d, double t, SecondOrderSystem::ConstRef q, SecondOrderSystem::ConstRef v) {
  d.equations->constraint(t, q, d.c);
  d.equations->constraint_jacobian(q, d.jacobian);
  d.equations->constraint_time_derivative(t, d.c_t);
  d.c_dot.noalias() = d.jacobian * v;
  d.c_dot += d.c_t;
  d.equations->constraint_rate_terms(t, q, v, d.gamma);
}

// Factorizes M(q) and forms Y = M⁻¹C_qᵀ and S = C_q Y for the current d.jacobian; false if M is not
// positive definite.
bool factorize(Index1Data& d, SecondOrderSystem::ConstRef q) {
  d.equations->full_mass_matrix(q, d.mass_matrix);
  d.mass.compute(d.mass_matrix);
  if (d.mass.info() != Eigen::Success) return false;
  d.mass_inverse_jacobian_t = d.mass.solve(d.jacobian.transpose());
  d.schur.noalias() = d.jacobian * d.mass_inverse_jacobian_t;
  return true;
}

// v̇ and λ at (t, q, v): v̇ = M⁻¹Q − Y λ with S λ = C_q M⁻¹Q − (γ − 2αĊ − β²C).
bool accelerations(Index1Data& d, double t, SecondOrderSystem::ConstRef q, SecondOrderSystem::ConstRef v, SecondOrderSystem::Ref v_dot) {
  constraint_terms(d, t, q, v);
  if (!factorize(d, q)) return false;
  d.equations->full_forces(t, q, v, d.forces);
  d.free_acceleration = d.mass.solve(d.forces);
  ConstraintVector rhs(d.c.size());
  rhs.noalias() = d.jacobian * d.free_acceleration;
  rhs -= d.gamma - 2.0 * d.alpha * d.c_dot - d.beta * d.beta * d.c;
  d.lambda = d.schur.partialPivLu().solve(rhs);
  v_dot = d.free_acceleration;
  v_dot.noalias() -= d.mass_inverse_jacobian_t * d.lambda;
  return v_dot.allFinite();
}

int index1_rhs(sunrealtype t, N_Vector y, N_Vector y_dot, void* user) {
  auto* d = static_cast<Index1Data*>(user);
  return (*d->guard)([&] {
    const auto state = sundials::Vector::view(y);
    auto rate = sundials::Vector::view(y_dot);
    if (!state.allFinite()) return 1;  // recoverable: CVODE retries with a smaller step
    const int n = d->size;
    rate.head(n) = state.tail(n);
    return accelerations(*d, t, state.head(n), state.tail(n), rate.tail(n)) ? 0 : 1;
  });
}

int index1_jacobian(sunrealtype t, N_Vector y, N_Vector f_y, SUNMatrix jacobian, void* user, N_Vector work_y, N_Vector work_f,
                    N_Vector) {
  auto* d = static_cast<Index1Data*>(user);
  return (*d->guard)([&] {
    const int flag = sundials::second_order_jacobian(
        t, y, f_y, jacobian, work_y, work_f,
        [d](double s, auto q, auto v, auto v_dot) { return accelerations(*d, s, q, v, v_dot); });
    if (flag == 0) d->jacobian_rhs_evaluations += 2 * d->size;
    return flag;
  });
}

// x minus its M-orthogonal component normal to C_q x = 0: x ← x − Y S⁻¹ C_q x.
void remove_normal_component(Index1Data& d, SecondOrderSystem::Ref x) {
  ConstraintVector normal(d.c.size());
  normal.noalias() = d.jacobian * x;
  d.work.noalias() = d.mass_inverse_jacobian_t * d.schur.partialPivLu().solve(normal);
  x -= d.work;
}

// Gauss–Newton for min ‖Δq‖_M subject to C(q + Δq) = 0, with M fixed at the step's q: stops when the
// update's weighted RMS norm over the positions (CVODE's error weights) is below eps (CVODE's epsProj);
// false if it does not converge.
bool project_positions(Index1Data& d, double t, SecondOrderSystem::ConstRef q, SecondOrderSystem::Ref q_projected, double eps) {
  q_projected = q;
  for (int iteration = 0; iteration < max_projection_iterations; ++iteration) {
    d.equations->constraint(t, q_projected, d.c);
    d.equations->constraint_jacobian(q_projected, d.jacobian);
    d.mass_inverse_jacobian_t = d.mass.solve(d.jacobian.transpose());
    d.schur.noalias() = d.jacobian * d.mass_inverse_jacobian_t;
    d.work.noalias() = d.mass_inverse_jacobian_t * d.schur.partialPivLu().solve(d.c);
    q_projected -= d.work;
    const double update = std::sqrt(d.work.cwiseProduct(d.weights.head(d.size)).squaredNorm() / d.size);
    if (!q_projected.allFinite()) return false;
    if (update < eps) break;
    if (iteration + 1 == max_projection_iterations) return false;
  }
  // C_q, Y and S at the projected q, for the velocity projection.
  d.equations->constraint_jacobian(q_projected, d.jacobian);
  d.mass_inverse_jacobian_t = d.mass.solve(d.jacobian.transpose());
  d.schur.noalias() = d.jacobian * d.mass_inverse_jacobian_t;
  return true;
}

// v onto C_q v + C_t = 0 (affine: one M-orthogonal projection at the projected q,
// v ← v − Y S⁻¹ (C_q v + C_t)).
void project_velocities(Index1Data& d, double t, SecondOrderSystem::Ref v) {
  d.equations->constraint_time_derivative(t, d.c_t);
  d.c_dot.noalias() = d.jacobian * v;
  d.c_dot += d.c_t;
  d.work.noalias() = d.mass_inverse_jacobian_t * d.schur.partialPivLu().solve(d.c_dot);
  v -= d.work;
}

// CVProjFn: corr = projected y − ycur; err (if given) gets the same linear projection, block by block
// (the position block against C_q, the velocity block against C_q; the second-order coupling of the
// velocity constraint to position errors, (C_q v)_q δq, is left out).
int index1_projection(sunrealtype t, N_Vector ycur, N_Vector corr, sunrealtype eps, N_Vector err, void* user) {
  auto* d = static_cast<Index1Data*>(user);
  const int n = d->size;
  const auto state = sundials::Vector::view(ycur);
  auto correction = sundials::Vector::view(corr);
  return (*d->guard)([&] {
    if (CVodeGetErrWeights(d->cvode, d->error_weights) != CV_SUCCESS) return -1;
    d->weights = sundials::Vector::view(d->error_weights);
    if (!state.allFinite()) return 1;
    d->equations->full_mass_matrix(state.head(n), d->mass_matrix);
    d->mass.compute(d->mass_matrix);
    if (d->mass.info() != Eigen::Success) return 1;
    auto q_projected = correction.head(n);
    if (!project_positions(*d, t, state.head(n), q_projected, eps)) return 1;
    q_projected -= state.head(n);
    auto v_projected = correction.tail(n);
    v_projected = state.tail(n);
    project_velocities(*d, t, v_projected);
    v_projected -= state.tail(n);
    if (err != nullptr) {
      auto error = sundials::Vector::view(err);
      remove_normal_component(*d, error.head(n));
      remove_normal_component(*d, error.tail(n));
    }
    return correction.allFinite() ? 0 : 1;
  });
}

}  // namespace

IntegrationRecord integrate_index1(SecondOrderSystem& equations, OutputSink& sink, const Eigen::VectorXd& z0,
                                   const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const bool baumgarte = settings.kind.formulation == Formulation::baumgarte;
  const bool projection = settings.kind.formulation == Formulation::projection;
  const std::string label(to_string(settings.kind));
  const std::string solver = "CVODE (" + label + ")";
  // Settings a caller must never pass (the study checks them): std::invalid_argument, as before.
  if (!baumgarte && !projection && settings.kind.formulation != Formulation::index1) {
    throw std::invalid_argument("integrate_index1: the formulation must be index1, baumgarte or projection");
  }
  if (baumgarte && !(settings.baumgarte_frequency > 0.0 && std::isfinite(settings.baumgarte_frequency))) {
    throw std::invalid_argument("baumgarte_frequency " + std::to_string(settings.baumgarte_frequency) +
                                ": not a valid stabilization frequency (valid range (0, inf) rad/s)");
  }
  const int n = equations.full_size();
  sundials::Context context;
  sundials::Vector y(2 * n, context.ctx), tolerance(2 * n, context.ctx);
  auto state = y.map();
  equations.full_from_minimal(0.0, z0, Eigen::VectorXd::Zero(z0.size()), state.head(n), state.tail(n));

  // Tolerances as IDA's: each full coordinate scaled by its minimal counterpart's typical size.
  const Eigen::VectorXd full_scale = full_coordinate_scale(equations);
  tolerance.map().head(n) = settings.absolute_tolerance * full_scale;
  tolerance.map().tail(n) = settings.absolute_tolerance * full_scale;

  const double gain = baumgarte ? settings.baumgarte_frequency : 0.0;
  sundials::CallbackGuard guard(solver, settings.work);
  Index1Data data(equations, n, gain, gain, guard);
  data.events = equations.event_count();
  sundials::LibraryMessage message;
  const sundials::SetupCheck check(solver, CVodeGetReturnFlagName, message);
  std::unique_ptr<void, void (*)(void*)> memory(CVodeCreate(CV_BDF, context.ctx), [](void* p) { CVodeFree(&p); });
  void* cvode = memory.get();
  check(cvode, "CVodeCreate");
  check(CVodeSetErrHandlerFn(cvode, sundials::LibraryMessage::handler, &message), "CVodeSetErrHandlerFn");
  data.cvode = cvode;
  sundials::Vector error_weights(2 * n, context.ctx);
  data.error_weights = error_weights.v;
  sundials::DenseSolver linear(y.v, context.ctx);
  check(CVodeInit(cvode, index1_rhs, 0.0, y.v), "CVodeInit");
  check(CVodeSVtolerances(cvode, settings.relative_tolerance, tolerance.v), "CVodeSVtolerances");
  check(CVodeSetUserData(cvode, &data), "CVodeSetUserData");
  check(CVodeSetLinearSolver(cvode, linear.solver, linear.matrix), "CVodeSetLinearSolver");
  check(CVodeSetJacFn(cvode, index1_jacobian), "CVodeSetJacFn");
  check(CVodeSetMaxNumSteps(cvode, settings.max_steps), "CVodeSetMaxNumSteps");
  check(CVodeSetMaxOrd(cvode, settings.max_order), "CVodeSetMaxOrd");
  if (settings.work.min_step > 0.0) check(CVodeSetMinStep(cvode, settings.work.min_step), "CVodeSetMinStep");
  if (data.events > 0) {
    check(CVodeRootInit(cvode, data.events, sundials::full_event_root<Index1Data>), "CVodeRootInit");
    CVodeSetNoInactiveRootWarn(cvode);
  }
  if (projection) check(CVodeSetProjFn(cvode, index1_projection), "CVodeSetProjFn");

  // Projection and the output times: CVODE projects the state at the end of each step, not the values
  // it interpolates at an output time in between. When the clamp fixes the whole frame (a rigid boom
  // on a driven hub) the projected error estimate vanishes and steps grow without bound, so the
  // interpolant drifts off the moving manifold C(q, t) = 0: the projection's steps are capped at the
  // output interval and every output state is projected as well (docs/theory.md §10).
  if (projection) check(CVodeSetMaxStep(cvode, settings.output_interval), "CVodeSetMaxStep");
  sundials::Vector projected_output(2 * n, context.ctx), output_correction(2 * n, context.ctx);

  IntegrationRecord result;
  Eigen::VectorXd v_dot(n);
  const auto record = [&](double t) {
    projected_output.map() = y.map();
    if (projection && t > 0.0 && index1_projection(t, y.v, output_correction.v, 1e-3, nullptr, &data) == 0) {
      projected_output.map() += output_correction.map();
    }
    const auto s = projected_output.map();
    if (!accelerations(data, t, s.head(n), s.tail(n), v_dot)) {
      throw SolverFailure(FailureKind::mass_not_positive_definite, solver, "the mass matrix is not positive definite", t);
    }
    result.time.push_back(t);
    sink.full_sample(t, s.head(n), s.tail(n), data.lambda);
  };
  const sundials::SolverSteps steps(cvode, sundials::cvode_calls, settings);
  sundials::sample_outputs_keeping_partial(
      result, settings, label.c_str(), CV_ROOT_RETURN,
      [&](double t_out, double& t) {
        if (!steps.allow_call()) return CV_TOO_MUCH_WORK;
        return CVode(cvode, t_out, y.v, &t, CV_NORMAL);
      },
      [&](int* directions) { steps.root_directions(directions); },
      [&](int flag, double t) {
        guard.rethrow(t);
        SolverFailure failure = steps.failure(solver, flag, t, message.suffix(), result.stats);
        if (flag == CV_PROJFUNC_FAIL || flag == CV_REPTD_PROJFUNC_ERR) {
          throw SolverFailure(FailureKind::step_size_collapse, solver,
                              steps.flag_name(flag) + ": the projection onto the constraint did not converge" +
                                  message.suffix(),
                              t, "tighten the tolerances, or use the index2 formulation or minimal coordinates");
        }
        throw failure;
      },
      record, data.events, result.events);

  sundials::cvode_statistics(cvode, data.jacobian_rhs_evaluations, result.stats);
  if (projection) CVodeGetNumProjEvals(cvode, &result.stats.projections);
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::solve
