// Element matrices against energies of exactly representable displacement fields: for a cubic
// transverse field v(x) and linear axial field u(x), ½qᵀKq = ½∫(EA u'² + EI v''²) dx,
// ½qᵀK_g q = ½P∫v'² dx and ½qᵀMq = ½∫ρ(u² + v²) dx, all integrated analytically here.
#include <gtest/gtest.h>

#include <cmath>

#include "fem/beam_element.hpp"

namespace {

using ffrf::fem::BeamSection;

// Cubic v(x) = a0 + a1 x + a2 x² + a3 x³, linear u(x) = b0 + b1 x on [0, l].
struct Field {
  double a0, a1, a2, a3, b0, b1;
  double v(double x) const { return a0 + a1 * x + a2 * x * x + a3 * x * x * x; }
  double dv(double x) const { return a1 + 2 * a2 * x + 3 * a3 * x * x; }
  double u(double x) const { return b0 + b1 * x; }
  Eigen::Matrix<double, 6, 1> nodal(double l) const {
    Eigen::Matrix<double, 6, 1> q;
    q << u(0), v(0), dv(0), u(l), v(l), dv(l);
    return q;
  }
};

// ∫0^l p(x) dx for a polynomial given by coefficients c[k] x^k.
double integrate_poly(const std::vector<double>& c, double l) {
  double sum = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) sum += c[k] * std::pow(l, static_cast<double>(k + 1)) / static_cast<double>(k + 1);
  return sum;
}

std::vector<double> multiply(const std::vector<double>& p, const std::vector<double>& q) {
  std::vector<double> r(p.size() + q.size() - 1, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j) r[i + j] += p[i] * q[j];
  return r;
}

const BeamSection section{2.1e11, 0.01, 8.333e-6, 78.5};
const Field field{0.3, -0.2, 0.7, -1.1, 0.4, 0.9};
const double l = 1.7;

TEST(BeamElement, StiffnessEnergyEqualsStrainEnergyOfCubicField) {
  const auto q = field.nodal(l);
  const double energy = 0.5 * q.dot(ffrf::fem::element_stiffness(section, l) * q);
  const std::vector<double> v2{2 * field.a2, 6 * field.a3};  // v''
  const double bending = section.bending_rigidity() * integrate_poly(multiply(v2, v2), l);
  const double axial = section.axial_rigidity() * field.b1 * field.b1 * l;
  EXPECT_NEAR(energy, 0.5 * (bending + axial), 1e-12 * energy);
}

TEST(BeamElement, GeometricStiffnessEnergyEqualsAxialForceWork) {
  const double force = -3.2e5;
  const auto q = field.nodal(l);
  const double energy = 0.5 * q.dot(ffrf::fem::element_geometric_stiffness(force, l) * q);
  const std::vector<double> dv{field.a1, 2 * field.a2, 3 * field.a3};
  EXPECT_NEAR(energy, 0.5 * force * integrate_poly(multiply(dv, dv), l), 1e-12 * std::abs(energy));
}

TEST(BeamElement, ConsistentMassEqualsKineticEnergyOfField) {
  const auto q = field.nodal(l);
  const double energy = 0.5 * q.dot(ffrf::fem::element_mass(section, l) * q);
  const std::vector<double> v{field.a0, field.a1, field.a2, field.a3};
  const std::vector<double> u{field.b0, field.b1};
  const double exact = 0.5 * section.mass_per_length * (integrate_poly(multiply(v, v), l) + integrate_poly(multiply(u, u), l));
  EXPECT_NEAR(energy, exact, 1e-12 * exact);
}

TEST(BeamElement, ShapeFunctionsInterpolateNodalValuesAndSlopes) {
  const auto q = field.nodal(l);
  for (double xi : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const Eigen::Vector2d disp = ffrf::fem::element_shape(xi, l) * q;
    const Eigen::Vector2d slope = ffrf::fem::element_shape_slope(xi, l) * q;
    EXPECT_NEAR(disp(0), field.u(xi * l), 1e-14);
    EXPECT_NEAR(disp(1), field.v(xi * l), 1e-13);
    EXPECT_NEAR(slope(0), field.b1, 1e-13);
    EXPECT_NEAR(slope(1), field.dv(xi * l), 1e-13);
  }
}

TEST(BeamElement, MatricesAreSymmetric) {
  const auto m = ffrf::fem::element_mass(section, l);
  const auto k = ffrf::fem::element_stiffness(section, l);
  const auto g = ffrf::fem::element_geometric_stiffness(1.0, l);
  EXPECT_LT((m - m.transpose()).norm(), 1e-14 * m.norm());
  EXPECT_LT((k - k.transpose()).norm(), 1e-14 * k.norm());
  EXPECT_LT((g - g.transpose()).norm(), 1e-14 * g.norm());
}

}  // namespace
