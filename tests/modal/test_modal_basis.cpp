// Modal basis and modal coordinates: static correction modes equal the FE static solution of
// their unit loads (dense solve here); the basis is M-orthonormal and spans the static solution
// exactly; a basis of all free DOFs (dense eigenvectors computed here) reproduces every nodal
// invariant, the stiffness and the shape rows exactly.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <memory>

#include "fem/point_shape.hpp"
#include "modal/modal_coordinates.hpp"
#include "nodal/nodal_coordinates.hpp"
#include "linalg/dense_solvers.hpp"

namespace {

using namespace ffrf;

std::shared_ptr<const fem::BeamModel> cantilever(int elements) {
  return std::make_shared<const fem::BeamModel>(
      fem::make_beam_model({10.0, elements, {2.1e11, 0.01, 8.333e-6, 78.5}}, fem::Boundary::clamped_free));
}

TEST(StaticModes, EqualTheStaticSolutionOfTheirUnitLoads) {
  const auto beam = cantilever(12);
  const auto loads = modal::tip_unit_loads(beam->mesh);
  const Eigen::MatrixXd modes = modal::static_modes(beam->mesh, beam->dofs, beam->stiffness, loads);
  const Eigen::MatrixXd dense_k(beam->stiffness);
  const Eigen::VectorXd tip_transverse = fem::point_load(beam->mesh, beam->dofs, 10.0, {0.0, 1.0}, 0.0);
  const Eigen::VectorXd reference = dense_k.ldlt().solve(tip_transverse);
  EXPECT_LT((modes.col(1) - reference).norm(), 1e-10 * reference.norm());
  const double ei = beam->mesh.section.bending_rigidity();
  const double tip = (fem::point_shape(beam->mesh, beam->dofs, 10.0).displacement * modes.col(1))(1);
  EXPECT_NEAR(tip, 1000.0 / (3 * ei), 1e-10 * tip);
}

TEST(ModalBasis, IsMOrthonormalAndSpansTheStaticSolutions) {
  const auto beam = cantilever(20);
  // Vibration modes from a dense solve (independent of the ARPACK wrapper).
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(beam->stiffness), Eigen::MatrixXd(beam->mass)};
  const int k = 2;
  const modal::ModalBasis basis = modal::append_static_modes(beam->mesh, beam->dofs, beam->stiffness, beam->mass,
                                                             dense.eigenvectors().leftCols(k), dense.eigenvalues().head(k),
                                                             modal::tip_unit_loads(beam->mesh));
  ASSERT_EQ(basis.vectors.cols(), k + 3);
  EXPECT_TRUE(basis.dropped_loads.empty());
  const Eigen::MatrixXd gram = basis.vectors.transpose() * (beam->mass * basis.vectors);
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(k + 3, k + 3)).norm(), 1e-10);
  const Eigen::MatrixXd raw = modal::static_modes(beam->mesh, beam->dofs, beam->stiffness, modal::tip_unit_loads(beam->mesh));
  for (int j = 0; j < 3; ++j) {
    const Eigen::VectorXd projected = basis.vectors * (basis.vectors.transpose() * (beam->mass * raw.col(j)));
    EXPECT_LT((projected - raw.col(j)).norm(), 1e-10 * raw.col(j).norm()) << "static mode " << j;
  }
}

TEST(ModalBasis, DropsAStaticModeTheVibrationModesAlreadySpan) {
  const auto beam = cantilever(3);  // 9 DOFs: all vibration modes span everything
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(beam->stiffness), Eigen::MatrixXd(beam->mass)};
  const modal::ModalBasis basis = modal::append_static_modes(beam->mesh, beam->dofs, beam->stiffness, beam->mass,
                                                             dense.eigenvectors(), dense.eigenvalues(),
                                                             modal::tip_unit_loads(beam->mesh));
  EXPECT_EQ(basis.vectors.cols(), 9);
  EXPECT_EQ(basis.dropped_loads.size(), 3u);
}

TEST(ModalCoordinates, FullBasisReproducesNodalInvariantsExactly) {
  const auto beam = cantilever(6);
  const nodal::NodalCoordinates nodal(beam);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(beam->stiffness), Eigen::MatrixXd(beam->mass)};
  modal::ModalBasis basis;
  basis.vectors = dense.eigenvectors();
  basis.vibration_count = static_cast<int>(basis.vectors.cols());
  const modal::ModalCoordinates modal(beam, basis);
  ASSERT_EQ(modal.size(), nodal.size());
  const Eigen::VectorXd eta = Eigen::VectorXd::LinSpaced(modal.size(), -1.0, 1.0).array().sin() * 1e-3;
  const Eigen::VectorXd eta_dot = Eigen::VectorXd::LinSpaced(modal.size(), 0.3, 2.0).array().cos() * 1e-3;
  const Eigen::VectorXd q = modal.to_nodal(eta), q_dot = modal.to_nodal(eta_dot);
  const double tol = 1e-12;
  auto rel = [](double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); };
  EXPECT_LT((modal.shape_integral() * eta - nodal.shape_integral() * q).norm(), tol * (nodal.shape_integral() * q).norm());
  EXPECT_LT(rel(modal.u0_dot_shape().dot(eta), nodal.u0_dot_shape().dot(q)), tol);
  EXPECT_LT(rel(modal.u0_cross_shape().dot(eta), nodal.u0_cross_shape().dot(q)), tol);
  EXPECT_LT(rel(eta.dot(modal.mass_ff() * eta_dot), q.dot(nodal.mass_ff() * q_dot)), tol);
  EXPECT_LT(rel(eta.dot(modal.skew_ff() * eta_dot), q.dot(nodal.skew_ff() * q_dot)), 1e-10);
  EXPECT_LT(rel(eta.dot(modal.stiffness() * eta), q.dot(nodal.stiffness() * q)), tol);
  EXPECT_LT(rel(eta.dot(modal.unit_geometric_stiffness() * eta), q.dot(nodal.unit_geometric_stiffness() * q)), tol);
  for (double x : {2.5, 10.0}) {
    EXPECT_LT((modal.displacement_rows(x) * eta - nodal.displacement_rows(x) * q).norm(), tol * (nodal.displacement_rows(x) * q).norm());
    EXPECT_LT(rel((modal.rotation_row(x) * eta)(0), (nodal.rotation_row(x) * q)(0)), tol);
  }
  // Φ is square and invertible, so the projected matrices determine the nodal ones: Φ⁻ᵀ(ΦᵀMΦ)Φ⁻¹ = M.
  const Eigen::MatrixXd phi_inv = basis.vectors.inverse();
  const Eigen::MatrixXd back = phi_inv.transpose() * modal.mass_ff() * phi_inv;
  EXPECT_LT((back - Eigen::MatrixXd(nodal.mass_ff())).norm(), 1e-10 * nodal.mass_ff().norm());
}

}  // namespace
