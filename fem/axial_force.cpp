// Axial force distributions and the geometric stiffness for a varying axial force (see header).
// Element integral ∫₀ˡ N(xₑ + ξl) s(ξ)ᵀ s(ξ) l dξ with s = row 1 of element_shape_slope (the
// rotation φ = dv/dx), evaluated at the 4 Gauss–Legendre points of [0, 1] (degree 7 exact).
#include "fem/axial_force.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/beam_element.hpp"

namespace ffrf::fem {
namespace {

// Gauss–Legendre points and weights on [−1, 1], 4 points: ±√(3/7 ∓ 2/7 √(6/5)),
// weights (18 ± √30)/36.
struct GaussPoint {
  double xi;      // on [0, 1]
  double weight;  // sums to 1 on [0, 1]
};

std::array<GaussPoint, 4> gauss_legendre_4() {
  const double inner = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double outer = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double w_inner = (18.0 + std::sqrt(30.0)) / 36.0;
  const double w_outer = (18.0 - std::sqrt(30.0)) / 36.0;
  return {{{0.5 * (1.0 - outer), 0.5 * w_outer},
           {0.5 * (1.0 - inner), 0.5 * w_inner},
           {0.5 * (1.0 + inner), 0.5 * w_inner},
           {0.5 * (1.0 + outer), 0.5 * w_outer}}};
}

void require_finite(double value, const char* name) {
  if (!std::isfinite(value)) throw std::invalid_argument(std::string(name) + " = " + std::to_string(value) + " is not finite");
}

}  // namespace

AxialForce static_axial_force(const BeamMesh& mesh, double load_per_length, double tip_force) {
  require_finite(load_per_length, "axial load per length p [N/m]");
  require_finite(tip_force, "axial tip force F [N]");
  const double length = mesh.length;
  return [=](double x) { return load_per_length * (length - x) + tip_force; };
}

AxialForce centrifugal_axial_force(const BeamMesh& mesh, double hub_radius) {
  if (!std::isfinite(hub_radius)) {
    throw std::invalid_argument("hub radius r = " + std::to_string(hub_radius) + " m must be finite");
  }
  const double length = mesh.length;
  const double rho_a = mesh.section.mass_per_length;
  return [=](double x) { return rho_a * (hub_radius * (length - x) + 0.5 * (length - x) * (length + x)); };
}

Eigen::Matrix<double, 6, 6> element_geometric_stiffness(const BeamMesh& mesh, int e, const AxialForce& axial_force) {
  const double l = mesh.element_length();
  ElementMatrix local = ElementMatrix::Zero();
  for (const GaussPoint& p : gauss_legendre_4()) {
    const Eigen::Matrix<double, 1, 6> slope = element_shape_slope(p.xi, l).row(1);
    const double force = axial_force(mesh.node_position(e) + p.xi * l);
    local.noalias() += (p.weight * l * force) * slope.transpose() * slope;
  }
  return local;
}

Eigen::SparseMatrix<double> assemble_geometric_stiffness(const BeamMesh& mesh, const DofMap& dofs,
                                                         const AxialForce& axial_force) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(16 * mesh.element_count));
  for (int e = 0; e < mesh.element_count; ++e) {
    const ElementMatrix local = element_geometric_stiffness(mesh, e, axial_force);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        if (local(i, j) != 0.0) entries.emplace_back(node_dofs * e + i, node_dofs * e + j, local(i, j));
      }
    }
  }
  Eigen::SparseMatrix<double> full(mesh.full_dof_count(), mesh.full_dof_count());
  full.setFromTriplets(entries.begin(), entries.end());
  return restrict_to_free(full, dofs);
}

}  // namespace ffrf::fem
