// Default (unstructured) linearizations of a SecondOrderSystem: forward differences of the equations'
// own evaluations, for implementations without analytic blocks.
#include "solve/second_order_system.hpp"

#include <algorithm>
#include <cmath>

namespace ffrf::solve {

namespace {

double increment(double value) { return 1e-7 * std::max(std::abs(value), 1.0); }

}  // namespace

Eigen::VectorXd full_coordinate_scale(SecondOrderSystem& system) {
  const int n = system.full_size();
  const Eigen::VectorXd minimal_scale = system.coordinate_scale();
  Eigen::VectorXd full_scale(n), ignore(n);
  system.full_from_minimal(0.0, minimal_scale, minimal_scale, full_scale, ignore);
  return full_scale.cwiseAbs().cwiseMax(Eigen::VectorXd::Constant(n, 1e-2));
}

void SecondOrderSystem::minimal_jacobian(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, SecondOrderJacobian& out) {
  const int n = minimal_size();
  out.set_zero();
  Eigen::VectorXd x = z, x_dot = z_dot, shifted(n);
  for (int i = 0; i < n; ++i) out.mass.at(i, i) = 1.0;
  for (int j = 0; j < n; ++j) {
    const double dz = increment(z(j)), dv = increment(z_dot(j));
    x(j) += dz;
    minimal_accelerations(t, x, x_dot, shifted);
    x(j) = z(j);
    for (int i = 0; i < n; ++i) out.stiffness.at(i, j) = -(shifted(i) - z_ddot(i)) / dz;
    x_dot(j) += dv;
    minimal_accelerations(t, x, x_dot, shifted);
    x_dot(j) = z_dot(j);
    for (int i = 0; i < n; ++i) out.damping.at(i, j) = -(shifted(i) - z_ddot(i)) / dv;
  }
}

void SecondOrderSystem::full_jacobian(double t, ConstRef q, ConstRef v, ConstRef v_dot, SecondOrderJacobian& out) {
  const int n = full_size();
  out.set_zero();
  Eigen::MatrixXd mass;
  full_mass_matrix(q, mass);
  Eigen::VectorXd x = q, x_dot = v, base(n), shifted(n), inertia(n);
  const auto residual = [&](Eigen::VectorXd& r) {  // Q − M a
    full_forces(t, x, x_dot, r);
    full_mass_times(x, v_dot, inertia);
    r -= inertia;
  };
  residual(base);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) out.mass.at(i, j) = mass(i, j);
    const double dq = increment(q(j)), dv = increment(v(j));
    x(j) += dq;
    residual(shifted);
    x(j) = q(j);
    for (int i = 0; i < n; ++i) out.stiffness.at(i, j) = -(shifted(i) - base(i)) / dq;
    x_dot(j) += dv;
    residual(shifted);
    x_dot(j) = v(j);
    for (int i = 0; i < n; ++i) out.damping.at(i, j) = -(shifted(i) - base(i)) / dv;
  }
}

}  // namespace ffrf::solve
