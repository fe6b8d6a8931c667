// The hull's BEM hydrodynamics for the crane (multibody::HullModel): the radiation model chosen by
// bem.radiation_model (or `--radiation`) and the BEM excitation for the wave field's components,
// both moved from the BEM body origin O to G1 by the rigid transfer T (sea/bem_excitation.hpp):
// A_G = TᵀAT, B_G = TᵀBT, K_G = TᵀKT, X_G = TᵀX. docs/hydrodynamics.md §6.
//  * constant: A(ω_c), B(ω_c) (linear in ω between the file's frequencies), ω_c = 2π/bem.constant_period,
//    else the wave's frequency, else the undamped heave natural frequency ω = √(C33/(m + A33(ω)))
//    (fixed point; C33 = ρgLB, m the displaced mass).
//  * convolution: A∞ and K(t) (hydro/retardation.hpp) with dt = bem.kernel_time_step, T_c =
//    bem.truncation_time (0: automatic) and the fitted high-frequency tail.
//  * state-space: the smallest stable order whose impulse-response error is within
//    bem.state_space_tolerance (hydro/state_space_fit.hpp), diagonalized (hydro/radiation_memory.hpp).
// Kernels and fits are computed once per (files, options) in a process (thread-safe cache).
#pragma once

#include <optional>

#include "multibody/crane_parameters.hpp"
#include "scene/scene.hpp"

namespace ffrf::scene {

// The BEM origin relative to G1 in the hull frame.
Eigen::Vector2d bem_origin_offset(const Scene& scene);
// ω_c of the constant model (see above) [rad/s].
double constant_radiation_frequency(const Scene& scene);
// A copy of the scene whose [bem] uses `kind` (throws SceneError when it has no [bem]).
Scene with_radiation(const Scene& scene, hydro::RadiationKind kind);
// The radiation model of scene.bem (its radiation_model), referred to G1.
std::shared_ptr<const hydro::RadiationMemoryModel> bem_radiation_model(const Scene& scene);
// Fills hull.radiation_memory and, with bem.excitation = "bem" and a wave, hull.bem_excitation
// (the hull's diagonal constants are zeroed: [bem] replaces [radiation]).
void apply_bem_hydrodynamics(const Scene& scene, multibody::HullModel& hull, const std::optional<sea::WaveField>& wave);

}  // namespace ffrf::scene
