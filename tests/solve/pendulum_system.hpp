// A planar pendulum (point mass m on a massless rod of length L, pivot at the origin, gravity −y) as
// a SecondOrderSystem, for the solver room's tests on a system that is not the crane:
//  * minimal coordinate θ (from the downward vertical): m L² θ̈ = −m g L sin θ;
//  * full coordinates q = (x, y) with one constraint C = x² + y² − L² = 0 (C_q = [2x, 2y],
//    γ = −(C_q v)_q v = −2 |v|²) and multiplier λ: M q̈ = (0, −m g) − C_qᵀλ;
//  * one event function, the horizontal position x (zero when the pendulum passes the vertical).
#pragma once

#include <cmath>

#include "solve/second_order_system.hpp"

namespace ffrf::test {

class PendulumSystem final : public solve::SecondOrderSystem {
 public:
  static constexpr double mass = 2.0, length = 1.5, gravity = 9.81;

  int minimal_size() const override { return 1; }
  Eigen::VectorXd initial_guess() const override { return Eigen::VectorXd::Zero(1); }
  void minimal_accelerations(double, ConstRef z, ConstRef, Ref z_ddot) override {
    z_ddot(0) = -gravity / length * std::sin(z(0));
  }
  void static_residual(ConstRef z, Ref residual) override { residual(0) = -mass * gravity * length * std::sin(z(0)); }
  void minimal_generalized_forces(double, ConstRef z, ConstRef, Ref forces) override { static_residual(z, forces); }
  Eigen::VectorXd static_residual_scale() const override { return Eigen::VectorXd::Constant(1, 1.0 / (mass * gravity * length)); }
  Eigen::VectorXd coordinate_scale() const override { return Eigen::VectorXd::Ones(1); }
  double minimal_kinetic_energy(double, ConstRef, ConstRef z_dot) override {
    return 0.5 * mass * length * length * z_dot(0) * z_dot(0);
  }

  int full_size() const override { return 2; }
  int constraint_count() const override { return 1; }
  void full_from_minimal(double, ConstRef z, ConstRef z_dot, Ref q, Ref v) const override {
    q << length * std::sin(z(0)), -length * std::cos(z(0));
    v << length * std::cos(z(0)) * z_dot(0), length * std::sin(z(0)) * z_dot(0);
  }
  void full_mass_times(ConstRef, ConstRef a, Ref out) override { out = mass * a; }
  void full_forces(double, ConstRef, ConstRef, Ref out) override { out << 0.0, -mass * gravity; }
  void constraint(double, ConstRef q, Ref c) const override { c(0) = q.squaredNorm() - length * length; }
  void constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const override {
    jacobian.resize(1, 2);
    jacobian << 2.0 * q(0), 2.0 * q(1);
  }
  void constraint_time_derivative(double, Ref c_t) const override { c_t(0) = 0.0; }
  void constraint_rate_terms(double, ConstRef, ConstRef v, Ref gamma) const override { gamma(0) = -2.0 * v.squaredNorm(); }
  using SecondOrderSystem::full_mass_matrix;
  void full_mass_matrix(ConstRef, Eigen::MatrixXd& mass_matrix) override {
    mass_matrix = mass * Eigen::MatrixXd::Identity(2, 2);
  }

  int event_count() const override { return 1; }
  void minimal_events(double, ConstRef z, Ref g) override { g(0) = length * std::sin(z(0)); }
  void full_events(double, ConstRef q, Ref g) override { g(0) = q(0); }

  // The period of the swing released at rest from θ0: T = 4 √(L/g) K(sin(θ0/2)) (complete elliptic
  // integral of the first kind, modulus k).
  static double period(double amplitude) {
    return 4.0 * std::sqrt(length / gravity) * std::comp_ellint_1(std::sin(0.5 * amplitude));
  }
};

// Records the angle and the total energy at each output time, from either coordinate set.
class PendulumRecorder final : public solve::OutputSink {
 public:
  std::vector<double> angle, energy;

  void minimal_sample(double, ConstRef z, ConstRef z_dot) override {
    keep(z(0), 0.5 * PendulumSystem::mass * std::pow(PendulumSystem::length * z_dot(0), 2),
         -PendulumSystem::length * std::cos(z(0)));
  }
  void full_sample(double, ConstRef q, ConstRef v, ConstRef) override {
    keep(std::atan2(q(0), -q(1)), 0.5 * PendulumSystem::mass * v.squaredNorm(), q(1));
  }

 private:
  void keep(double theta, double kinetic, double height) {
    angle.push_back(theta);
    energy.push_back(kinetic + PendulumSystem::mass * PendulumSystem::gravity * height);
  }
};

}  // namespace ffrf::test
