// Generalized-α (Chung & Hulbert 1993) for a system in full coordinates with its constraints as
// index-3 constraints, in the form of Arnold & Brüls (2007, Multibody Syst. Dyn. 18:185): each
// step solves M(q)q̈ − Q(q, v, t) + C_qᵀλ = 0, C(q)/(βh²) = 0 at t_{n+1} for (q̈_{n+1}, λ_{n+1}) with
//   (1−α_m) a_{n+1} + α_m a_n = (1−α_f) q̈_{n+1} + α_f q̈_n,
//   q_{n+1} = q_n + h v_n + h²(½−β) a_n + h²β a_{n+1},   v_{n+1} = v_n + h(1−γ) a_n + hγ a_{n+1},
// by modified Newton with an iteration matrix kept across steps while Newton converges in ≤ 4
// iterations. The iteration matrix ∂r/∂(q̈, λ) = [M + γ'D + β'(K + H_λ), C_qᵀ; C_q β'/(βh²), 0]
// (β' = ∂q/∂q̈, γ' = ∂v/∂q̈, K, D, M from SecondOrderSystem::full_jacobian, H_λ = ∂(C_qᵀλ)/∂q) keeps the
// bordered band structure with λ in the border (solve/constrained_newton.hpp): its cost is linear
// in the element count. The step is rounded down to divide the output interval, so every output is a
// step (no interpolation).
#include <Eigen/LU>
#include <chrono>
#include <cmath>
#include <limits>

#include "solve/constrained_newton.hpp"
#include "solve/integration.hpp"
#include "solve/sundials_support.hpp"

namespace ffrf::solve {
namespace {

constexpr int kept_matrix_iterations = 4;   // refresh the iteration matrix beyond this
constexpr int fresh_matrix_iterations = 12;  // give up beyond this with a fresh matrix
constexpr double newton_tolerance = 0.1;  // WRMS norm of the correction in units of rtol|x| + atol·scale
constexpr const char* solver_name = "generalized-α";

class GeneralizedAlpha {
 public:
  GeneralizedAlpha(SecondOrderSystem& equations, const IntegratorSettings& settings, double h, IntegrationRecord& result)
      : eq_(equations), n_(equations.full_size()), constraints_(equations.constraint_count()), h_(h), settings_(settings),
        stats_(result.stats) {
    const double rho = settings.spectral_radius;
    alpha_m_ = (2.0 * rho - 1.0) / (rho + 1.0);
    alpha_f_ = rho / (rho + 1.0);
    gamma_ = 0.5 + alpha_f_ - alpha_m_;
    beta_ = 0.25 * (gamma_ + 0.5) * (gamma_ + 0.5);
    beta_prime_ = h * h * beta_ * (1.0 - alpha_f_) / (1.0 - alpha_m_);  // ∂q_{n+1}/∂q̈_{n+1}
    gamma_prime_ = h * gamma_ * (1.0 - alpha_f_) / (1.0 - alpha_m_);    // ∂v_{n+1}/∂q̈_{n+1}
    const int m = n_ + constraints_;
    for (Eigen::VectorXd* x : {&q_, &v_, &a_, &acc_, &q1_, &v1_, &a1_, &x_acc_, &mass_times_, &forces_, &scale_,
                               &weight_q_, &weight_v_, &acc_step_}) {
      x->setZero(n_);
    }
    r_.setZero(m);
    delta_.setZero(m);
    matrix_ = ConstrainedNewtonMatrix(equations.full_structure(), constraints_);
    blocks_ = SecondOrderJacobian(equations.full_structure());
    jacobian_.setZero(constraints_, n_);
    lambda_.setZero(constraints_);
    x_lambda_.setZero(constraints_);
    events_.setZero(equations.event_count());
    next_events_.setZero(equations.event_count());
  }

