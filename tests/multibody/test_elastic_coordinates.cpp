// The two elastic coordinates of the floating-frame boom against each other: a modal basis of all
// free DOFs (dense eigenvectors computed here, independent of the ARPACK wrapper) reproduces every
// nodal inertia invariant, the stiffness, the geometric stiffness and the shape rows exactly, and
// its projected mass gives back the nodal one.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <memory>

#include "linalg/dense_solvers.hpp"
#include "modal/modal_coordinates.hpp"
#include "nodal/nodal_coordinates.hpp"
#include "../modal/cantilever_test_beam.hpp"

namespace elastic_coordinates_test {

using namespace ffrf;

using test::cantilever;

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

}  // namespace elastic_coordinates_test
