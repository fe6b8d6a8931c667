// The planar Euler–Bernoulli frame element: linear axial and cubic Hermite bending shape
// functions (paper eq. 4) and the element matrices that follow from them by exact integration:
// consistent mass  M_e = ∫ ρA SᵀS dx            (paper eq. 19.d, M_ff),
// stiffness        K_e = ∫ (DS)ᵀ E (DS) dx      (paper eq. 15.b),
// geometric        K_g = P ∫ (∂S_v/∂x)ᵀ(∂S_v/∂x) dx for a constant axial force P (tension > 0).
// Element DOF order: (u1, v1, phi1, u2, v2, phi2). Derivations: docs/theory.md §1.
#pragma once

#include <Eigen/Dense>

#include "fem/element_space.hpp"
#include "fem/section.hpp"

namespace ffrf::fem {

using ElementMatrix = Eigen::Matrix<double, element_dofs, element_dofs>;
using ElementShape = Eigen::Matrix<double, Space::dimension, element_dofs>;  // rows: axial u, transverse v

// Shape matrix S(ξ) of paper eq. 4 (transposed to 2×6), ξ = x/l in [0, 1].
ElementShape element_shape(double xi, double element_length);
// dS/dx: row 0 axial strain shape, row 1 the small rotation phi = dv/dx.
ElementShape element_shape_slope(double xi, double element_length);

ElementMatrix element_mass(const BeamSection& section, double element_length);
ElementMatrix element_stiffness(const BeamSection& section, double element_length);
ElementMatrix element_geometric_stiffness(double axial_force, double element_length);

}  // namespace ffrf::fem
