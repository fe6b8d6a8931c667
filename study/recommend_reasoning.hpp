// The physics behind `ffrf recommend` (docs/recommend.md), before any time integration: which parts of the
// boom's behaviour a scene excites, and so which models can be pruned without running them.
//  * Excitation band: the wave frequency ω_w = 2π/T and the hub's spin rate Ω; its top ω_e.
//  * Boom frequencies ω_i: the same solve_modes() as `ffrf modes` on the scene's mesh.
//  * Quasi-static modes: a mode driven at r = ω_e/ω_i < 1 answers with the dynamic amplification
//    1/(1 − r²); treating it as static (a static correction mode) errs by r²/(1 − r²). Modes where
//    that exceeds the tolerance τ must be kept as vibration modes (k ≥ their count).
//  * Rigid boom: misses the quasi-static tip deflection under the load δ = F⊥L³/(3EI) + q⊥L⁴/(8EI)
//    (F⊥ the cargo weight, q⊥ the boom's weight per length, both across the boom); its vertical part
//    δ cos φ against the cargo's RMS heave a/√2 (a = H/2, the wave amplitude) estimates its error.
//    A boom without that deflection's output (the tip deflection itself) errs by 100 %.
//  * Modal truncation without static modes: mode i carries the share 12 EI/(ω_i² m L³) of the
//    tip's static flexibility L³/(3EI) (a clamped–free beam: φ_i(L)² = 4/m); k modes miss the rest.
//  * Geometric stiffening: the compression P = (ρA g L + m_c g) sin φ against the Euler load
//    P_E = π²EI/(4L²) amplifies the deflection by 1/(1 − P/P_E) (static stiffening needed when that
//    changes the outputs by more than τ); a spin Ω softens the unstiffened boom to ω1² − Ω²
//    (centrifugal stiffening needed when Ω²/ω1² > τ; Ω ≥ ω1 diverges).
//  * Integrator: BDF at the model-choice rtol, the decade at or below τ/10⁴ (study/verdict.hpp: its
//    global error reaches ~100× rtol, leaving the model to decide);
//    an explicit RK only where its stability limit β_I/ω_max (damped: docs/performance.md) is at
//    least the output interval, i.e. where the stiffness of the retained modes does not bind.
#pragma once

#include <string>
#include <vector>

#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"
#include "multibody/error_metrics.hpp"

namespace ffrf::study {

struct BoomMode {
  double angular_frequency;  // [rad/s]
  std::string kind;          // "bending", "axial", ...
};

struct RecommendReasoning {
  double tolerance = 0.01;
  std::vector<BoomMode> modes;         // solve_modes on the scene's mesh, as `ffrf modes`
  double wave_frequency = 0.0;         // ω_w [rad/s] (0: calm water)
  double spin_rate = 0.0;              // Ω [rad/s] (0: no spinning hub)
  double excitation_top = 0.0;         // ω_e = max(ω_w, Ω)
  int dynamic_modes = 0;               // modes with r²/(1 − r²) > τ (or r ≥ 1): keep as vibration modes
  double static_tip_deflection = 0.0;  // δ [m]
  double rigid_error = 0.0;            // a-priori normalized error of the rigid boom
  double axial_load = 0.0;             // P [N] (compression)
  double euler_load = 0.0;             // P_E [N]
  double static_stiffening_effect = 0.0;       // rigid_error · P/(P_E − P)
  double centrifugal_softening = 0.0;          // Ω²/ω1²
  scene::Stiffening required_stiffening = scene::Stiffening::none;  // what the physics needs
  scene::Stiffening reference_stiffening = scene::Stiffening::none; // required ∪ the scene's
  double relative_tolerance = 1e-6;    // the integrators' rtol (model_choice_rtol(τ))
  std::vector<std::string> statements; // the reasoning in plain words with its numbers
};

// The geometric stiffening a reference for this scene models (one physics for compare,
// sweep and recommend): what the physics needs at `tolerance` on the judged outputs (static
// stiffening near buckling, centrifugal at high spin) together with what the scene asks for —
// RecommendReasoning::reference_stiffening. Throws modal::EigenSolverError.
scene::Stiffening physics_stiffening(const scene::Scene& scene, double tolerance);

// Throws modal::EigenSolverError when the boom's modes cannot be solved.
RecommendReasoning reason_about(const scene::Scene& scene, double tolerance,
                                const std::vector<multibody::OutputChannel>& outputs);

// Fraction of the tip's static flexibility the first k modes of `modes` do not carry (bending modes
// only, each 12 EI/(ω² m L³)); 1 for k = 0.
double missing_flexibility(const scene::Scene& scene, const std::vector<BoomMode>& modes, int k);

// Quasi-static error r²/(1 − r²) of a mode at ω driven at ω_e (infinity at or above resonance).
double quasi_static_error(double excitation, double angular_frequency);

}  // namespace ffrf::study
