// Geometric stiffness for a varying axial force (fem/axial_force.hpp) against independent
// results: the closed-form constant-force element matrix of fem/beam_element.cpp; the differential
// equilibrium of the centrifugal force dN/dx = −ρAΩ²(r + x) with N(L) = 0; and, for a linearly
// varying N, element integrals computed here exactly from the monomial coefficients of the
// Hermite slopes (∫₀¹ ξⁿ dξ = 1/(n + 1)), written out by hand and not taken from the element code.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>

#include "fem/assembly.hpp"
#include "fem/axial_force.hpp"

namespace {

using namespace ffrf::fem;

const BeamMesh prestressed_mesh{10.0, 8, {2.1e11, 0.01, 8.333e-6, 78.5}};

double max_abs_difference(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  return Eigen::MatrixXd(a - b).cwiseAbs().maxCoeff();
}

TEST(AxialForce, ConstantForceEqualsTheClosedFormElementMatrix) {
  for (Boundary boundary : {Boundary::clamped_free, Boundary::pinned_pinned, Boundary::free_free}) {
    const DofMap dofs = make_dof_map(prestressed_mesh, boundary);
    const double force = -3.7e5;
    const auto quadrature = assemble_geometric_stiffness(prestressed_mesh, dofs, [&](double) { return force; });
    const auto closed_form = restrict_to_free(assemble_geometric_stiffness(prestressed_mesh, force), dofs);
    const double scale = Eigen::MatrixXd(closed_form).cwiseAbs().maxCoeff();
    EXPECT_LT(max_abs_difference(quadrature, closed_form), 1e-14 * scale) << to_string(boundary);
  }
}

TEST(AxialForce, StaticDistributionIsLoadTimesRemainingLengthPlusTipForce) {
  const AxialForce n = static_axial_force(prestressed_mesh, 250.0, -4.0e3);
  EXPECT_DOUBLE_EQ(n(prestressed_mesh.length), -4.0e3);                 // the tip carries the tip force only
  EXPECT_DOUBLE_EQ(n(0.0), 250.0 * prestressed_mesh.length - 4.0e3);    // the root carries everything
  EXPECT_NEAR(n(2.0) - n(3.0), 250.0, 1e-9);                // dN/dx = −p
  EXPECT_THROW(static_axial_force(prestressed_mesh, std::nan(""), 0.0), std::invalid_argument);
}

TEST(AxialForce, CentrifugalDistributionSatisfiesEquilibriumAndFreeTip) {
  const double hub_radius = 2.5, spin = 3.0;
  const AxialForce per_spin2 = centrifugal_axial_force(prestressed_mesh, hub_radius);
  const double rho_a = prestressed_mesh.section.mass_per_length;
  EXPECT_NEAR(per_spin2(prestressed_mesh.length), 0.0, 1e-12);
  // N is quadratic in x: the central difference is its exact derivative up to round-off.
  for (double x : {0.0, 1.3, 5.0, 9.9}) {
    const double h = 1e-3;
    const double slope = spin * spin * (per_spin2(x + h) - per_spin2(x - h)) / (2 * h);
    EXPECT_NEAR(slope, -rho_a * spin * spin * (hub_radius + x), 1e-7 * rho_a * spin * spin * prestressed_mesh.length) << "x = " << x;
  }
  // The root carries the whole centrifugal force ∫₀ᴸ ρAΩ²(r + s) ds.
  EXPECT_NEAR(per_spin2(0.0), rho_a * (hub_radius * prestressed_mesh.length + 0.5 * prestressed_mesh.length * prestressed_mesh.length), 1e-9);
  EXPECT_THROW(centrifugal_axial_force(prestressed_mesh, std::nan("")), std::invalid_argument);
  // An axis ahead of the root (r < 0, on the beam's line): the same integral ∫ₓᴸ ρA (r + s) ds.
  const AxialForce ahead = centrifugal_axial_force(prestressed_mesh, -1.0);
  EXPECT_NEAR(ahead(0.0), rho_a * (-1.0 * prestressed_mesh.length + 0.5 * prestressed_mesh.length * prestressed_mesh.length), 1e-9 * rho_a * prestressed_mesh.length * prestressed_mesh.length);
  EXPECT_NEAR(ahead(prestressed_mesh.length), 0.0, 1e-12);
}

// Transverse slope dv/dx of the element's Hermite functions as polynomials in ξ (coefficients of
// ξ⁰, ξ¹, ξ²) for the DOFs (v1, φ1, v2, φ2): d/dx = (1/l) d/dξ of
// 1 − 3ξ² + 2ξ³,  l(ξ − 2ξ² + ξ³),  3ξ² − 2ξ³,  l(−ξ² + ξ³).
std::array<std::array<double, 3>, 4> hermite_slope_coefficients(double l) {
  return {{{0.0, -6.0 / l, 6.0 / l}, {1.0, -4.0, 3.0}, {0.0, 6.0 / l, -6.0 / l}, {0.0, -2.0, 3.0}}};
}

// ∫₀ˡ (N₀(1 − ξ) + N₁ξ) s_i s_j dx exactly, from the monomial coefficients.
Eigen::Matrix4d linear_force_element(double n0, double n1, double l) {
  const auto c = hermite_slope_coefficients(l);
  Eigen::Matrix4d k = Eigen::Matrix4d::Zero();
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      double sum = 0.0;
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
          const int power = a + b;
          // N = N₀ + (N₁ − N₀)ξ
          sum += c[i][a] * c[j][b] * (n0 / (power + 1) + (n1 - n0) / (power + 2));
        }
      }
      k(i, j) = sum * l;
    }
  }
  return k;
}

