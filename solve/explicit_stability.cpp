// Measured explicit stability limit and the ERK stability region (see explicit_stability.hpp).
#include "solve/explicit_stability.hpp"

#include <arkode/arkode_erkstep.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "solve/integration.hpp"

namespace ffrf::solve {
namespace {


// Forwards every call and counts the right-hand sides (minimal accelerations) of all trials.
class CountingEquations final : public SecondOrderSystem {
 public:
  explicit CountingEquations(SecondOrderSystem& inner) : inner_(inner) {}
  long rhs_evaluations() const { return count_; }

  int minimal_size() const override { return inner_.minimal_size(); }
  Eigen::VectorXd initial_guess() const override { return inner_.initial_guess(); }
  void minimal_accelerations(double t, ConstRef z, ConstRef z_dot, Ref z_ddot) override {
    ++count_;
    inner_.minimal_accelerations(t, z, z_dot, z_ddot);
  }
  void static_residual(ConstRef z, Ref residual) override { inner_.static_residual(z, residual); }
  void minimal_generalized_forces(double t, ConstRef z, ConstRef z_dot, Ref forces) override {
    inner_.minimal_generalized_forces(t, z, z_dot, forces);
  }
  Eigen::VectorXd static_residual_scale() const override { return inner_.static_residual_scale(); }
  Eigen::VectorXd coordinate_scale() const override { return inner_.coordinate_scale(); }
  double minimal_kinetic_energy(double t, ConstRef z, ConstRef z_dot) override { return inner_.minimal_kinetic_energy(t, z, z_dot); }
  int full_size() const override { return inner_.full_size(); }
  void full_from_minimal(double t, ConstRef z, ConstRef z_dot, Ref q, Ref v) const override {
    inner_.full_from_minimal(t, z, z_dot, q, v);
  }
  void full_mass_times(ConstRef q, ConstRef a, Ref out) override { inner_.full_mass_times(q, a, out); }
  void full_forces(double t, ConstRef q, ConstRef v, Ref out) override { inner_.full_forces(t, q, v, out); }
  void constraint(double t, ConstRef q, Ref c) const override { inner_.constraint(t, q, c); }
  void constraint_time_derivative(double t, Ref c_t) const override { inner_.constraint_time_derivative(t, c_t); }
  void constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const override { inner_.constraint_jacobian(q, jacobian); }
  void constraint_rate_terms(double t, ConstRef q, ConstRef v, Ref gamma) const override {
    inner_.constraint_rate_terms(t, q, v, gamma);
  }
  using SecondOrderSystem::full_mass_matrix;
  void full_mass_matrix(ConstRef q, Eigen::MatrixXd& mass) override { inner_.full_mass_matrix(q, mass); }
  int constraint_count() const override { return inner_.constraint_count(); }
  int event_count() const override { return inner_.event_count(); }
  void minimal_events(double t, ConstRef z, Ref g) override { inner_.minimal_events(t, z, g); }
  void full_events(double t, ConstRef q, Ref g) override { inner_.full_events(t, q, g); }

 private:
  SecondOrderSystem& inner_;
  long count_ = 0;
};

// Rays from the imaginary axis (undamped modes) to the negative real axis (overdamped modes).
std::vector<std::complex<double>> left_half_plane_rays() {
  std::vector<std::complex<double>> rays;
  for (int degrees = 90; degrees <= 180; degrees += 5) rays.push_back(std::polar(1.0, degrees * std::numbers::pi / 180.0));
  return rays;
}

}  // namespace

double explicit_mode_step_limit(std::complex<double> eigenvalue) {
  const double size = std::abs(eigenvalue);
  return size > 0.0 ? explicit_ray_boundary(eigenvalue) / size : std::numeric_limits<double>::infinity();
}

long stability_window_steps(const StableStepSearch& search) {
  double slowest_growth = std::numeric_limits<double>::infinity();
  for (const std::complex<double> d : left_half_plane_rays()) {
    const double beyond = (1.0 + 0.5 * search.relative_precision) * explicit_ray_boundary(d);
    slowest_growth = std::min(slowest_growth, std::abs(explicit_stability_function(beyond * d)));
  }
  const double steps = std::log(search.detection_growth) / std::log(slowest_growth);
  return std::max(search.min_window_steps, static_cast<long>(std::ceil(steps)));
}

Eigen::VectorXd stability_seed(SecondOrderSystem& equations, double seed_size) {
  const Eigen::VectorXd scale = equations.coordinate_scale();
  Eigen::VectorXd seed(scale.size());
  for (Eigen::Index j = 0; j < seed.size(); ++j) seed(j) = seed_size * scale(j) * std::cos(2.0 + 2.39996 * static_cast<double>(j));
  return seed;
}

StableStepMeasurement measure_stable_step(SecondOrderSystem& equations, const Eigen::VectorXd& z0, double h0,
                                          const StableStepSearch& search) {
  if (!(h0 > 0.0) || !std::isfinite(h0) || !(search.relative_precision > 0.0)) {
    throw SolverFailure(FailureKind::setup, "ARKODE ERK", "invalid start step " + std::to_string(h0) + " or precision " +
                                          std::to_string(search.relative_precision), 0.0,
                        "give a start step > 0 and a relative precision > 0");
  }
  CountingEquations counted(equations);
  const Eigen::VectorXd start = z0 + stability_seed(equations, search.seed_size);
  StableStepMeasurement m;
  m.window_steps = stability_window_steps(search);
  const long steps_per_output = std::max(1L, m.window_steps / 32);
  const long outputs = (m.window_steps + steps_per_output - 1) / steps_per_output;

  const auto stable = [&](double h) {
    IntegratorSettings settings;
    settings.kind = Integrator::arkode;
    settings.fixed_step = h;
    settings.output_interval = static_cast<double>(steps_per_output) * h;
    settings.duration = static_cast<double>(outputs) * settings.output_interval;
    settings.max_steps = 2 * steps_per_output + 10;
    ++m.trials;
    try {
      DiscardSamples no_samples;  // a trial asks only whether the window completes
      integrate_explicit(counted, no_samples, start, settings);
      return true;
    } catch (const SolverFailure& failure) {
      if (failure.cause().rfind("unstable:", 0) != 0) throw;
      if (m.unstable_step == 0.0 || h < m.unstable_step) m.failure = failure.cause();
      return false;
    }
  };
  const auto within_caps = [&] { return m.trials < search.max_trials && counted.rhs_evaluations() < search.max_rhs_evaluations; };
  const auto record = [&](double h, bool is_stable) {
    m.trial_log.push_back({h, is_stable});
    if (is_stable) {
      m.stable_step = std::max(m.stable_step, h);
    } else if (m.unstable_step == 0.0 || h < m.unstable_step) {
      m.unstable_step = h;
    }
  };

  constexpr double bracket_factor = 1.5;
  double h = h0;
  const bool first = stable(h);
  record(h, first);
  while (within_caps() && (m.stable_step == 0.0 || m.unstable_step == 0.0)) {
    h = first ? h * bracket_factor : h / bracket_factor;
    record(h, stable(h));
  }
  while (m.stable_step > 0.0 && m.unstable_step > 0.0 && m.relative_width() > search.relative_precision && within_caps()) {
    h = std::sqrt(m.stable_step * m.unstable_step);
    record(h, stable(h));
  }
  m.converged = m.stable_step > 0.0 && m.unstable_step > 0.0 && m.relative_width() <= search.relative_precision;
  m.rhs_evaluations = counted.rhs_evaluations();
  return m;
}

}  // namespace ffrf::solve
