// State-space approximation of the radiation kernel (docs/hydrodynamics.md §3.3):
//   ż = A z + B ẋ,   μ = C z,   so that K(t) ≈ C e^{At} B  (μ the memory force of the Cummins equation).
// Fitted by realization theory from the sampled kernel (Kung 1978, "A new identification and model
// reduction algorithm via singular value decompositions"; Juang & Pappa 1985, ERA; used for
// radiation by Kristiansen, Egeland & Fossen 2005 and Taghipour, Perez & Moan 2008): with the
// kernel scaled entry-wise by S = diag(1/sqrt(max|K_ii|)) (so that surge, heave and pitch weigh
// alike whatever their units), samples h_k = S K(kΔ) S form the block Hankel matrix H0 = [h_{i+j}]
// and its shift H1 = [h_{i+j+1}]; the SVD H0 = U Σ Vᵀ truncated at order r gives
//   A_d = Σ_r^{-1/2} U_rᵀ H1 V_r Σ_r^{-1/2},  B_d = first columns of Σ_r^{1/2} V_rᵀ,  C_d = first rows of U_r Σ_r^{1/2},
// h_k ≈ C_d A_d^k B_d, hence A = log(A_d)/Δ (eigen-decomposition), B = B_d S⁻¹, C = S⁻¹ C_d.
// The order is the smallest r whose model is stable (every eigenvalue of A in Re < 0, checked) and
// whose impulse-response error on the fine kernel grid,
//   e_r = sqrt(Σ_k ‖S (K_k − C e^{A t_k} B) S‖_F² / Σ_k ‖S K_k S‖_F²),
// is at most `tolerance`. Passivity (the symmetric part of B_ss(ω) = Re C (iωI − A)⁻¹ B positive
// semi-definite) is reported, not enforced.
#pragma once

#include <Eigen/Dense>

#include <complex>

#include "hydro/retardation.hpp"

namespace ffrf::hydro {

struct StateSpaceOptions {
  double tolerance = 0.02;  // relative L2 impulse-response error e_r
  int max_order = 40;
  int hankel_samples = 200;  // kernel samples used in the Hankel matrices (Δ = T_c / this, a multiple of dt)
};

struct RadiationStateSpace {
  Eigen::MatrixXd a;  // r × r
  Eigen::MatrixXd b;  // r × 3
  Eigen::MatrixXd c;  // 3 × r
  int order = 0;
  double impulse_error = 0.0;       // e_r on the fine kernel grid
  double slowest_decay = 0.0;       // max Re λ(A) [1/s] (< 0: stable)
  double passivity_margin = 0.0;    // min over ω of λ_min(sym B_ss(ω)) / max_ω λ_max(sym B_ss(ω)) (≥ 0: passive)
  double fit_step = 0.0;            // Δ [s]
};

// Throws std::runtime_error when no order up to max_order meets the tolerance with a stable model
// (the message gives the best error reached and what to try).
RadiationStateSpace fit_state_space(const RetardationFunction& kernel, const StateSpaceOptions& options = {});

PlanarMatrix impulse_response(const RadiationStateSpace& model, double t);  // C e^{At} B
// K̂(iω) = C (iωI − A)⁻¹ B = B(ω) + iω (A(ω) − A∞)
Eigen::Matrix3cd frequency_response(const RadiationStateSpace& model, double omega);

}  // namespace ffrf::hydro
