// Cantilever statics against Euler–Bernoulli theory: tip load P → tip deflection PL³/(3EI) and
// rotation PL²/(2EI) (exact for Hermite elements), uniform load w → wL⁴/(8EI) (exact at the
// nodes with consistent loads), axial tip load → PL/(EA); and the clamped–free column buckles at
// the Euler load π²EI/(4L²) (eigenproblem (K + λK_g(−1 N))φ = 0 solved densely here).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <numbers>

#include "fem/assembly.hpp"
#include "fem/point_shape.hpp"
#include "linalg/dense_solvers.hpp"

namespace {

using namespace ffrf::fem;

const BeamMesh cantilever{10.0, 8, {2.1e11, 0.01, 8.333e-6, 78.5}};

Eigen::VectorXd solve_static(const BeamMesh& mesh, const Eigen::VectorXd& load) {
  const FreeMatrices m = assemble_free(mesh, Boundary::clamped_free);
  Eigen::SimplicialLDLT<SparseMatrix> solver(m.stiffness);
  return solver.solve(load);
}

TEST(StaticDeflection, TipLoadGivesPL3Over3EI) {
  const DofMap dofs = make_dof_map(cantilever, Boundary::clamped_free);
  const double force = 1.0e4, ei = cantilever.section.bending_rigidity(), length = cantilever.length;
  const Eigen::VectorXd q = solve_static(cantilever, point_load(cantilever, dofs, length, {0.0, force}, 0.0));
  const PointShape tip = point_shape(cantilever, dofs, length);
  const double deflection = (tip.displacement * q)(1);
  const double rotation = (tip.rotation * q)(0);
  EXPECT_NEAR(deflection, force * length * length * length / (3 * ei), 1e-10 * std::abs(deflection));
  EXPECT_NEAR(rotation, force * length * length / (2 * ei), 1e-10 * std::abs(rotation));
  // Mid-span: v(x) = P x²(3L − x)/(6EI), exact inside elements too.
  const double x = 0.37 * length;
  const double mid = (point_shape(cantilever, dofs, x).displacement * q)(1);
  EXPECT_NEAR(mid, force * x * x * (3 * length - x) / (6 * ei), 1e-10 * std::abs(mid));
}

TEST(StaticDeflection, UniformLoadGiveswL4Over8EI) {
  const DofMap dofs = make_dof_map(cantilever, Boundary::clamped_free);
  const double w = 750.0, ei = cantilever.section.bending_rigidity(), length = cantilever.length;
  const Eigen::VectorXd q = solve_static(cantilever, distributed_load(cantilever, dofs, {0.0, w}));
  const double deflection = (point_shape(cantilever, dofs, length).displacement * q)(1);
  EXPECT_NEAR(deflection, w * std::pow(length, 4) / (8 * ei), 1e-10 * std::abs(deflection));
}

TEST(StaticDeflection, AxialTipLoadGivesPLOverEA) {
  const DofMap dofs = make_dof_map(cantilever, Boundary::clamped_free);
  const double force = -2.0e5;
  const Eigen::VectorXd q = solve_static(cantilever, point_load(cantilever, dofs, cantilever.length, {force, 0.0}, 0.0));
  const double stretch = (point_shape(cantilever, dofs, cantilever.length).displacement * q)(0);
  EXPECT_NEAR(stretch, force * cantilever.length / cantilever.section.axial_rigidity(), 1e-12 * std::abs(stretch));
}

TEST(StaticDeflection, ClampedFreeColumnBucklesAtEulerLoad) {
  const BeamMesh column{10.0, 32, cantilever.section};
  const FreeMatrices m = assemble_free(column, Boundary::clamped_free);
  const Eigen::MatrixXd stiffness(m.stiffness);
  const Eigen::MatrixXd unit_tension(restrict_to_free(assemble_geometric_stiffness(column, 1.0), m.dofs));
  // Compression P: (K − P K_g(1)) φ = 0  ⇔  K_g(1) φ = (1/P) K φ; the largest 1/P is the critical load.
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(unit_tension, stiffness);
  ASSERT_EQ(solver.info(), Eigen::Success);
  const double critical = 1.0 / solver.eigenvalues().maxCoeff();
  const double euler = std::numbers::pi * std::numbers::pi * column.section.bending_rigidity() / (4 * column.length * column.length);
  EXPECT_NEAR(critical / euler, 1.0, 1e-4);
}

}  // namespace
