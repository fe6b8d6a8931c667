// The crane linearised about its static equilibrium (multibody/linearisation.hpp).
#include "multibody/linearisation.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "multibody/crane_equations.hpp"
#include "solve/second_order_jacobian.hpp"

namespace ffrf::multibody {
namespace {

// Central-difference step of the outputs: this fraction of each coordinate's typical size.
constexpr double output_step_fraction = 1e-6;

// The linear outputs' SI values in a sample (the output-channel table's rows with a linear name).
Eigen::VectorXd output_vector(const CraneOutputs& o) {
  Eigen::VectorXd y(linear_output_count);
  for (int i = 0; i < linear_output_count; ++i) y(i) = linear_channel(static_cast<LinearOutput>(i)).extract(o);
  return y;
}

}  // namespace

LinearisedCrane linearise_crane(CraneEquations& calm, const Eigen::VectorXd& equilibrium) {
  const int n = calm.minimal_size();
  if (equilibrium.size() != n) {
    throw std::invalid_argument("linearise_crane: equilibrium has " + std::to_string(equilibrium.size()) +
                                " coordinates, the equations " + std::to_string(n));
  }
  LinearisedCrane linear;
  linear.equilibrium = equilibrium;
  linear.cargo_at = calm.cargo_offset();
  linear.elastic_at = n - calm.elastic_size();
  linear.hull_at = calm.layout().hull;
  for (std::size_t body = 0; body < calm.layout().bodies.size(); ++body) {
    if (!calm.layout().bodies[body].pinned) continue;
    linear.pinned_at.push_back(calm.layout().bodies[body].minimal);
    linear.pinned_names.push_back(calm.body_name(static_cast<int>(body)));
  }
  SecondOrderJacobian blocks(calm.minimal_structure());
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(n);
  calm.minimal_jacobian(0.0, equilibrium, rest, rest, blocks);
  linear.mass = blocks.mass.dense();
  linear.damping = blocks.damping.dense();
  linear.stiffness = blocks.stiffness.dense();
  if (!linear.mass.allFinite() || !linear.damping.allFinite() || !linear.stiffness.allFinite()) {
    throw std::runtime_error("linearise_crane: the mass, damping or stiffness matrix at the static equilibrium is not finite");
  }
  return linear;
}

Eigen::VectorXcd wave_excitation(CraneEquations& waved, const LinearisedCrane& linear, double angular_frequency,
                                 double amplitude) {
  if (!(angular_frequency > 0.0) || !(amplitude > 0.0)) {
    throw std::invalid_argument("wave_excitation: the angular frequency and the amplitude must be positive");
  }
  const int n = linear.size();
  const double period = 2.0 * std::numbers::pi / angular_frequency;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(n);
  const auto force = [&](double t) -> Eigen::VectorXd {
    Eigen::VectorXd q(n);
    waved.minimal_generalized_forces(t, linear.equilibrium, rest, q);  // Q_z itself: no mass matrix solved
    return q;
  };
  const Eigen::VectorXd real = (force(0.0) - force(0.5 * period)) / (2.0 * amplitude);
  const Eigen::VectorXd imaginary = -(force(0.25 * period) - force(0.75 * period)) / (2.0 * amplitude);
  Eigen::VectorXcd excitation(n);
  excitation.real() = real;
  excitation.imag() = imaginary;
  return excitation;
}

OutputMap linear_outputs(CraneEquations& calm, const LinearisedCrane& linear) {
  const int n = linear.size();
  const Eigen::VectorXd scale = calm.coordinate_scale();
  OutputMap map{Eigen::MatrixXd(linear_output_count, n), Eigen::MatrixXd(linear_output_count, n)};
  Eigen::VectorXd z = linear.equilibrium, z_dot = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < n; ++j) {
    const double h = output_step_fraction * scale(j);
    z(j) += h;
    const Eigen::VectorXd plus = output_vector(calm.minimal_outputs(0.0, z, z_dot));
    z(j) -= 2.0 * h;
    const Eigen::VectorXd minus = output_vector(calm.minimal_outputs(0.0, z, z_dot));
    z(j) = linear.equilibrium(j);
    map.position.col(j) = (plus - minus) / (2.0 * h);
    z_dot(j) = h;
    const Eigen::VectorXd faster = output_vector(calm.minimal_outputs(0.0, z, z_dot));
    z_dot(j) = -h;
    const Eigen::VectorXd slower = output_vector(calm.minimal_outputs(0.0, z, z_dot));
    z_dot(j) = 0.0;
    map.velocity.col(j) = (faster - slower) / (2.0 * h);
  }
  return map;
}

}  // namespace ffrf::multibody
