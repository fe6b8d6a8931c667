// Exact Fourier integral of a piecewise-linear function (Filon's idea with linear interpolation:
// Filon 1928, Proc. R. Soc. Edinburgh 49): for samples f_k at increasing x_k,
//   ∫_{x_0}^{x_{n−1}} f(x) e^{i t x} dx = Σ_k h_k e^{i t x_k} [f_k (E0(θ_k) − E1(θ_k)) + f_{k+1} E1(θ_k)],
//   h_k = x_{k+1} − x_k, θ_k = t h_k, E_m(θ) = ∫₀¹ s^m e^{iθs} ds,
// E0 = (e^{iθ} − 1)/(iθ), E1 = e^{iθ}/(iθ) + (e^{iθ} − 1)/θ², by their Taylor series for |θ| < 0.25
// (no cancellation). Exact whatever t h_k: the frequency or time step need not resolve cos(t x).
// Used both ways: B(ω) → K(t) (cosine part) and K(t) → B(ω), A(ω) (cosine and sine parts).
#pragma once

#include <complex>
#include <cstddef>

namespace ffrf::hydro {

// x, f of length n ≥ 2, x strictly increasing; `stride` is the distance between consecutive f
// values in memory (to read one entry of a sequence of matrices).
std::complex<double> linear_fourier_integral(const double* x, const double* f, std::size_t n, double t,
                                             std::size_t stride = 1);

}  // namespace ffrf::hydro
