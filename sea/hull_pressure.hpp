// Nonlinear hydrostatic + Froude–Krylov load on a box-shaped hull section: the total incident
// pressure (sea/wave_field.hpp; calm water when wave == nullptr) integrated over the hull's
// instantaneous wetted boundary below the incident wave profile. The box (in the hull frame, origin
// at G1) is clipped by the wave surface: each edge is split where it crosses ζ(x, t)
// (sea/waterline_crossings.hpp) and the pressure, a sum of exponentials along a straight edge,
// is integrated on each wetted piece in closed form (linear cost in the wave component count).
// F = −B ∮ p n ds (B the width normal to the plane, n the outward normal),
// M = −B ∮ p (r − r_G1) × n ds about G1 (planar cross product a × b = a_x b_y − a_y b_x).
// Carries hydrostatics and the incident-wave (Froude–Krylov) excitation only; radiation and
// diffraction are separate (docs/theory.md §6). Planar: surge x, heave y, pitch θ counter-clockwise.
#pragma once

#include <Eigen/Dense>

#include "sea/wave_field.hpp"

namespace ffrf::sea {

struct BoxHullSection {
  double aft_x;    // hull frame x of the stern relative to G1 [m] (< fore_x)
  double fore_x;   // hull frame x of the bow [m] (> aft_x)
  double keel_y;   // hull frame y of the keel [m] (< deck_y)
  double deck_y;   // hull frame y of the deck [m] (> keel_y)
  double width;    // B, normal to the plane [m] (> 0)
};

struct HullLoad {
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  // global frame [N]
  double moment = 0.0;                              // about G1, counter-clockwise [N m]
  double wetted_length = 0.0;                       // length of wetted boundary in the plane [m]
};

// pose: G1 position (x, y) in the global frame and pitch θ; t the time for the wave. Hull frame
// point c maps to g1_position + A(θ) c. With a wave, its pressure uses wave->gravity(), which must
// equal `gravity` (std::invalid_argument otherwise). Allocates nothing on success. Throws
// std::domain_error (pose in the message) if the pose or t is not finite, or if one edge crosses
// the surface more than 64 times; std::invalid_argument on a degenerate box.
HullLoad hull_pressure_load(const BoxHullSection& hull, const WaveField* wave, double water_density,
                            double gravity, const Eigen::Vector2d& g1_position, double pitch, double t);

// Linear calm-water hydrostatic restoring coefficients of the box floating at even keel with
// displaced volume V (draft T = V / (B L), L = fore_x − aft_x), and the centre of gravity of the
// whole floating system at height z_G above the keel:
//   C33 = ρ g B L                                     [N/m]
//   C55 = ρ g (B L³ / 12 + V (z_B − z_G)),  z_B = T/2  [N m/rad]
// C55 is the pitch stiffness about the centre of flotation (mid-length: waterplane inertia about
// its own centre), i.e. the uncoupled pitch stiffness used to size critical damping. About G1,
// x_f = (aft_x + fore_x)/2 forward of it, the pressure integral gives instead
// C55 + ρ g B L x_f² and the heave–pitch couplings C35 = C53 = +ρ g B L x_f (C = −∂Q/∂q; pitch
// bow-up positive, so ∂F_y/∂θ = ∂M/∂y = −ρ g B L x_f). C55 < 0 (unstable) is returned as is.
// Throws std::invalid_argument if V ≤ 0, T ≥ deck_y − keel_y or the box is degenerate.
Eigen::Vector2d box_hydrostatic_stiffness(const BoxHullSection& hull, double water_density, double gravity,
                                          double displaced_volume, double center_of_gravity_above_keel);

}  // namespace ffrf::sea
