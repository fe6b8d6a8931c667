// The infinite-frequency added mass A∞ of a BEM table that has none (Capytaine's datasets
// usually), two ways (docs/hydrodynamics.md §4.5):
//  * Kramers–Kronig, from B(ω). With ffrf's definitions (retardation.hpp)
//      A(ω) = A∞ − (1/ω)∫₀^∞ K(t) sin ωt dt,  K(t) = (2/π)∫₀^∞ B(ν) cos νt dν,
//    and ∫₀^∞ cos νt sin ωt dt = ω/(ω² − ν²) (Abel limit), so
//      A(ω) − A∞ = (2/π) PV∫₀^∞ B(ν)/(ν² − ω²) dν.
//    (Check: B = b a²/(a² + ν²) gives −ab/(a² + ω²), the Lorentzian pair of kernel_pairs.) Every
//    tabulated ω but the last gives an estimate A(ω) − (2/π)PV∫…; the estimate is their median,
//    entry by entry (robust to the irregular frequencies of a BEM run). B is the retardation
//    function's model (damping_model: linear between samples, from 0 at ω = 0, with its fitted
//    high-frequency tail), whose principal-value integral is exact in closed form:
//      PV∫ B/(ν² − ω²) = (1/2ω) Σ_k [c_k ln|ν_k − ω| − d_k ln(ν_k + ω)]
//    over the model's nodes ν_k, with c_k = (q_k⁻ − q_k⁺)(ω − ν_k), d_k = (q_k⁻ − q_k⁺)(−ω − ν_k)
//    at interior nodes (q⁻, q⁺ the slopes left and right) and the end nodes' jumps to B = 0.
//  * the high-frequency end: A(ω) = A∞ + c/ω² fitted by least squares to the last `points`
//    tabulated frequencies (the leading term of the relation above once ω is beyond B's support).
//    Good only when the table reaches well past the damping's band.
// On the WAMIT fixture, which has A∞, Kramers–Kronig reproduces it within 0.13 % (surge),
// 1.4·10⁻⁶ (heave), 6.5·10⁻⁵ (pitch) and 0.14 % (couplings); the high-frequency end within 1.3 %,
// 0.03 %, 0.02 % and 0.33 %: tests/hydro/test_infinite_frequency.cpp.
#pragma once

#include <string>
#include <vector>

#include "hydro/planar_coefficients.hpp"

namespace ffrf::hydro {

enum class InfiniteFrequencyMethod { kramers_kronig, high_frequency };
std::string to_string(InfiniteFrequencyMethod method);  // "kramers-kronig", "high-frequency"

// A(ω_k) − (2/π) PV∫₀^∞ B(ν)/(ν² − ω_k²) dν at every tabulated ω_k but the last (per frequency).
std::vector<PlanarMatrix> kramers_kronig_estimates(const PlanarRadiation& radiation);

struct InfiniteFrequencyEstimate {
  InfiniteFrequencyMethod method = InfiniteFrequencyMethod::kramers_kronig;
  PlanarMatrix added_mass = PlanarMatrix::Zero();      // the chosen method's A∞
  PlanarMatrix kramers_kronig = PlanarMatrix::Zero();  // median of kramers_kronig_estimates
  PlanarMatrix high_frequency = PlanarMatrix::Zero();  // the fit at the table's end
  int high_frequency_points = 0;                       // samples the fit used
};

// Both estimates and the chosen one. Throws std::invalid_argument for fewer than 3 frequencies.
InfiniteFrequencyEstimate estimate_infinite_frequency_added_mass(const PlanarRadiation& radiation,
                                                                 InfiniteFrequencyMethod method, int points = 5);

// The table with A∞ set from the estimate (has_infinite_frequency true).
PlanarRadiation with_infinite_frequency(PlanarRadiation radiation, const InfiniteFrequencyEstimate& estimate);

}  // namespace ffrf::hydro