  // Consistent start at rest: q̈0, λ0 from [M C_qᵀ; C_q 0][q̈; λ] = [Q; −(C_q v)_q v], a_0 = q̈0.
  void start(const Eigen::VectorXd& z0) {
    eq_.full_from_minimal(0.0, z0, Eigen::VectorXd::Zero(z0.size()), q_, v_);
    scale_ = full_coordinate_scale(eq_);
    consistent_accelerations(eq_, 0.0, q_, v_, acc_, lambda_);
    a_ = acc_;
    if (events_.size() > 0) eq_.full_events(0.0, q_, events_);
  }

  // One step from t to t + h; the events' sign changes located by linear interpolation.
  void step(double t, std::vector<Event>& events) {
    const double t1 = t + h_;
    x_acc_ = acc_;  // predictor: the last acceleration and multipliers
    x_lambda_ = lambda_;
    bool fresh = false;
    int iterations = 0, since_refresh = 0;
    double previous = std::numeric_limits<double>::infinity();
    while (true) {
      residual(t1, x_acc_, x_lambda_, r_);
      if (!r_.allFinite()) fail(t, "the residual is not finite (the solution diverged)");
      if (need_matrix_) {
        form_matrix(t1);
        fresh = true;
        need_matrix_ = false;
        since_refresh = 0;
        previous = std::numeric_limits<double>::infinity();
      }
      matrix_.pack(r_.head(n_), r_.tail(constraints_), delta_);
      matrix_.solve(delta_);
      ConstraintVector lambda_step(constraints_);
      matrix_.unpack(delta_, acc_step_, lambda_step);
      x_acc_ -= acc_step_;
      x_lambda_ -= lambda_step;
      ++iterations;
      ++since_refresh;
      ++stats_.newton_iterations;
      const double norm = correction_norm();
      const double ratio = norm / previous;
      // Converged: the correction is well inside the tolerances, or within them and no longer
      // shrinking (the round-off floor of the residual).
      if (norm <= newton_tolerance || (norm <= 1.0 && ratio >= 0.5)) break;
      previous = norm;
      if (!std::isfinite(norm) || (fresh && (since_refresh >= fresh_matrix_iterations || ratio > 2.0))) {
        ++stats_.convergence_failures;
        fail(t, "Newton diverged at step " + std::to_string(stats_.steps + 1) + " (correction norm " +
                    std::to_string(norm) + " after " + std::to_string(iterations) + " iterations)");
      }
      if (!fresh && (since_refresh >= kept_matrix_iterations || ratio > 0.9)) need_matrix_ = true;
    }
    if (iterations > kept_matrix_iterations) need_matrix_ = true;
    kinematics(x_acc_);
    q_.swap(q1_);
    v_.swap(v1_);
    a_.swap(a1_);
    acc_ = x_acc_;
    lambda_ = x_lambda_;
    ++stats_.steps;
    if (events_.size() == 0) return;
    eq_.full_events(t1, q_, next_events_);
    for (int i = 0; i < static_cast<int>(events_.size()); ++i) {
      const double before = events_(i), after = next_events_(i);
      if ((after > 0.0) != (before > 0.0)) events.push_back({t + h_ * before / (before - after), i, after <= 0.0});
    }
    events_.swap(next_events_);
  }

  void sample(OutputSink& sink, double t) { sink.full_sample(t, q_, v_, lambda_); }
  bool finite() const { return q_.allFinite() && v_.allFinite() && lambda_.allFinite(); }

 private:
  void kinematics(const Eigen::VectorXd& acc1) {
    a1_ = ((1.0 - alpha_f_) * acc1 + alpha_f_ * acc_ - alpha_m_ * a_) / (1.0 - alpha_m_);
    q1_ = q_ + h_ * v_ + (h_ * h_ * (0.5 - beta_)) * a_ + (h_ * h_ * beta_) * a1_;
    v1_ = v_ + (h_ * (1.0 - gamma_)) * a_ + (h_ * gamma_) * a1_;
  }

