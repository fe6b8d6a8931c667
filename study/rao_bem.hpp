// The hull of a [bem] scene in the frequency domain (`ffrf rao`; docs/hydrodynamics.md §6.1).
// The crane's linearisation (multibody/linearisation.hpp) holds the radiation model's A_model in the
// mass matrix and its ∂μ/∂ẋ at t = 0 (empty history) in the damping: A(ω_c), B(ω_c) for the constant
// model, A∞ and ½·dt·K(0) for the convolution, A∞ and 0 for the state-space form. The frequency
// domain adds the hull impedance beyond them, Z(s) (3 × 3, at G1), so that the crane's dynamic
// stiffness is s²M + sC + K + Z(s):
//   * file (the physical RAO): at s = iω, Z = −ω²(A_G(ω) − A_model) + iω(B_G(ω) − ∂μ/∂ẋ(0)), with
//     A(ω), B(ω) of the WAMIT .1 file linear between its frequencies (hydro::radiation_at) and
//     moved to G1 as the time domain moves them, A_G = TᵀAT, B_G = TᵀBT (scene/bem_hull_model.hpp).
//   * model (what the time domain realises): Z(s) = s (K̂(s) − ∂μ/∂ẋ(0)) with K̂ the Laplace transform
//     of the model's own kernel — the convolution's trapezoid sum dt Σ w_j K_j e^{−s j dt} over the
//     truncated samples (w_0 = w_N = ½), the state-space form's Σ c_i b_iᵀ/(s − λ_i) — and 0 for the
//     constant model. At s = iω, K̂ = B_model(ω) + iω(A_model(ω) − A∞). Defined for complex s too, so
//     the natural modes of a memory hull are the roots of det(s²M + sC + K + Z(s)) = 0.
// The wave excitation needs no term here: with excitation = "bem" the waved crane's generalized force
// is the .3 file's (sea/bem_excitation.hpp) and the linearisation's central difference returns
// TᵀX(ω) exactly; the hydrostatic restoring is the linearisation's, i.e. the calm-water pressure on the
// wetted box that the time domain integrates (the .hst only checks the files belong to the hull).
#pragma once

#include <Eigen/Core>
#include <complex>
#include <functional>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace ffrf::study {

enum class BemRadiationSource { file, model };
std::string_view to_string(BemRadiationSource source);  // "file", "model"

using HullImpedance = std::function<Eigen::Matrix3cd(std::complex<double> s)>;

// Z(s) of the scene's [bem] hull (see above); the scene must have [hull] and [bem]. `source` file:
// defined on the imaginary axis only (s = iω within the file's band; other s throw
// std::invalid_argument).
HullImpedance bem_hull_impedance(const scene::Scene& scene, BemRadiationSource source);

// Every angular frequency must lie within the band of the .1 file (and of the .3 file with
// excitation = "bem"): the frequency domain does not extrapolate BEM data. Throws scene::SceneError
// naming the scene file, the key (bem.radiation_file / bem.excitation_file), the file, the first
// frequency outside (and its period) and the valid range in rad/s and s.
void require_bem_band(const scene::Scene& scene, const std::vector<double>& angular_frequencies);

}  // namespace ffrf::study
