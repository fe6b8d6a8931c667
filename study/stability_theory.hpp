// Theoretical explicit-RK step limits of the crane's parts, to compare with the measured limit
// (solve/explicit_stability.hpp) and with the coupled system's Jacobian bound
// (solve::explicit_stable_step):
//  * the boom's elastic coordinates alone, clamped at the root: ω_i² the eigenvalues of
//    M_ff⁻¹ K in the coordinates build_crane_equations uses (nodal: the FE mesh's free DOFs; modal: the
//    retained vibration modes and the Rayleigh frequencies of the static correction modes);
//    undamped bound h = β_I / ω_max (β_I the table's imaginary-axis boundary); with the boom's
//    stiffness-proportional damping D = βK each mode is an oscillator λ² + βω²λ + ω² = 0, ζ = βω/2,
//    and the bound is min over modes and roots of s*(λ/|λ|)/|λ| (overdamped top modes sit near
//    λ ≈ −βω² on the real axis);
//  * the wire–cargo bounce √(k_wire / m_cargo) (the rigid boom's fastest mode), bound β_I / ω.
// The axial preload's geometric stiffness is left out (it shifts the top frequencies by < 10⁻⁴).
#pragma once

#include <Eigen/Dense>

#include "scene/crane_builder.hpp"
#include "modal/mode_cache.hpp"
#include "scene/scene.hpp"

namespace ffrf::study {

// All angular frequencies ω_i [rad/s] of the boom's elastic coordinates, ascending (empty: rigid).
Eigen::VectorXd boom_angular_frequencies(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* cache = nullptr);

// ω_max [rad/s] of the boom's elastic coordinates (0 for the rigid boom).
double highest_boom_frequency(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* cache = nullptr);

// β_I / ω_max: the undamped boom's ERK step limit [s] (infinity for the rigid boom).
double undamped_boom_step_limit(double highest_frequency);

// The boom's ERK step limit [s] with its stiffness-proportional damping β (min over the modes).
double damped_boom_step_limit(const Eigen::VectorXd& angular_frequencies, double stiffness_damping);

// √(k_wire / m_cargo) [rad/s]: the cargo bouncing on the wire rope with the boom tip held.
double wire_cargo_frequency(const scene::Scene& scene);

}  // namespace ffrf::study
