// The crane linearised about its static equilibrium in calm water, in the minimal coordinates z of
// the time domain (multibody/crane_equations.hpp): small motions δz obey
//   M δz̈ + C δż + K δz = F(t),   M = M_z(z₀),  C = −∂Q_z/∂ż,  K = −∂Q_z/∂z  at (z₀, ż = 0),
// the blocks the implicit integrators' Newton matrices use (CraneEquations::minimal_jacobian): hull
// hydrostatics and constant radiation, mooring, the taut wire as a spring–dashpot, boom stiffness,
// damping and geometric stiffness — the time domain's own physics, not a second model.
// The wave excitation per unit wave amplitude is the derivative of the generalized forces Q_z
// (CraneEquations::minimal_generalized_forces: the forces themselves, no mass matrix solved) with
// respect to the amplitude of a regular wave at the equilibrium, at phases 0° and 90°:
// with the elevation ζ(x = 0, t) = a cos ωt and F(t) = a Re(F̂ e^{iωt}),
//   Re F̂ = [Q(0) − Q(T/2)] / 2a,   Im F̂ = −[Q(T/4) − Q(3T/4)] / 2a     (T = 2π/ω),
// a central difference in the amplitude (Q at t + T/2 is Q of the wave −ζ), so the nonlinear hull
// pressure's second-order part drops out. Outputs y = G δz + H δż by central differences of the
// equations' outputs (the wire tension depends on the stretch rate). Theory: docs/theory.md §12.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string_view>

#include "multibody/output_channels.hpp"

namespace ffrf::multibody {

class CraneEquations;

struct LinearisedCrane {
  Eigen::VectorXd equilibrium;  // z₀
  Eigen::MatrixXd mass;         // M (n × n)
  Eigen::MatrixXd damping;      // C
  Eigen::MatrixXd stiffness;    // K
  int hull_at = -1;             // index of the hull's (x, y, θ) in z; −1 when the hull is held
  int cargo_at = -1;            // index of the cargo's (x, y, θ); −1 without a cargo
  int elastic_at = 0;           // index of the elastic coordinates
  // The angles of the bodies pinned to the hull (the A-frame's γ) and their bodies' names.
  std::vector<int> pinned_at;
  std::vector<std::string> pinned_names;
  int size() const { return static_cast<int>(equilibrium.size()); }
};

// M, C, K of `calm` (equations without a wave) at its static equilibrium z₀ (at rest).
LinearisedCrane linearise_crane(CraneEquations& calm, const Eigen::VectorXd& equilibrium);

// F̂ per metre of wave amplitude (see above) from `waved`: the same crane in a regular wave of
// amplitude `amplitude` [m] and angular frequency ω, zero phase, no ramp.
Eigen::VectorXcd wave_excitation(CraneEquations& waved, const LinearisedCrane& linear, double angular_frequency,
                                 double amplitude);

// y = G δz + H δż for every LinearOutput (rows in enum order: the output-channel table's rows with a
// linear name, multibody/output_channels.hpp), at the equilibrium.
struct OutputMap {
  Eigen::MatrixXd position;  // G (linear_output_count × n)
  Eigen::MatrixXd velocity;  // H
};
OutputMap linear_outputs(CraneEquations& calm, const LinearisedCrane& linear);

}  // namespace ffrf::multibody
