// First-order wave excitation of the hull from BEM coefficients (Froude–Krylov + diffraction), for
// the same components as the wave field (sea/wave_field.hpp). Component i with amplitude a_i,
// frequency ω_i, wave number k_i and phase φ_i has the incident elevation at the BEM body origin's
// mean position x_O, ζ(x_O, t) = a_i cos(k_i x_O − δω_i t + φ_i) = a_i cos(ω_i t + ψ_i),
// ψ_i = −δ(k_i x_O + φ_i) (δ = +1 following, −1 head sea), so the force on the origin is
// Re{a_i X(ω_i, β) e^{i(ω_i t + ψ_i)}} (docs/hydrodynamics.md §4.3: e^{iωt}, β = 0° for δ = +1,
// 180° for δ = −1), X linear in Re/Im between the BEM frequencies, and the generalized force at G1 is
// Tᵀ times it (rigid_transfer). The total is multiplied by the wave field's ramp r(t).
// With this excitation, the hull pressure is integrated in calm water (hydrostatics only): the
// Froude–Krylov force is the BEM file's, never counted twice (docs/hydrodynamics.md §6).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "sea/wave_field.hpp"
#include "hydro/planar_coefficients.hpp"

namespace ffrf::sea {

struct BemExcitation {
  std::vector<Eigen::Vector3cd> force;  // a_i Tᵀ X(ω_i) [N, N, N m] per component
  std::vector<double> frequency;        // ω_i [rad/s]
  std::vector<double> phase;            // ψ_i [rad]
  // Generalized excitation at G1 (surge, heave, pitch) at t, without the ramp.
  Eigen::Vector3d at(double t) const;
};

// T of ẋ_O = T ẋ_G1 for a point O at `offset` from G1 in the hull frame (at zero pitch):
// T = [[1, 0, −o_y], [0, 1, o_x], [0, 0, 1]]; forces transfer as F_G1 = Tᵀ F_O.
Eigen::Matrix3d rigid_transfer(const Eigen::Vector2d& offset);

// X at ω for the heading the wave travels along (δ = +1: β = 0°, −1: β = 180°). Throws
// std::invalid_argument naming the file when the heading is not in the table or ω lies outside the
// table's frequencies.
hydro::PlanarComplexVector excitation_at(const hydro::PlanarExcitation& table, double direction, double omega);

// The excitation for every component of `wave` on a hull whose BEM origin lies at x_O (global, mean
// position) and at `origin_offset` from G1 in the hull frame.
BemExcitation bem_excitation(const hydro::PlanarExcitation& table, const WaveField& wave, double origin_x,
                             const Eigen::Vector2d& origin_offset);

}  // namespace ffrf::sea
