// Modal basis construction: k vibration modes from the eigen solver, then static correction modes
// M-orthogonalized against them by modified Gram–Schmidt in the M inner product (two passes,
// "twice is enough", Giraud et al. 2005) and M-normalized.
#include "modal/modal_basis.hpp"

#include <cmath>

namespace ffrf::modal {

ModalBasis make_modal_basis(const fem::BeamMesh& mesh, const fem::DofMap& dofs,
                            const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                            const ModalBasisRequest& request) {
  if (request.vibration_modes < 0) throw EigenSolverError("number of vibration modes must be >= 0");
  Eigen::MatrixXd vibration(dofs.free_count(), 0);
  Eigen::VectorXd eigenvalues(0);
  if (request.vibration_modes > 0) {
    EigenRequest eigen;
    eigen.nev = request.vibration_modes;
    eigen.sigma = 0.0;  // clamped reference condition: K is positive definite
    EigenPairs pairs = solve_generalized(stiffness, mass, eigen, request.solver);
    vibration = std::move(pairs.eigenvectors);
    eigenvalues = std::move(pairs.eigenvalues);
  }
  std::vector<UnitLoad> loads;
  if (request.static_correction) loads = request.loads.empty() ? tip_unit_loads(mesh) : request.loads;
  return append_static_modes(mesh, dofs, stiffness, mass, vibration, eigenvalues, loads);
}

ModalBasis append_static_modes(const fem::BeamMesh& mesh, const fem::DofMap& dofs,
                               const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                               const Eigen::MatrixXd& vibration_vectors, const Eigen::VectorXd& vibration_eigenvalues,
                               const std::vector<UnitLoad>& loads) {
  ModalBasis basis;
  basis.vibration_count = static_cast<int>(vibration_vectors.cols());
  basis.vibration_eigenvalues = vibration_eigenvalues;
  const Eigen::MatrixXd raw = loads.empty() ? Eigen::MatrixXd(dofs.free_count(), 0)
                                            : static_modes(mesh, dofs, stiffness, loads);
  Eigen::MatrixXd columns(dofs.free_count(), vibration_vectors.cols() + raw.cols());
  columns.leftCols(vibration_vectors.cols()) = vibration_vectors;
  Eigen::Index kept = vibration_vectors.cols();
  for (Eigen::Index j = 0; j < raw.cols(); ++j) {
    Eigen::VectorXd r = raw.col(j);
    const double original = std::sqrt(r.dot(mass * r));
    for (int pass = 0; pass < 2; ++pass) {
      for (Eigen::Index c = 0; c < kept; ++c) {
        const Eigen::VectorXd m_col = mass * columns.col(c);
        r -= m_col.dot(r) * columns.col(c);
      }
    }
    const double remainder = std::sqrt(r.dot(mass * r));
    // (A load on a DOF the reference condition fixes, e.g. a transverse tip load in the chord frame,
    // moves nothing: dropped like a load the vibration modes already span.)
    if (!(original > 0.0) || remainder < 1e-8 * original) {
      basis.dropped_loads.push_back(loads[static_cast<std::size_t>(j)]);
      continue;
    }
    columns.col(kept++) = r / remainder;
    basis.static_loads.push_back(loads[static_cast<std::size_t>(j)]);
  }
  basis.vectors = columns.leftCols(kept);
  return basis;
}

}  // namespace ffrf::modal
