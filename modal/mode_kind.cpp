// Mode classification by kinetic-energy share of the axial DOFs, and pairing with the analytic
// Euler–Bernoulli frequencies of the same kind and order.
#include "modal/mode_kind.hpp"

#include <cmath>

namespace ffrf::modal {

std::vector<ClassifiedMode> classify_modes(const fem::BeamMesh& mesh, fem::Boundary boundary, const fem::DofMap& dofs,
                                           const Eigen::SparseMatrix<double>& mass, const Eigen::VectorXd& eigenvalues,
                                           const Eigen::MatrixXd& eigenvectors) {
  // ω² below this is a rigid-body mode: 1 % of the first analytic elastic ω² of the boundary
  // condition (FE frequencies converge from above, so every elastic FE mode lies above it). A
  // relative gap, not an absolute threshold: on fine meshes (N ≳ 1000) round-off in K − σM lifts
  // the rigid modes' ω² far above zero, yet still orders of magnitude below the first elastic one.
  const double first_elastic = fem::analytic_bending_modes(mesh, boundary, 1)[0].angular_frequency;
  const double rigid_limit = 1e-2 * first_elastic * first_elastic;
  Eigen::VectorXd axial_mask = Eigen::VectorXd::Zero(dofs.free_count());
  for (int i = 0; i < dofs.free_count(); ++i) {
    if (dofs.free_to_full[static_cast<std::size_t>(i)] % 3 == static_cast<int>(fem::NodeDof::axial)) axial_mask(i) = 1.0;
  }
  const int count = static_cast<int>(eigenvalues.size());
  const auto bending = fem::analytic_bending_modes(mesh, boundary, count);
  const auto axial = fem::analytic_axial_modes(mesh, boundary, count);
  const int rigid_expected = fem::rigid_mode_count(boundary);

  std::vector<ClassifiedMode> modes;
  int rigid_order = 0, bending_order = 0, axial_order = 0;
  for (int j = 0; j < count; ++j) {
    const Eigen::VectorXd phi = eigenvectors.col(j);
    const Eigen::VectorXd axial_part = phi.cwiseProduct(axial_mask);
    const double total = phi.dot(mass * phi);
    const double share = total > 0.0 ? axial_part.dot(mass * axial_part) / total : 0.0;
    ClassifiedMode mode{};
    mode.axial_energy_share = share;
    if (eigenvalues(j) < rigid_limit) {
      mode.kind = fem::ModeKind::rigid;
      mode.order = ++rigid_order;
      mode.angular_frequency = 0.0;
      if (rigid_order <= rigid_expected) mode.analytic_frequency = 0.0;
    } else if (share > 0.5) {
      mode.kind = fem::ModeKind::axial;
      mode.order = ++axial_order;
      mode.angular_frequency = std::sqrt(eigenvalues(j));
      mode.analytic_frequency = axial[static_cast<std::size_t>(axial_order - 1)].angular_frequency;
    } else {
      mode.kind = fem::ModeKind::bending;
      mode.order = ++bending_order;
      mode.angular_frequency = std::sqrt(eigenvalues(j));
      mode.analytic_frequency = bending[static_cast<std::size_t>(bending_order - 1)].angular_frequency;
    }
    modes.push_back(mode);
  }
  return modes;
}

}  // namespace ffrf::modal
