// Radiation-damping curves with closed-form retardation functions (K = (2/π)∫B cos ωt dω ⇔
// B = ∫₀^∞ K cos ωt dt, A(ω) − A∞ = −(1/ω)∫₀^∞ K sin ωt dt), for the hydro tests:
//   Lorentzian:     B = b a²/(a² + ω²)                              ⇔ K = a b e^{−at},
//                   A − A∞ = −a b/(a² + ω²);
//   damped cosine:  B = (c/2)[α/(α² + (ω − β)²) + α/(α² + (ω + β)²)] ⇔ K = c e^{−αt} cos βt.
// Both B decay like ω⁻², the tail the retardation function's tail model must carry.
#pragma once

#include <cmath>

#include "hydro/planar_coefficients.hpp"

namespace ffrf::hydro::test {

struct Lorentzian {
  double a = 0.8, b = 2.0e6;
  double damping(double w) const { return b * a * a / (a * a + w * w); }
  double kernel(double t) const { return a * b * std::exp(-a * t); }
  double added_mass_change(double w) const { return -a * b / (a * a + w * w); }
};

struct DampedCosine {
  double c = 1.5e6, alpha = 0.3, beta = 1.2;
  double damping(double w) const {
    return 0.5 * c * (alpha / (alpha * alpha + (w - beta) * (w - beta)) + alpha / (alpha * alpha + (w + beta) * (w + beta)));
  }
  double kernel(double t) const { return c * std::exp(-alpha * t) * std::cos(beta * t); }
};

// A heave-only coefficient set sampled at ω = 0, dω, ..., ω_max (A∞ = a_inf; A(ω) = A∞ stands in, unused).
template <class Pair>
PlanarRadiation heave_only(const Pair& pair, double d_omega, double omega_max, double a_inf = 3.0e6) {
  PlanarRadiation r;
  for (int k = 0; k * d_omega <= omega_max * (1 + 1e-12); ++k) {
    const double w = k * d_omega;
    r.frequency.push_back(w);
    PlanarMatrix b = PlanarMatrix::Zero();
    b(1, 1) = pair.damping(w);
    r.damping.push_back(b);
    PlanarMatrix a = PlanarMatrix::Zero();
    a(1, 1) = a_inf;
    r.added_mass.push_back(a);
  }
  r.has_infinite_frequency = true;
  r.infinite_frequency_added_mass(1, 1) = a_inf;
  return r;
}

}  // namespace ffrf::hydro::test
