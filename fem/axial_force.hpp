// Geometric (stress) stiffness of the beam for an axial force that varies along the axis:
// K_g = Σ_e ∫ N(x) (∂S_v/∂x)ᵀ(∂S_v/∂x) dx (the second-order work of the axial force N on the
// transverse slope v' = φ, tension > 0 stiffens). Two distributions of N(x) of a clamped-free beam:
//   static load:   N(x) = p (L − x) + F           (axial load p [N/m] along +x, tip force F [N]),
//   centrifugal:   N(x) / Ω² = ρA [r (L − x) + (L² − x²)/2]
// for a beam spinning at Ω about an axis normal to the plane a distance r (hub radius) behind the
// root: N(x) = ∫ₓᴸ ρA Ω² (r + s) ds, so dN/dx = −ρAΩ²(r + x) and N(L) = 0 (free tip).
// Derivation and use: docs/theory.md, "Rotating and prestressed beam frequencies".
#pragma once

#include <Eigen/SparseCore>
#include <functional>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::fem {

// Axial force distribution N(x) [N] along the beam axis x ∈ [0, L] (tension > 0).
using AxialForce = std::function<double(double x)>;

// Clamped-free beam, uniform axial load p [N/m] along +x (toward the tip) and axial tip force F [N] (+x):
// N(x) = p (L − x) + F. Throws std::invalid_argument for a non-finite p or F.
AxialForce static_axial_force(const BeamMesh& mesh, double load_per_length, double tip_force);

// Centrifugal axial force per unit Ω² [N s²] of a beam spinning about an axis normal to the plane that lies a
// distance hub_radius behind the root on the beam axis (r < 0: the axis lies ahead of the root, on
// the beam's line): N(x)/Ω² = ρA [r (L − x) + (L² − x²)/2]. Throws std::invalid_argument for a
// non-finite hub radius.
AxialForce centrifugal_axial_force(const BeamMesh& mesh, double hub_radius);

// Geometric stiffness on the free DOFs, K_g = Σ_e ∫ N(x) (∂S_v/∂x)ᵀ(∂S_v/∂x) dx, by 4-point Gauss–Legendre
// quadrature per element (exact for N(x) up to degree 3: the slope product is of degree 4), assembled like
// fem/assembly.cpp and restricted to `dofs`.
Eigen::SparseMatrix<double> assemble_geometric_stiffness(const BeamMesh& mesh, const DofMap& dofs,
                                                         const AxialForce& axial_force);
// One element's share of it, over its six DOFs.
Eigen::Matrix<double, 6, 6> element_geometric_stiffness(const BeamMesh& mesh, int element, const AxialForce& axial_force);

}  // namespace ffrf::fem
