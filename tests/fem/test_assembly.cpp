// Assembled beam matrices: the consistent mass integrates the beam's mass, first and second
// moments exactly (rigid translation and rotation fields of a free–free beam), the stiffness
// annihilates rigid motion, and boundary conditions remove the right DOFs.
#include <gtest/gtest.h>

#include "fem/assembly.hpp"

namespace {

using namespace ffrf::fem;

const BeamMesh assembly_mesh{10.0, 7, {2.1e11, 0.01, 8.333e-6, 78.5}};

// Full-DOF nodal vectors of rigid motions: translation along u, along v, rotation about x = 0.
Eigen::VectorXd rigid_field(int kind) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(assembly_mesh.full_dof_count());
  for (int n = 0; n < assembly_mesh.node_count(); ++n) {
    if (kind == 0) q(full_dof(n, NodeDof::axial)) = 1.0;
    if (kind == 1) q(full_dof(n, NodeDof::transverse)) = 1.0;
    if (kind == 2) {
      q(full_dof(n, NodeDof::transverse)) = assembly_mesh.node_position(n);
      q(full_dof(n, NodeDof::rotation)) = 1.0;
    }
  }
  return q;
}

TEST(Assembly, ConsistentMassIntegratesMassAndMomentsExactly) {
  const SparseMatrix m = assemble_mass(assembly_mesh);
  const double rho = assembly_mesh.section.mass_per_length, length = assembly_mesh.length;
  const Eigen::VectorXd tu = rigid_field(0), tv = rigid_field(1), rot = rigid_field(2);
  EXPECT_NEAR(tu.dot(m * tu), rho * length, 1e-12 * rho * length);
  EXPECT_NEAR(tv.dot(m * tv), rho * length, 1e-12 * rho * length);
  EXPECT_NEAR(tv.dot(m * rot), rho * length * length / 2.0, 1e-12 * rho * length * length);
  EXPECT_NEAR(rot.dot(m * rot), rho * length * length * length / 3.0, 1e-12 * rho * length * length * length);
  EXPECT_NEAR(tu.dot(m * tv), 0.0, 1e-12);
}

TEST(Assembly, StiffnessAnnihilatesRigidMotion) {
  const SparseMatrix k = assemble_stiffness(assembly_mesh);
  for (int kind = 0; kind < 3; ++kind) {
    EXPECT_LT((k * rigid_field(kind)).norm(), 1e-6 * k.norm()) << "rigid field " << kind;
  }
}

TEST(Assembly, MatricesAreSymmetricAndBanded) {
  const SparseMatrix m = assemble_mass(assembly_mesh);
  const SparseMatrix k = assemble_stiffness(assembly_mesh);
  EXPECT_LT((SparseMatrix(m.transpose()) - m).norm(), 1e-12 * m.norm());
  EXPECT_LT((SparseMatrix(k.transpose()) - k).norm(), 1e-12 * k.norm());
  for (int c = 0; c < k.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(k, c); it; ++it) EXPECT_LE(std::abs(it.row() - c), 5);
}

TEST(Assembly, BoundaryConditionsFixTheRightDofs) {
  EXPECT_EQ(make_dof_map(assembly_mesh, Boundary::clamped_free).free_count(), 3 * assembly_mesh.element_count);
  EXPECT_EQ(make_dof_map(assembly_mesh, Boundary::free_free).free_count(), 3 * assembly_mesh.node_count());
  const DofMap pinned = make_dof_map(assembly_mesh, Boundary::pinned_pinned);
  EXPECT_EQ(pinned.free_count(), 3 * assembly_mesh.node_count() - 3);
  EXPECT_EQ(pinned.full_to_free[full_dof(assembly_mesh.element_count, NodeDof::transverse)], -1);
  EXPECT_GE(pinned.full_to_free[full_dof(0, NodeDof::rotation)], 0);
  const FreeMatrices free = assemble_free(assembly_mesh, Boundary::clamped_free);
  EXPECT_EQ(free.mass.rows(), 3 * assembly_mesh.element_count);
  Eigen::VectorXd full = Eigen::VectorXd::LinSpaced(assembly_mesh.full_dof_count(), 1.0, 2.0);
  const Eigen::VectorXd round_trip = extend_to_full(restrict_to_free(full, free.dofs), free.dofs);
  EXPECT_EQ(round_trip.head(3).norm(), 0.0);
  EXPECT_EQ((round_trip - full).tail(assembly_mesh.full_dof_count() - 3).norm(), 0.0);
}

TEST(Assembly, BoundaryKeywordsRoundTrip) {
  for (Boundary b : {Boundary::clamped_free, Boundary::free_free, Boundary::pinned_pinned}) {
    EXPECT_EQ(parse_boundary(to_string(b)), b);
  }
  EXPECT_FALSE(parse_boundary("clamped").has_value());
}

}  // namespace
