// Section forces recovered from element deformations against Euler–Bernoulli statics:
//  * a cantilever under a tip force P: M(x) = P(L − x) and N = const, exact at every node (the
//    cubic element holds the linear moment exactly);
//  * a cantilever under a uniform load q: the nodal moments are the exact q(L − x)²/2 shifted by the
//    fixed-end moment q l²/12 (so the recovery converges as O(l²));
//  * a simply supported (pinned–pinned) span under a uniform load q (towards +y, so that it bows
//    concave towards −y): the mid-span moment −qL²/8 and zero at the pins, both shifted by the same
//    −q l²/12;
//  * the fibre stresses of a section: N/A ∓ M c/I, the extreme fibre |N|/A + |M|c/I.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>

#include "fem/assembly.hpp"
#include "fem/beam_element.hpp"
#include "fem/point_shape.hpp"
#include "fem/section_forces.hpp"

namespace {

using namespace ffrf::fem;

const BeamSection boom_section{2.1e11, 1.27, 11.4, 1.0e4};

Eigen::VectorXd static_displacements(const BeamMesh& mesh, Boundary boundary, const Eigen::VectorXd& load) {
  const FreeMatrices m = assemble_free(mesh, boundary);
  Eigen::SimplicialLDLT<SparseMatrix> solver(m.stiffness);
  return solver.solve(load);
}

TEST(SectionForces, CantileverTipForceGivesLinearMomentExactly) {
  const BeamMesh mesh{120.0, 7, boom_section};
  const DofMap dofs = make_dof_map(mesh, Boundary::clamped_free);
  const double transverse = 3.0e6, axial = -5.0e6;
  const Eigen::VectorXd q =
      static_displacements(mesh, Boundary::clamped_free, point_load(mesh, dofs, mesh.length, {axial, transverse}, 0.0));
  const SectionForces forces = section_forces(mesh, dofs, q);
  ASSERT_EQ(forces.position.size(), mesh.node_count());
  for (int node = 0; node < mesh.node_count(); ++node) {
    const double x = mesh.node_position(node);
    EXPECT_NEAR(forces.bending_moment(node), transverse * (mesh.length - x), 1e-8 * transverse * mesh.length) << "node " << node;
    EXPECT_NEAR(forces.axial_force(node), axial, 1e-8 * std::abs(axial)) << "node " << node;
  }
}

TEST(SectionForces, UniformLoadMomentIsExactLessTheFixedEndMoment) {
  const double q = 4.9e4, length = 120.0;
  for (int elements : {4, 8, 16, 32}) {
    const BeamMesh mesh{length, elements, boom_section};
    const DofMap dofs = make_dof_map(mesh, Boundary::clamped_free);
    const SectionForces forces =
        section_forces(mesh, dofs, static_displacements(mesh, Boundary::clamped_free, distributed_load(mesh, dofs, {0.0, q})));
    const double l = mesh.element_length(), fixed_end = q * l * l / 12.0;
    for (int node = 0; node < mesh.node_count(); ++node) {
      const double x = mesh.node_position(node);
      const double exact = 0.5 * q * (length - x) * (length - x);
      EXPECT_NEAR(forces.bending_moment(node), exact - fixed_end, 1e-7 * q * length * length) << elements << " elements, node " << node;
    }
  }
}

TEST(SectionForces, SimplySupportedSpanConvergesToQLSquaredOverEight) {
  const double q = 4.9e4, length = 120.0;
  double previous_error = 0.0;
  for (int elements : {8, 16, 32, 64}) {
    const BeamMesh mesh{length, elements, boom_section};
    const DofMap dofs = make_dof_map(mesh, Boundary::pinned_pinned);
    const SectionForces forces =
        section_forces(mesh, dofs, static_displacements(mesh, Boundary::pinned_pinned, distributed_load(mesh, dofs, {0.0, q})));
    const double mid = forces.bending_moment(elements / 2);
    const double exact = -q * length * length / 8.0;
    const double error = std::abs((mid - exact) / exact);
    const double h = mesh.element_length();
    // The same shift at mid-span as at the pins: −q l²/12 (O(l²) relative to qL²/8).
    EXPECT_NEAR(mid, exact - q * h * h / 12.0, 1e-7 * std::abs(exact)) << elements;
    EXPECT_NEAR(forces.bending_moment(0), -q * h * h / 12.0, 1e-7 * std::abs(exact)) << elements;
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 4.0, 1e-4) << elements;  // O(l²)
    }
    previous_error = error;
  }
}

