// Inertia shape integrals: (1) one-element cantilever against the closed forms integrated by hand
// (tip DOFs u2, v2, φ2 of paper eq. 26: ∫ρS = ρl(½, ½, −l/12) per row, ∫ρ x S_u = ρl²/3,
// ∫ρū0ᵀĨS = −∫ρ x S_v = (−7ρl²/20, ρl³/20), ∫ρ S_vᵀS_u = (7ρl/20, −ρl²/20)); (2) a 5-element mesh
// against composite Simpson quadrature of the defining integrals through point_shape().
#include <gtest/gtest.h>

#include "fem/point_shape.hpp"
#include "fem/shape_integrals.hpp"

namespace {

using namespace ffrf::fem;

TEST(ShapeIntegrals, OneElementCantileverClosedForms) {
  const double rho = 10000.0, l = 120.0;
  const BeamMesh mesh{l, 1, {2.1e11, 1.27, 11.4, rho}};
  const DofMap dofs = make_dof_map(mesh, Boundary::clamped_free);
  const NodalInvariants inv = nodal_invariants(mesh, dofs);
  const double tol = 1e-12;
  EXPECT_NEAR(inv.mass, rho * l, tol * rho * l);
  EXPECT_NEAR(inv.first_moment(0), rho * l * l / 2, tol * rho * l * l);
  EXPECT_EQ(inv.first_moment(1), 0.0);
  EXPECT_NEAR(inv.second_moment, rho * l * l * l / 3, tol * rho * l * l * l);
  Eigen::Matrix<double, 2, 3> s_bar;
  s_bar << rho * l / 2, 0, 0, 0, rho * l / 2, -rho * l * l / 12;
  EXPECT_LT((inv.shape_integral - s_bar).norm(), tol * s_bar.norm());
  Eigen::RowVector3d d(rho * l * l / 3, 0, 0), c(0, -7 * rho * l * l / 20, rho * l * l * l / 20);
  EXPECT_LT((inv.u0_dot_shape - d).norm(), tol * d.norm());
  EXPECT_LT((inv.u0_cross_shape - c).norm(), tol * c.norm());
  Eigen::Matrix3d skew;
  skew << 0, -7 * rho * l / 20, rho * l * l / 20, 7 * rho * l / 20, 0, 0, -rho * l * l / 20, 0, 0;
  EXPECT_LT((Eigen::MatrixXd(inv.skew_ff) - skew).norm(), tol * skew.norm());
  Eigen::Matrix3d mff;  // tip block of the consistent mass (paper eq. 28.d m44, m55, m56, m66)
  mff << rho * l / 3, 0, 0, 0, 13 * rho * l / 35, -11 * rho * l * l / 210, 0, -11 * rho * l * l / 210, rho * l * l * l / 105;
  EXPECT_LT((Eigen::MatrixXd(inv.mass_ff) - mff).norm(), tol * mff.norm());
}

TEST(ShapeIntegrals, MultiElementMatchesQuadratureOfDefinitions) {
  const BeamMesh mesh{7.0, 5, {2.1e11, 0.01, 8.333e-6, 31.0}};
  const DofMap dofs = make_dof_map(mesh, Boundary::clamped_free);
  const NodalInvariants inv = nodal_invariants(mesh, dofs);
  const int n = dofs.free_count();
  const Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 0.5, 3.0).array().cos();
  const double rho = mesh.section.mass_per_length;
  // Composite Simpson over [0, L] with 2000 intervals (integrands are piecewise polynomials).
  const int intervals = 2000;
  const double h = mesh.length / intervals;
  Eigen::Vector2d s_bar_a = Eigen::Vector2d::Zero();
  double mff = 0, skew = 0, dot = 0, cross = 0;
  for (int i = 0; i <= intervals; ++i) {
    const double x = i * h;
    const double w = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const PointShape s = point_shape(mesh, dofs, x);
    const Eigen::Vector2d ua = s.displacement * a, ub = s.displacement * b;
    s_bar_a += w * rho * ua;
    mff += w * rho * ua.dot(ub);
    skew += w * rho * (ua(0) * (-ub(1)) + ua(1) * ub(0));  // (Sa)ᵀ Ĩ (Sb)
    dot += w * rho * x * ua(0);                              // ū0ᵀ S a
    cross += w * rho * x * (-ua(1));                         // ū0ᵀ Ĩ S a
  }
  const double f = h / 3.0;
  const double tol = 1e-9;
  EXPECT_LT(((inv.shape_integral * a) - f * s_bar_a).norm(), tol * s_bar_a.norm() * f);
  EXPECT_NEAR(a.dot(inv.mass_ff * b), f * mff, tol * std::abs(f * mff));
  EXPECT_NEAR(a.dot(inv.skew_ff * b), f * skew, tol * std::abs(f * skew));
  EXPECT_NEAR(inv.u0_dot_shape.dot(a), f * dot, tol * std::abs(f * dot));
  EXPECT_NEAR(inv.u0_cross_shape.dot(a), f * cross, tol * std::abs(f * cross));
  EXPECT_LT((Eigen::MatrixXd(inv.skew_ff) + Eigen::MatrixXd(inv.skew_ff).transpose()).norm(), 1e-12 * inv.skew_ff.norm());
}

}  // namespace