  // [M q̈ − Q + C_qᵀλ ; C(q)/(βh²)] at (q_{n+1}, v_{n+1}) from the trial q̈_{n+1}.
  void residual(double t1, const Eigen::VectorXd& acc1, const ConstraintVector& lambda, Eigen::VectorXd& out) {
    kinematics(acc1);
    eq_.full_mass_times(q1_, acc1, mass_times_);
    eq_.full_forces(t1, q1_, v1_, forces_);
    eq_.constraint_jacobian(q1_, jacobian_);
    out.head(n_) = mass_times_ - forces_;
    out.head(n_).noalias() += jacobian_.transpose() * lambda;
    ConstraintVector c(constraints_);
    eq_.constraint(t1, q1_, c);
    out.tail(constraints_) = c / (beta_ * h_ * h_);
    ++stats_.function_evaluations;
  }

  // The structured iteration matrix at the trial state (see the file comment).
  void form_matrix(double t1) {
    kinematics(x_acc_);
    eq_.full_jacobian(t1, q1_, v1_, x_acc_, blocks_);
    curvature_.evaluate(eq_, q1_, scale_);
    matrix_.assign_coordinate_block(1.0, blocks_.mass, gamma_prime_, blocks_.damping, beta_prime_, blocks_.stiffness);
    const int b = curvature_.border;
    const double constraint_row = beta_prime_ / (beta_ * h_ * h_);
    for (int j = 0; j < b; ++j) {
      for (int i = 0; i < b; ++i) matrix_.at(matrix_.reduced(i), matrix_.reduced(j)) += beta_prime_ * curvature_.transpose_product(x_lambda_, i, j);
      for (int k = 0; k < constraints_; ++k) {
        matrix_.at(matrix_.reduced(j), matrix_.reduced_extra(k)) = curvature_.jacobian(k, j);
        matrix_.at(matrix_.reduced_extra(k), matrix_.reduced(j)) = constraint_row * curvature_.jacobian(k, j);
      }
    }
    if (!matrix_.factorize()) throw SolverFailure(FailureKind::newton_divergence, solver_name, "the iteration matrix is singular",
                                                  t1, "reduce the fixed step (now " + std::to_string(h_) + " s)");
    ++stats_.jacobian_evaluations;
    ++stats_.linear_setups;
    stats_.function_evaluations += eq_.full_jacobian_evaluations();
  }

  // Largest WRMS norm of the position and velocity corrections the q̈ correction implies.
  double correction_norm() {
    weight_q_ = settings_.relative_tolerance * q1_.cwiseAbs() + settings_.absolute_tolerance * scale_;
    weight_v_ = settings_.relative_tolerance * v1_.cwiseAbs() + settings_.absolute_tolerance * scale_;
    const double nq = (beta_prime_ * acc_step_.cwiseQuotient(weight_q_)).norm();
    const double nv = (gamma_prime_ * acc_step_.cwiseQuotient(weight_v_)).norm();
    return std::max(nq, nv) / std::sqrt(static_cast<double>(n_));
  }

  [[noreturn]] void fail(double t, const std::string& cause) {
    throw SolverFailure(FailureKind::newton_divergence, solver_name, cause, t,
                        "reduce the fixed step (now " + std::to_string(h_) + " s), or use an adaptive solver (bdf)");
  }