TEST(AxialForce, LinearForceMatchesExactElementIntegrals) {
  const double p = 1.7e3, tip = -2.0e4;  // N(x) = p(L − x) + F: linear
  const AxialForce n = static_axial_force(prestressed_mesh, p, tip);
  const DofMap dofs = make_dof_map(prestressed_mesh, Boundary::free_free);  // all DOFs: compare the full matrix
  const Eigen::MatrixXd kg(assemble_geometric_stiffness(prestressed_mesh, dofs, n));
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(prestressed_mesh.full_dof_count(), prestressed_mesh.full_dof_count());
  const double l = prestressed_mesh.element_length();
  const int v[4] = {1, 2, 4, 5};
  for (int e = 0; e < prestressed_mesh.element_count; ++e) {
    const Eigen::Matrix4d local = linear_force_element(n(prestressed_mesh.node_position(e)), n(prestressed_mesh.node_position(e + 1)), l);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) expected(3 * e + v[i], 3 * e + v[j]) += local(i, j);
    }
  }
  const double scale = expected.cwiseAbs().maxCoeff();
  EXPECT_LT((kg - expected).cwiseAbs().maxCoeff(), 1e-13 * scale);
  // Axial DOFs carry no geometric stiffness.
  for (int node = 0; node < prestressed_mesh.node_count(); ++node) EXPECT_EQ(kg.row(3 * node).cwiseAbs().sum(), 0.0);
}

TEST(AxialForce, CubicForceIsIntegratedExactly) {
  // N(x) = x³ on one element of length 2: compare with a fine composite Simpson rule, which is
  // exact for the degree-7 integrand only in the limit; 1e-9 relative at 2000 panels.
  const BeamMesh one{2.0, 1, prestressed_mesh.section};
  const DofMap dofs = make_dof_map(one, Boundary::free_free);
  const Eigen::MatrixXd kg(assemble_geometric_stiffness(one, dofs, [](double x) { return x * x * x; }));
  const auto c = hermite_slope_coefficients(2.0);
  const auto slope = [&](int i, double xi) { return c[i][0] + c[i][1] * xi + c[i][2] * xi * xi; };
  const int v[4] = {1, 2, 4, 5};
  const int panels = 2000;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      double sum = 0.0;
      for (int k = 0; k <= panels; ++k) {
        const double xi = static_cast<double>(k) / panels;
        const double weight = (k == 0 || k == panels) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
        const double x = 2.0 * xi;
        sum += weight * x * x * x * slope(i, xi) * slope(j, xi);
      }
      const double exact = sum * 2.0 / (3.0 * panels);
      EXPECT_NEAR(kg(v[i], v[j]), exact, 1e-9 * (1.0 + std::abs(exact))) << i << "," << j;
    }
  }
}

}  // namespace
