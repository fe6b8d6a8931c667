// The radiation added mass made symmetric where BEM coefficients enter the model. For a body at
// zero forward speed A(ω) is symmetric (Green's reciprocity; Newman, Marine Hydrodynamics (1977)
// §6.17), so an asymmetry in a file is numerical error of the BEM code (WAMIT's runs are symmetric
// to about 1 %, other codes' to 10–30 % in the surge–pitch pair). Every path of the model (the
// equations' residual and Jacobian, the minimal-coordinate accelerations, whose hull block an LDLᵀ
// factorization reads by its lower triangle, the linearisation, the frequency domain, the Cummins
// kernel's A∞) must see one matrix, so A(ω_k), A(0) and A∞ are replaced by (A + Aᵀ)/2 once, when the
// file has been read; the damping B(ω) is left as read (no path factorizes it).
// The asymmetry reported is the largest relative difference of a pair,
//   r = |A_ij − A_ji| / max(|A_ij|, |A_ji|)   (i ≠ j),
// over the entries where the pair is at least `significant_share` of its largest magnitude in the
// table (near a zero crossing of the coupling a relative difference means nothing).
#pragma once

#include <string>

#include "hydro/planar_coefficients.hpp"

namespace ffrf::hydro {

// Where a coefficient of the table lies: a tabulated frequency or one of the two limits.
enum class TableRow { frequency, zero_frequency, infinite_frequency };

struct AddedMassAsymmetry {
  double relative = 0.0;       // r of the worst pair [-] (0: symmetric)
  int row = -1, column = -1;   // planar indices of the worst pair (0 surge, 1 heave, 2 pitch); −1: none
  TableRow where = TableRow::frequency;
  double angular_frequency = 0.0;  // ω [rad/s] when where == frequency
  double upper = 0.0, lower = 0.0;  // A_ij (i < j) and A_ji there, as read
  bool found() const { return row >= 0; }
  // "A15 = 1.23e6 kg m against A51 = 1.48e6 kg m (20.3 %) at ω = 0.785 rad/s (period 8 s)", in WAMIT's
  // mode numbers (1 surge, 3 heave, 5 pitch); "" when none was found.
  std::string describe() const;
};

// Entries below this share of the pair's largest magnitude are not compared; asymmetries above
// `asymmetry_warning` are reported to the user (scene/scene_loader.cpp).
inline constexpr double significant_share = 0.05;
inline constexpr double asymmetry_warning = 0.01;

// Replaces every added-mass matrix of `radiation` by its symmetric part; returns the largest
// asymmetry it removed.
AddedMassAsymmetry symmetrise_added_mass(PlanarRadiation& radiation);

}  // namespace ffrf::hydro
