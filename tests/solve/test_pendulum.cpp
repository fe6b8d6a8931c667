// The solver room on a system that is not the crane: a pendulum (tests/solve/pendulum_system.hpp)
// integrated by every row of the integrator table, checked against the exact period of the
// nonlinear pendulum (complete elliptic integral), energy conservation and the located events; and
// the static solver on it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "solve/integration.hpp"
#include "solve/integrator_table.hpp"
#include "solve/static_equilibrium.hpp"
#include "tests/solve/pendulum_system.hpp"

namespace ffrf {
namespace {

using test::PendulumRecorder;
using test::PendulumSystem;

constexpr double amplitude = 1.0;  // released at rest from 1 rad (57°): far from the linear pendulum

solve::IntegratorSettings settings_for(const solve::IntegratorEntry& entry) {
  solve::IntegratorSettings settings;
  settings.kind = entry.choice;
  settings.relative_tolerance = 1e-10;
  settings.absolute_tolerance = 1e-12;
  settings.duration = 6.0;
  settings.output_interval = 0.01;
  if (entry.choice == solve::Integrator::generalized_alpha) {
    // Its Newton iteration stops at rtol|q| + atol·scale: tolerances far below the step's own error
    // only ask it to converge into round-off.
    settings.relative_tolerance = 1e-8;
    settings.absolute_tolerance = 1e-10;
    settings.fixed_step = 2e-4;
    settings.spectral_radius = 1.0;  // no numerical dissipation
  }
  return settings;
}

TEST(PendulumOnEveryIntegrator, CrossesTheVerticalAtTheQuartersOfTheEllipticPeriod) {
  const double period = PendulumSystem::period(amplitude);
  ASSERT_NEAR(period, 2.0 * M_PI * std::sqrt(PendulumSystem::length / PendulumSystem::gravity) * 1.0663, 1e-3 * period)
      << "the period of a 1-rad swing is 6.6 % longer than the linear pendulum's";
  for (const solve::IntegratorEntry& entry : solve::integrator_table()) {
    SCOPED_TRACE(std::string(entry.name));
    PendulumSystem pendulum;
    PendulumRecorder recorder;
    const solve::IntegratorSettings settings = settings_for(entry);
    const solve::IntegrationRecord record =
        solve::integrate(pendulum, recorder, Eigen::VectorXd::Constant(1, amplitude), settings);

    // Every output time sampled once.
    ASSERT_EQ(record.time.size(), 601u);
    ASSERT_EQ(recorder.angle.size(), record.time.size());
    EXPECT_NEAR(recorder.angle.front(), amplitude, 1e-12);

    // x = 0 at T/4, 3T/4, 5T/4, ... : falling first (x > 0 at release), then alternating.
    const double tolerance = entry.choice == solve::Integrator::generalized_alpha ? 2e-5 : 2e-6;
    ASSERT_EQ(record.events.size(), 5u);
    for (std::size_t k = 0; k < record.events.size(); ++k) {
      EXPECT_EQ(record.events[k].index, 0);
      EXPECT_EQ(record.events[k].falling, k % 2 == 0) << "event " << k;
      EXPECT_NEAR(record.events[k].time, (2.0 * static_cast<double>(k) + 1.0) * period / 4.0, tolerance * period) << "event " << k;
    }

    // Energy conserved (no damping anywhere): within 10⁻⁶ of m g L.
    const double energy_scale = PendulumSystem::mass * PendulumSystem::gravity * PendulumSystem::length;
    for (const double energy : recorder.energy) EXPECT_NEAR(energy, recorder.energy.front(), 1e-6 * energy_scale);

    EXPECT_GT(record.stats.steps, 0);
  }
}

TEST(PendulumStatics, HangsStraightDown) {
  PendulumSystem pendulum;
  const solve::StaticSolution rest = solve::solve_static_equilibrium(pendulum, Eigen::VectorXd::Constant(1, 0.4));
  EXPECT_NEAR(rest.z(0), 0.0, 1e-9);
  EXPECT_GT(rest.newton_iterations, 0);
}

// A torque the pendulum cannot balance (more than m g L): the static solver names the row.
class OverloadedPendulum final : public solve::SecondOrderSystem {
 public:
  int minimal_size() const override { return 1; }
  Eigen::VectorXd initial_guess() const override { return Eigen::VectorXd::Zero(1); }
  void minimal_accelerations(double, ConstRef z, ConstRef z_dot, Ref z_ddot) override { pendulum_.minimal_accelerations(0.0, z, z_dot, z_ddot); }
  void static_residual(ConstRef z, Ref residual) override {
    pendulum_.static_residual(z, residual);
    residual(0) += 1.5 * PendulumSystem::mass * PendulumSystem::gravity * PendulumSystem::length;
  }
  void minimal_generalized_forces(double, ConstRef z, ConstRef, Ref forces) override { static_residual(z, forces); }
  Eigen::VectorXd static_residual_scale() const override { return pendulum_.static_residual_scale(); }
  Eigen::VectorXd coordinate_scale() const override { return pendulum_.coordinate_scale(); }
  double minimal_kinetic_energy(double t, ConstRef z, ConstRef z_dot) override { return pendulum_.minimal_kinetic_energy(t, z, z_dot); }
  solve::ResidualRow residual_row(int) const override { return {"the pendulum's moment about its pivot", "lighten the torque", true, true}; }
  int full_size() const override { return 2; }
  int constraint_count() const override { return 1; }
  void full_from_minimal(double t, ConstRef z, ConstRef z_dot, Ref q, Ref v) const override { pendulum_.full_from_minimal(t, z, z_dot, q, v); }
  void full_mass_times(ConstRef q, ConstRef a, Ref out) override { pendulum_.full_mass_times(q, a, out); }
  void full_forces(double t, ConstRef q, ConstRef v, Ref out) override { pendulum_.full_forces(t, q, v, out); }
  void constraint(double t, ConstRef q, Ref c) const override { pendulum_.constraint(t, q, c); }
  void constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const override { pendulum_.constraint_jacobian(q, jacobian); }
  void constraint_time_derivative(double t, Ref c_t) const override { pendulum_.constraint_time_derivative(t, c_t); }
  void constraint_rate_terms(double t, ConstRef q, ConstRef v, Ref gamma) const override { pendulum_.constraint_rate_terms(t, q, v, gamma); }
  using SecondOrderSystem::full_mass_matrix;
  void full_mass_matrix(ConstRef q, Eigen::MatrixXd& mass) override { pendulum_.full_mass_matrix(q, mass); }

 private:
  mutable PendulumSystem pendulum_;
};

TEST(PendulumStatics, NamesTheRowThatStaysOutOfBalance) {
  OverloadedPendulum pendulum;
  try {
    solve::solve_static_equilibrium(pendulum, Eigen::VectorXd::Zero(1));
    FAIL() << "a torque of 1.5 m g L has no balance";
  } catch (const solve::SolverFailure& failure) {
    EXPECT_EQ(failure.kind(), solve::FailureKind::newton_divergence);
    EXPECT_NE(failure.cause().find("the pendulum's moment about its pivot stays out of balance"), std::string::npos)
        << failure.cause();
    EXPECT_NE(failure.cause().find(" N m"), std::string::npos) << failure.cause();
    EXPECT_EQ(failure.remedy(), "lighten the torque");
  }
}

}  // namespace
}  // namespace ffrf
