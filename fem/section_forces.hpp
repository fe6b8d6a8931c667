// Section forces and fibre stresses of the beam from its element deformations (Euler–Bernoulli;
// docs/theory.md §13). On element e of length l with local DOFs (u1, v1, φ1, u2, v2, φ2) and
// ξ = (x − x_e)/l, the axial strain is constant and the curvature linear (paper eq. 4's shapes):
//   ε = (u2 − u1)/l,   κ(ξ) = [(12ξ − 6) v1 + l(6ξ − 4) φ1 + (6 − 12ξ) v2 + l(6ξ − 2) φ2] / l²,
// so the axial force is N = EA ε (tension > 0) and the bending moment M = EI κ (positive when the
// boom bends concave towards +y of its frame). A fibre at distance y from the axis has the strain
// ε − yκ, so the fibres at y = ±c carry
//   σ_top = N/A − M c/I,  σ_bottom = N/A + M c/I,  and the extreme fibre |N|/A + |M| c/I.
// The sections are the nodes; an interior node takes the mean of its two elements' end values, and
// the axial force at the two ends is extrapolated from the two nearest elements' (each element's is
// its mean, exact at its middle for a linearly varying N).
// For a uniform transverse load q the cubic element's moment is the exact one shifted by q l²/12
// at every node (the fixed-end moment), so the recovered moment converges as O(l²).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::fem {

struct SectionForces {
  Eigen::VectorXd position;        // x of each section (the nodes) [m]
  Eigen::VectorXd axial_force;     // N, tension > 0 [N]
  Eigen::VectorXd bending_moment;  // M [N m]
};

// The section forces of the free nodal displacements q (size dofs.free_count(); fixed DOFs are zero).
SectionForces section_forces(const BeamMesh& mesh, const DofMap& dofs, const Eigen::VectorXd& free_displacements);
// The same into preallocated vectors (node_count() each) from the full nodal displacements.
void section_forces_full(const BeamMesh& mesh, const Eigen::VectorXd& full_displacements, SectionForces& out);

// The section forces from each element's end forces r_e: the forces the rest of the beam (and its
// supports) apply to element e at its ends, over (u1, v1, φ1, u2, v2, φ2). By the element's own
// balance, r_e = K_e q_e − f_e with f_e the consistent nodal loads of everything distributed along it
// (its weight, its inertia, a point load inside it): N(start) = −r[0], M(start) = −r[2], N(end) = r[3],
// M(end) = r[5] (K_e q_e alone gives the curvature values above). Exact at the nodes whenever the
// nodal displacements are (a uniform load: no l²/12 shift). An interior node takes the mean of its two
// elements' values (they differ by a point load applied at the node).
using ElementForces = Eigen::Matrix<double, 6, 1>;
void section_forces_from_end_forces(const BeamMesh& mesh, const std::vector<ElementForces>& end_forces, SectionForces& out);

// The stresses of the two extreme fibres at distance c from the axis [Pa].
struct FibreStress {
  double top = 0.0;     // σ at y = +c
  double bottom = 0.0;  // σ at y = −c
  double extreme() const { return std::max(std::abs(top), std::abs(bottom)); }
};
FibreStress fibre_stress(const BeamSection& section, double fibre_distance, double axial_force, double bending_moment);

// The extreme-fibre distance of a section whose area sits in two flanges at ±c (a lattice boom's
// chords): I = A c², so c = sqrt(I/A). The default when a scene gives none.
double two_flange_fibre_distance(const BeamSection& section);

}  // namespace ffrf::fem
