// Independent reference for the rotating (and axially prestressed) clamped-free Euler–Bernoulli
// beam: a Frobenius power series about the root, not finite elements. Dimensionless ξ = x/L,
// λ = Ω²ρAL⁴/EI, μ = ω²ρAL⁴/EI, hub radius ratio ρ_h = r/L, uniform extra force p̄ = PL²/EI:
//   V'''' − [n(ξ) V']' − κλ V = μ V,   n(ξ) = sλ [ρ_h(1 − ξ) + (1 − ξ²)/2] + p̄,
//   V(0) = V'(0) = 0,  V''(1) = 0,  V'''(1) − n(1) V'(1) = 0,
// with s = 1 (centrifugal stiffening) or 0, κ = 1 in the plane of rotation (the centrifugal
// softening −Ω²ρA v of the floating frame) or 0 out of plane (flapwise). n(ξ) = N(x) L²/EI is the
// dimensionless axial force of fem/axial_force.hpp. The coefficients are polynomials, so the
// solution is entire: V = Σ cₙ ξⁿ with c₀ = c₁ = 0, (c₂, c₃) = (1, 0) or (0, 1) and, writing
// n(ξ) = n₀ + n₁ξ + n₂ξ², the recurrence (coefficient of ξᵏ)
//   (k+1)(k+2)(k+3)(k+4) c_{k+4} = (k+1)[n₀(k+2)c_{k+2} + n₁(k+1)c_{k+1} + n₂ k c_k] + (μ + κλ) c_k.
// The eigenvalues μ are the roots of the 2×2 tip determinant of the two solutions, bracketed by a
// scan in √(μ + κλ) and refined by bisection in long double. Without stiffening (s = 0, p̄ = 0) the
// equation is V'''' = (μ + κλ)V, so μ = μ₀ − κλ exactly. docs/theory.md, "Rotating and prestressed
// beam frequencies".
#pragma once

#include <vector>

#include "fem/mesh.hpp"

namespace ffrf::fem {

struct RotatingBeamProblem {
  double spin_parameter = 0.0;         // λ = Ω²ρAL⁴/EI ≥ 0
  double hub_radius_ratio = 0.0;       // ρ_h = r/L ≥ 0
  double axial_force_parameter = 0.0;  // p̄ = PL²/EI, uniform, tension > 0; must exceed −π²/4 (buckling)
  bool centrifugal_stiffening = true;  // s
  bool in_plane = true;                // κ: the −λV centrifugal softening of the plane of rotation
};

// √(EI/(ρA L⁴)) [rad/s]: ω = √μ · scale.
double rotating_beam_frequency_scale(const BeamMesh& mesh);
// The dimensionless problem of a clamped-free beam spinning at Ω [rad/s] about an axis a distance
// hub_radius [m] behind the root, with a uniform extra axial force P [N].
RotatingBeamProblem rotating_beam_problem(const BeamMesh& mesh, double spin_rate, double hub_radius, double axial_force,
                                          bool centrifugal_stiffening);

// The 2×2 tip determinant D(μ) of the two series solutions (zero at an eigenvalue).
// Throws std::runtime_error when the series does not converge in 6000 terms.
long double rotating_beam_tip_determinant(const RotatingBeamProblem& problem, long double mu);

// The lowest `count` dimensionless eigenvalues μ, ascending (μ < 0: divergence, growth rate √(−μ)·scale).
// Throws std::invalid_argument for invalid parameters or count < 1, std::domain_error when
// p̄ ≤ −π²/4 (buckled: no reference).
std::vector<double> rotating_beam_eigenvalues(const RotatingBeamProblem& problem, int count);

}  // namespace ffrf::fem
