// The stability region of the explicit Runge–Kutta table that integrate_explicit uses (ARKODE's
// Zonneveld 4(3)): the stability function R(w) = 1 + w bᵀ(I − wA)⁻¹𝟙 (A strictly lower) and its
// boundary along a ray of the complex plane. Shared by the ARKODE adapter (its linearized step
// limit) and the stable-step measurement (solve/explicit_stability.hpp).
#pragma once

#include <cstdio>  // before SUNDIALS' Butcher header, which uses FILE

#include <arkode/arkode_butcher_erk.h>

#include <complex>

namespace ffrf::solve {

inline constexpr ARKODE_ERKTableID explicit_table_id = ARKODE_ZONNEVELD_5_3_4;

// R(w) of the table.
std::complex<double> explicit_stability_function(std::complex<double> w);
// s*(d): the largest s with |R(s d)| ≤ 1 on (0, s] along the direction d (normalized here; ≤ 20).
double explicit_ray_boundary(std::complex<double> direction);

}  // namespace ffrf::solve
