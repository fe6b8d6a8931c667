// The free-free mode set in the heel's tangent frame (modal/free_free_modes.hpp), against facts that
// do not use its construction:
//  * the frame's rigid motions and the returned shapes span what the rigid and elastic free-free
//    modes span: each free-free mode of an independent dense solve of the unsupported beam is fitted
//    exactly (least squares over the three rigid motions and the shapes) — the frame changes how a
//    deformation is described, not which deformations the boom can take;
//  * the shapes satisfy the tangent frame's reference condition: on the clamped-free DOFs, they are
//    admissible for the cantilever, so their Ritz values bound the cantilever's eigenvalues from
//    above, λ_i ≥ ω_i² for i = 1..k (Poincaré's separation theorem), and the bound tightens as k grows;
//  * the columns are M-orthonormal and K-orthogonal in the cantilever's mass and stiffness.
#include <gtest/gtest.h>

#include "fem/beam_model.hpp"
#include "fem/mesh.hpp"
#include "linalg/dense_solvers.hpp"
#include "modal/free_free_modes.hpp"
#include "modal/mode_cache.hpp"

namespace {

using namespace ffrf;

const fem::BeamMesh kMesh{120.0, 12, {2.1e11, 1.27, 11.4, 1.0e4}};  // the reference crane's boom, 12 elements

// The three rigid motions of the unsupported beam on all DOFs: u = 1; v = 1; the turn about the root.
Eigen::MatrixXd rigid_motions(const fem::BeamMesh& mesh) {
  Eigen::MatrixXd rigid = Eigen::MatrixXd::Zero(mesh.full_dof_count(), 3);
  for (int node = 0; node < mesh.node_count(); ++node) {
    rigid(fem::full_dof(node, fem::NodeDof::axial), 0) = 1.0;
    rigid(fem::full_dof(node, fem::NodeDof::transverse), 1) = 1.0;
    rigid(fem::full_dof(node, fem::NodeDof::transverse), 2) = mesh.node_position(node);
    rigid(fem::full_dof(node, fem::NodeDof::rotation), 2) = 1.0;
  }
  return rigid;
}

TEST(FreeFreeModes, TheFrameAndTheShapesSpanTheFreeFreeModes) {
  const int k = 6;
  modal::ModeCache cache;
  const fem::BeamModel tangent = fem::make_beam_model(kMesh, fem::Boundary::clamped_free);
  const modal::EigenPairs set = modal::free_free_modes_in_tangent_frame(tangent, k, modal::EigenSolverKind::arpack, cache);
  ASSERT_EQ(set.eigenvectors.cols(), k);

  const fem::BeamModel free = fem::make_beam_model(kMesh, fem::Boundary::free_free);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Eigen::MatrixXd(free.stiffness), Eigen::MatrixXd(free.mass));
  Eigen::MatrixXd basis(kMesh.full_dof_count(), 3 + k);
  basis << rigid_motions(kMesh), Eigen::MatrixXd::Zero(kMesh.full_dof_count(), k);
  for (int j = 0; j < k; ++j) basis.col(3 + j) = fem::extend_to_full(set.eigenvectors.col(j), tangent.dofs);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> fit(basis);
  for (int j = 0; j < k; ++j) {
    const Eigen::VectorXd mode = dense.eigenvectors().col(3 + j);  // after the three rigid modes
    const Eigen::VectorXd residual = basis * fit.solve(mode) - mode;
    EXPECT_LT(residual.norm(), 1e-7 * mode.norm()) << "free-free mode " << j + 1;
  }
  // The next free-free mode is not in the span: the fit is a real test.
  const Eigen::VectorXd outside = dense.eigenvectors().col(3 + k);
  EXPECT_GT((basis * fit.solve(outside) - outside).norm(), 0.1 * outside.norm());
}

TEST(FreeFreeModes, TheirRitzValuesBoundTheCantileversFromAbove) {
  modal::ModeCache cache;
  const fem::BeamModel tangent = fem::make_beam_model(kMesh, fem::Boundary::clamped_free);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> cantilever(Eigen::MatrixXd(tangent.stiffness),
                                                                               Eigen::MatrixXd(tangent.mass));
  Eigen::VectorXd previous;
  for (const int k : {2, 4, 8, 16}) {
    const modal::EigenPairs set = modal::free_free_modes_in_tangent_frame(tangent, k, modal::EigenSolverKind::arpack, cache);
    const Eigen::MatrixXd& shapes = set.eigenvectors;
    const Eigen::MatrixXd mass = shapes.transpose() * (tangent.mass * shapes);
    const Eigen::MatrixXd stiffness = shapes.transpose() * (tangent.stiffness * shapes);
    EXPECT_LT((mass - Eigen::MatrixXd::Identity(k, k)).norm(), 1e-10) << "k = " << k;
    EXPECT_LT((stiffness - Eigen::MatrixXd(set.eigenvalues.asDiagonal())).norm(), 1e-9 * set.eigenvalues.maxCoeff()) << "k = " << k;
    for (int i = 0; i < k; ++i) {
      EXPECT_GE(set.eigenvalues(i), cantilever.eigenvalues()(i) * (1.0 - 1e-10)) << "k = " << k << ", mode " << i + 1;
      if (i < previous.size()) {
        EXPECT_LE(set.eigenvalues(i), previous(i) * (1.0 + 1e-10)) << "k = " << k << ", mode " << i + 1;
      }
    }
    std::printf("k = %2d: first Ritz frequency %.6f Hz, cantilever %.6f Hz\n", k, std::sqrt(set.eigenvalues(0)) / (2 * M_PI),
                std::sqrt(cantilever.eigenvalues()(0)) / (2 * M_PI));
    previous = set.eigenvalues;
  }
}

TEST(FreeFreeModes, OnlyTheTangentFramesDofsAreAccepted) {
  modal::ModeCache cache;
  const fem::BeamModel chord = fem::make_beam_model(kMesh, fem::Boundary::pinned_pinned);
  EXPECT_THROW((void)modal::free_free_modes_in_tangent_frame(chord, 2, modal::EigenSolverKind::arpack, cache), std::invalid_argument);
}

}  // namespace
