// Explicit step limits of the boom and the wire–cargo mode (see stability_theory.hpp).
#include "study/stability_theory.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <limits>

#include "solve/explicit_stability.hpp"
#include "multibody/crane_run.hpp"
#include "linalg/dense_solvers.hpp"

namespace ffrf::study {
namespace {

Eigen::VectorXd frequencies(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass) {
  if (stiffness.rows() == 0) return Eigen::VectorXd(0);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass, Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success) {
    throw solve::SolverFailure(solve::FailureKind::model_error, "Eigen generalized eigen solver", "K φ = ω² M φ of the boom did not converge", 0.0,
                                  "check the boom section and mass values");
  }
  return solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace

Eigen::VectorXd boom_angular_frequencies(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* cache) {
  if (choice.kind == scene::BoomKind::rigid) return Eigen::VectorXd(0);
  if (choice.kind == scene::BoomKind::nodal) {
    const nodal::NodalCoordinates coords(scene::boom_beam(scene, choice.elements));
    return frequencies(Eigen::MatrixXd(coords.stiffness()), Eigen::MatrixXd(coords.mass_ff()));
  }
  const modal::ModalCoordinates coords = scene::modal_coordinates(scene, choice, cache);
  return frequencies(coords.stiffness(), coords.mass_ff());
}

double highest_boom_frequency(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* cache) {
  const Eigen::VectorXd omega = boom_angular_frequencies(scene, choice, cache);
  return omega.size() == 0 ? 0.0 : omega.maxCoeff();
}

double undamped_boom_step_limit(double highest_frequency) {
  return highest_frequency > 0.0 ? solve::explicit_imaginary_axis_boundary() / highest_frequency
                                 : std::numeric_limits<double>::infinity();
}

double damped_boom_step_limit(const Eigen::VectorXd& angular_frequencies, double stiffness_damping) {
  double limit = std::numeric_limits<double>::infinity();
  for (const double omega : angular_frequencies) {
    if (!(omega > 0.0)) continue;
    const double zeta = 0.5 * stiffness_damping * omega;
    // Roots of λ² + 2ζωλ + ω² = 0: the one with the larger |λ| (both share the ray when ζ < 1).
    const std::complex<double> root = std::sqrt(std::complex<double>(zeta * zeta - 1.0, 0.0));
    const std::complex<double> lambda = omega * (-zeta - (zeta >= 1.0 ? root : -root));
    limit = std::min(limit, solve::explicit_mode_step_limit(lambda));
  }
  return limit;
}

double wire_cargo_frequency(const scene::Scene& scene) {
  if (!scene.wire || !scene.cargo) return 0.0;
  return std::sqrt(scene.wire->stiffness / scene.cargo->mass);
}

}  // namespace ffrf::study
