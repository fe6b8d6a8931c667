// Test helpers for the boom alone on a held hull: the crane's parameters with the hull held at a pose
// (no water), without the cargo and its hoist wire (a pinned heel keeps its luffing wires), and the
// natural frequencies of such a crane's linearisation about a state.
#pragma once

#include <Eigen/Dense>
#include <memory>

#include "multibody/crane_model.hpp"
#include "multibody/linearisation.hpp"
#include "linalg/dense_solvers.hpp"

namespace ffrf::test {

// `model` with its hull held at `pose` (x, y, θ), no hydrostatics, no cargo, no hoist wire.
template <class Parameters>
std::unique_ptr<multibody::CraneEquations> held_boom(Parameters model, const Eigen::Vector3d& pose) {
  model.hull.fixed = true;
  model.hull.hydrostatics = false;
  model.hull.support_pose = pose;
  multibody::remove_cargo(model);
  return multibody::make_crane_equations(std::move(model));
}

// The held hull's pose that lays the boom level (its frame at the hull's angle plus boom.angle).
template <class Parameters>
Eigen::Vector3d level_boom_pose(const Parameters& model) {
  return Eigen::Vector3d(0.0, 0.0, -model.mount.angle);
}

// The natural frequencies ω [rad/s], ascending, of K φ = ω² M φ of the crane linearised about z
// (M and K symmetrised; negative eigenvalues clipped to zero).
inline Eigen::VectorXd natural_frequencies(multibody::CraneEquations& equations, const Eigen::VectorXd& z) {
  const multibody::LinearisedCrane linear = multibody::linearise_crane(equations, z);
  const Eigen::MatrixXd stiffness = 0.5 * (linear.stiffness + linear.stiffness.transpose());
  const Eigen::MatrixXd mass = 0.5 * (linear.mass + linear.mass.transpose());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass);
  return solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace ffrf::test
