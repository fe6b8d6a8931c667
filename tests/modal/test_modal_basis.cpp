// Modal basis: static correction modes equal the FE static solution of their unit loads (dense
// solve here); the basis is M-orthonormal and spans the static solution exactly. (The modal
// coordinates against the nodal ones: tests/coupling/test_elastic_coordinates.cpp.)
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <memory>

#include "fem/point_shape.hpp"
#include "modal/modal_coordinates.hpp"
#include "linalg/dense_solvers.hpp"
#include "cantilever_test_beam.hpp"

namespace {

using namespace ffrf;

using test::cantilever;

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


}  // namespace