  SecondOrderSystem& eq_;
  int n_;
  int constraints_;  // m
  double h_;
  const IntegratorSettings& settings_;
  SolverStats& stats_;
  double alpha_m_ = 0, alpha_f_ = 0, gamma_ = 0, beta_ = 0, beta_prime_ = 0, gamma_prime_ = 0;
  Eigen::VectorXd q_, v_, a_, acc_;  // state at t_n (acc_ = q̈_n, a_ the auxiliary acceleration)
  ConstraintVector lambda_, x_lambda_;
  Eigen::VectorXd q1_, v1_, a1_, x_acc_;  // trial values at t_{n+1}
  Eigen::VectorXd mass_times_, forces_, scale_, weight_q_, weight_v_, r_, delta_, acc_step_;
  Eigen::MatrixXd jacobian_;
  SecondOrderJacobian blocks_;
  ConstraintCurvature curvature_;
  ConstrainedNewtonMatrix matrix_;
  bool need_matrix_ = true;
  EventVector events_, next_events_;  // the event functions at the last step and at the new one
};

}  // namespace

IntegrationRecord integrate_generalized_alpha(SecondOrderSystem& equations, OutputSink& sink, const Eigen::VectorXd& z0,
                                              const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  if (!(settings.fixed_step > 0.0) || !std::isfinite(settings.fixed_step)) {
    throw SolverFailure(FailureKind::setup, solver_name, "no step size given (fixed_step = " + std::to_string(settings.fixed_step) + ")",
                        0.0, "give a fixed step > 0, e.g. 0.01 s");
  }
  if (!(settings.spectral_radius >= 0.0 && settings.spectral_radius <= 1.0)) {
    throw SolverFailure(FailureKind::setup, solver_name, "spectral radius ρ∞ = " + std::to_string(settings.spectral_radius) + " outside [0, 1]",
                        0.0, "choose ρ∞ in [0, 1] (0.8 is common; 1 = no numerical dissipation)");
  }
  // Steps land on every output time: h = Δt_out / ⌈Δt_out / fixed_step⌉.
  const long per_output = std::max(1L, static_cast<long>(std::ceil(settings.output_interval / settings.fixed_step - 1e-9)));
  const double h = settings.output_interval / static_cast<double>(per_output);
  // The work limits: the step count is known before the run; the wall clock is checked every step.
  const double planned_steps = static_cast<double>(per_output) * std::round(settings.duration / settings.output_interval);
  if (planned_steps > static_cast<double>(settings.work.max_steps)) {
    throw SolverFailure(FailureKind::too_much_work, solver_name,
                        "the run needs " + std::to_string(static_cast<long>(planned_steps)) + " steps of " + std::to_string(h) +
                            " s, more than the run's step limit of " + std::to_string(settings.work.max_steps),
                        0.0, "use a larger fixed step, a shorter duration, or raise the step limit");
  }
  if (h < settings.work.min_step) {
    throw SolverFailure(FailureKind::setup, solver_name,
                        "the fixed step " + std::to_string(h) + " s is below the step-size floor " +
                            std::to_string(settings.work.min_step) + " s",
                        0.0, "use a fixed step above the step-size floor, or lower the floor");
  }
  const sundials::CallbackGuard wall_clock(solver_name, settings.work);

  IntegrationRecord result;
  result.stats.step = h;
  GeneralizedAlpha solver(equations, settings, h, result);
  solver.start(z0);
  sundials::Progress progress(settings.progress, settings.duration, "generalized-alpha");
  const long outputs = std::lround(settings.duration / settings.output_interval);
  double t = 0.0;
  try {
    throw_if_stop_requested();
    result.time.push_back(0.0);
    solver.sample(sink, 0.0);
    for (long k = 1; k <= outputs; ++k) {
      const double t0 = static_cast<double>(k - 1) * settings.output_interval;
      for (long i = 0; i < per_output; ++i) {
        t = t0 + static_cast<double>(i) * h;
        solver.step(t, result.events);
        wall_clock.check_wall_clock(t + h);
      }
      const double t_out = static_cast<double>(k) * settings.output_interval;
      if (!solver.finite()) {
        throw SolverFailure(FailureKind::divergence, solver_name, "the solution is not finite", t_out, "reduce the fixed step");
      }
      throw_if_stop_requested();
      result.time.push_back(t_out);
      solver.sample(sink, t_out);
      progress.update(t_out);
    }
  } catch (SolverFailure& failure) {
    progress.finish();
    failure.attach_partial(std::make_shared<const IntegrationRecord>(std::move(result)));
    throw;
  } catch (const std::exception& error) {  // the model refused a state
    progress.finish();
    SolverFailure failure(model_failure_kind(error), solver_name, std::string("the model failed: ") + error.what(), t,
                          "reduce the fixed step; check the scene's values");
    failure.attach_partial(std::make_shared<const IntegrationRecord>(std::move(result)));
    throw failure;
  }
  progress.finish();
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::solve
