// Classifies an FE mode shape as rigid, bending or axial: a mode whose ω² is negligible against
// the stiffness scale is rigid; otherwise the share of its kinetic energy (φᵀMφ restricted to the
// axial DOFs) decides axial (> 1/2) or bending. Pairs FE modes with analytic Euler–Bernoulli modes
// of the same kind in order.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <optional>
#include <vector>

#include "fem/analytic_beam.hpp"
#include "fem/boundary.hpp"

namespace ffrf::modal {

struct ClassifiedMode {
  double angular_frequency;                      // FE ω [rad/s] (0 for rigid modes)
  fem::ModeKind kind;
  int order;                                     // 1-based within its kind
  std::optional<double> analytic_frequency;      // analytic ω where one exists [rad/s]
  double axial_energy_share;                     // in [0, 1]
};

// eigenvalues ω² ascending and M-normalized eigenvectors on the free DOFs of `dofs`.
std::vector<ClassifiedMode> classify_modes(const fem::BeamMesh& mesh, fem::Boundary boundary,
                                           const fem::DofMap& dofs, const Eigen::SparseMatrix<double>& mass,
                                           const Eigen::VectorXd& eigenvalues, const Eigen::MatrixXd& eigenvectors);

}  // namespace ffrf::modal
