// A modal basis Φ = [k vibration modes | static correction modes], M-orthonormal (ΦᵀMΦ = I):
// the static modes are made M-orthogonal to the kept vibration modes and to each other (modified
// Gram–Schmidt in the M inner product, twice) and a static mode that the vibration modes already
// span (M-norm of the remainder below 1e-8 of its original) is dropped and reported.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/static_modes.hpp"

namespace ffrf::modal {

struct ModalBasisRequest {
  int vibration_modes = 4;               // k
  bool static_correction = false;        // add static modes for `loads`
  std::vector<UnitLoad> loads;           // empty with static_correction = default tip loads
  EigenSolverKind solver = EigenSolverKind::arpack;
};

struct ModalBasis {
  Eigen::MatrixXd vectors;               // n × (k + s), M-orthonormal columns, free DOFs
  Eigen::VectorXd vibration_eigenvalues; // ω² of the k vibration modes
  int vibration_count = 0;               // k
  std::vector<UnitLoad> static_loads;    // the loads whose static modes were kept
  std::vector<UnitLoad> dropped_loads;   // static modes already spanned by the vibration modes
};

// Builds Φ for the clamped-free mesh: k vibration modes from `solver`, then static modes.
ModalBasis make_modal_basis(const fem::BeamMesh& mesh, const fem::DofMap& dofs,
                            const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                            const ModalBasisRequest& request);

// Appends static modes to given vibration modes (M-orthonormal columns) — the step above.
ModalBasis append_static_modes(const fem::BeamMesh& mesh, const fem::DofMap& dofs,
                               const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
                               const Eigen::MatrixXd& vibration_vectors, const Eigen::VectorXd& vibration_eigenvalues,
                               const std::vector<UnitLoad>& loads);

}  // namespace ffrf::modal