TEST(SectionForces, UniformAxialLoadGivesTheLinearAxialForceAtEveryNode) {
  const double p = -4.2e4, length = 120.0;  // along −x (a boom's weight component): compression grows to the root
  const BeamMesh mesh{length, 6, boom_section};
  const DofMap dofs = make_dof_map(mesh, Boundary::clamped_free);
  const SectionForces forces =
      section_forces(mesh, dofs, static_displacements(mesh, Boundary::clamped_free, distributed_load(mesh, dofs, {p, 0.0})));
  for (int node = 0; node < mesh.node_count(); ++node) {
    const double x = mesh.node_position(node);
    EXPECT_NEAR(forces.axial_force(node), p * (length - x), 1e-8 * std::abs(p) * length) << "node " << node;
    EXPECT_NEAR(forces.bending_moment(node), 0.0, 1e-6) << "node " << node;
  }
}

// The element end forces r_e = K_e q_e − f_e with the consistent load of a uniform transverse load:
// the moments are exact at every node, the fixed-end shift gone.
TEST(SectionForces, EndForcesWithTheElementLoadsAreExactUnderAUniformLoad) {
  const double q = 4.9e4, length = 120.0;
  for (const Boundary boundary : {Boundary::clamped_free, Boundary::pinned_pinned}) {
    const BeamMesh mesh{length, 8, boom_section};
    const DofMap dofs = make_dof_map(mesh, boundary);
    const Eigen::VectorXd full = extend_to_full(
        static_displacements(mesh, boundary, distributed_load(mesh, dofs, {0.0, q})), dofs);
    const double l = mesh.element_length();
    const ElementMatrix stiffness = element_stiffness(mesh.section, l);
    ElementForces consistent;  // ∫ S_eᵀ (0, q) dx
    consistent << 0.0, q * l / 2.0, q * l * l / 12.0, 0.0, q * l / 2.0, -q * l * l / 12.0;
    std::vector<ElementForces> end_forces;
    for (int e = 0; e < mesh.element_count; ++e) end_forces.push_back(stiffness * full.segment<6>(3 * e) - consistent);
    SectionForces forces;
    section_forces_from_end_forces(mesh, end_forces, forces);
    for (int node = 0; node < mesh.node_count(); ++node) {
      const double x = mesh.node_position(node);
      const double exact = boundary == Boundary::clamped_free ? 0.5 * q * (length - x) * (length - x) : -0.5 * q * x * (length - x);
      EXPECT_NEAR(forces.bending_moment(node), exact, 1e-8 * q * length * length) << to_string(boundary) << ", node " << node;
    }
  }
}

TEST(SectionForces, FibreStressesOfTheTwoFlangeSection) {
  const double c = two_flange_fibre_distance(boom_section);
  EXPECT_NEAR(c * c * boom_section.area, boom_section.second_moment, 1e-12 * boom_section.second_moment);
  const double axial = -2.0e7, moment = 8.0e7;
  const FibreStress s = fibre_stress(boom_section, c, axial, moment);
  EXPECT_DOUBLE_EQ(s.top, axial / boom_section.area - moment * c / boom_section.second_moment);
  EXPECT_DOUBLE_EQ(s.bottom, axial / boom_section.area + moment * c / boom_section.second_moment);
  EXPECT_NEAR(s.extreme(), std::abs(axial) / boom_section.area + std::abs(moment) * c / boom_section.second_moment, 1e-6);
}

}  // namespace
