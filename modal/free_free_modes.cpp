// Free-free modes in the heel's tangent frame (see header).
#include "modal/free_free_modes.hpp"

#include <stdexcept>

#include "fem/analytic_beam.hpp"
#include "fem/boundary.hpp"
#include "fem/rigid_motion.hpp"
#include "linalg/dense_solvers.hpp"

namespace ffrf::modal {

EigenPairs free_free_modes_in_tangent_frame(const fem::BeamModel& tangent_beam, int k, EigenSolverKind solver, ModeCache& cache) {
  if (tangent_beam.boundary != fem::Boundary::clamped_free) {
    throw std::invalid_argument("free-free modes are taken in the tangent frame: the beam's DOFs must be clamped-free");
  }
  const fem::BeamMesh& mesh = tangent_beam.mesh;
  const fem::DofMap& tangent = tangent_beam.dofs;
  const int rigid = fem::rigid_mode_count(fem::Boundary::free_free);
  // The rigid modes have ω² = 0 and the first elastic one (βL)⁴ EI/(ρA L⁴), βL = 4.73: the lowest
  // `rigid` eigenpairs are the rigid motions, the next k the elastic modes.
  const EigenPairs all = cache.lowest_modes(mesh, fem::Boundary::free_free, k + rigid, solver);
  const fem::DofMap all_dofs = fem::make_dof_map(mesh, fem::Boundary::free_free);
  const Eigen::VectorXd along = fem::rigid_motion(mesh, all_dofs, fem::RigidMotion::axial_translation);
  const Eigen::VectorXd across = fem::rigid_motion(mesh, all_dofs, fem::RigidMotion::transverse_translation);
  const Eigen::VectorXd turn = fem::rigid_motion(mesh, all_dofs, fem::RigidMotion::turn_about_root);
  Eigen::MatrixXd shapes(tangent.free_count(), k);
  for (int j = 0; j < k; ++j) {
    const Eigen::VectorXd mode = all.eigenvectors.col(rigid + j);
    const Eigen::VectorXd root_motion = mode(fem::full_dof(0, fem::NodeDof::axial)) * along +
                                        mode(fem::full_dof(0, fem::NodeDof::transverse)) * across +
                                        mode(fem::full_dof(0, fem::NodeDof::rotation)) * turn;
    const Eigen::VectorXd in_frame = mode - root_motion;
    shapes.col(j) = fem::restrict_to_free(in_frame, tangent);
  }
  const Eigen::MatrixXd reduced_stiffness = shapes.transpose() * (tangent_beam.stiffness * shapes);
  const Eigen::MatrixXd reduced_mass = shapes.transpose() * (tangent_beam.mass * shapes);
  // The solver below factors the reduced mass by Cholesky without reporting a failure: check it here.
  if (Eigen::LLT<Eigen::MatrixXd>(reduced_mass).info() != Eigen::Success) {
    throw EigenSolverError("the free-free modes taken in the tangent frame are linearly dependent (their mass matrix is "
                           "not positive definite); use fewer modes or more elements");
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(reduced_stiffness, reduced_mass);
  EigenPairs pairs;
  pairs.eigenvalues = ritz.eigenvalues();
  pairs.eigenvectors = shapes * ritz.eigenvectors();  // Xᵀ (ΦᵀMΦ) X = I
  // The solvers' convention: M-normalized, ascending, the sign fixed by the largest entry.
  normalize_and_sort(tangent_beam.mass, pairs.eigenvalues, pairs.eigenvectors);
  pairs.stats = all.stats;
  return pairs;
}

}  // namespace ffrf::modal
