// Inertia shape integrals of the floating-frame beam (see the header for the definitions),
// accumulated element by element with 4-point Gauss–Legendre quadrature, which is exact for the
// polynomial integrands (degree ≤ 6 in ξ).
#include "fem/shape_integrals.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "fem/beam_element.hpp"

namespace ffrf::fem {
namespace {

struct GaussPoint {
  double xi;
  double weight;
};

// 4-point Gauss–Legendre on [0, 1].
std::array<GaussPoint, 4> gauss4() {
  const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double wa = (18.0 + std::sqrt(30.0)) / 36.0;
  const double wb = (18.0 - std::sqrt(30.0)) / 36.0;
  return {{{0.5 * (1.0 - b), 0.5 * wb}, {0.5 * (1.0 - a), 0.5 * wa}, {0.5 * (1.0 + a), 0.5 * wa}, {0.5 * (1.0 + b), 0.5 * wb}}};
}

}  // namespace

ElementInvariants element_invariants(const BeamMesh& mesh, int element) {
  const double l = mesh.element_length();
  const double rho = mesh.section.mass_per_length;
  const double x0 = element * l;
  ElementInvariants inv;
  inv.shape_integral.setZero();
  inv.u0_dot_shape.setZero();
  inv.u0_cross_shape.setZero();
  inv.mass.setZero();
  inv.skew.setZero();
  for (const GaussPoint& gp : gauss4()) {
    const ElementShape s = element_shape(gp.xi, l);
    const double w = rho * l * gp.weight;
    const double x = x0 + gp.xi * l;
    inv.shape_integral += w * s;
    inv.u0_dot_shape += (w * x) * s.row(0);
    inv.u0_cross_shape -= (w * x) * s.row(1);  // ĨS = [−S_v; S_u], so ū0ᵀĨS = −x S_v
    inv.mass += w * s.transpose() * s;
    inv.skew += w * (s.row(1).transpose() * s.row(0) - s.row(0).transpose() * s.row(1));
  }
  return inv;
}

NodalInvariants nodal_invariants(const BeamMesh& mesh, const DofMap& dofs) {
  const int n = dofs.free_count();
  const double l = mesh.element_length();
  const double rho = mesh.section.mass_per_length;
  NodalInvariants inv;
  inv.shape_integral = Eigen::Matrix<double, 2, Eigen::Dynamic>::Zero(2, n);
  inv.u0_dot_shape = Eigen::RowVectorXd::Zero(n);
  inv.u0_cross_shape = Eigen::RowVectorXd::Zero(n);
  std::vector<Eigen::Triplet<double>> mass_entries;
  std::vector<Eigen::Triplet<double>> skew_entries;

  for (int e = 0; e < mesh.element_count; ++e) {
    const double x0 = e * l;
    const ElementInvariants element = element_invariants(mesh, e);
    inv.mass += rho * l;
    inv.first_moment(0) += rho * (x0 * l + 0.5 * l * l);
    inv.second_moment += rho * ((x0 + l) * (x0 + l) * (x0 + l) - x0 * x0 * x0) / 3.0;
    for (int i = 0; i < 6; ++i) {
      const int fi = dofs.full_to_free[static_cast<std::size_t>(node_dofs * e + i)];
      if (fi < 0) continue;
      inv.shape_integral.col(fi) += element.shape_integral.col(i);
      inv.u0_dot_shape(fi) += element.u0_dot_shape(i);
      inv.u0_cross_shape(fi) += element.u0_cross_shape(i);
      for (int j = 0; j < 6; ++j) {
        const int fj = dofs.full_to_free[static_cast<std::size_t>(node_dofs * e + j)];
        if (fj < 0) continue;
        if (element.mass(i, j) != 0.0) mass_entries.emplace_back(fi, fj, element.mass(i, j));
        if (element.skew(i, j) != 0.0) skew_entries.emplace_back(fi, fj, element.skew(i, j));
      }
    }
  }
  inv.mass_ff.resize(n, n);
  inv.mass_ff.setFromTriplets(mass_entries.begin(), mass_entries.end());
  inv.skew_ff.resize(n, n);
  inv.skew_ff.setFromTriplets(skew_entries.begin(), skew_entries.end());
  return inv;
}

}  // namespace ffrf::fem
