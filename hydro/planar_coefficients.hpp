// Frequency-domain hydrodynamic coefficients of a hull in ffrf's planar degrees of freedom
// (surge x forward, heave y up, pitch θ counter-clockwise = bow up; docs/hydrodynamics.md §4), at
// the reference point of the BEM run: added mass A(ω), radiation damping B(ω), their zero- and
// infinite-frequency limits, the hydrostatic stiffness C and the first-order excitation per unit
// wave amplitude X(ω, heading) (complex: F(t) = Re{X a e^{iωt}} for η(0, t) = Re{a e^{iωt}}).
// Units: [kg, kg m, kg m²] for A, [N s/m, N s, N m s] for B, [N/m, N, N m/rad] for C, [N/m, N m/m]
// for X. Plain data; the readers fill it (wamit_reader.hpp), the radiation models use it.
#pragma once

#include <Eigen/Dense>

#include "linalg/space.hpp"

#include <array>
#include <complex>
#include <string>
#include <vector>

namespace ffrf::hydro {

// A planar rigid body's degrees of freedom (linalg/space.hpp): 0 surge, 1 heave, 2 pitch.
inline constexpr int kPlanarDofs = linalg::Planar::body_dofs;
// From a BEM file's degrees of freedom to these: T = diag(1, 1, −1), a coefficient A_ij becoming
// T_i T_j A_ij and an excitation X_i becoming T_i X_i (WAMIT's and Capytaine's pitch is bow down).
inline constexpr std::array<double, kPlanarDofs> kBemToPlanarSign{1.0, 1.0, -1.0};
using PlanarMatrix = Eigen::Matrix3d;
using PlanarVector = Eigen::Vector3d;
using PlanarComplexVector = Eigen::Vector3cd;

struct PlanarRadiation {
  std::vector<double> frequency;           // ω [rad/s], strictly increasing, ≥ 0 (BEM files: > 0)
  std::vector<PlanarMatrix> added_mass;    // A(ω_i)
  std::vector<PlanarMatrix> damping;       // B(ω_i)
  bool has_zero_frequency = false, has_infinite_frequency = false;
  PlanarMatrix zero_frequency_added_mass = PlanarMatrix::Zero();      // A(0)
  PlanarMatrix infinite_frequency_added_mass = PlanarMatrix::Zero();  // A∞
  std::string source;                      // file the data came from
};

struct PlanarExcitation {
  std::vector<double> frequency;                        // ω [rad/s], strictly increasing
  std::vector<double> heading_degrees;                  // BEM headings β (0: waves travel +x)
  std::vector<std::vector<PlanarComplexVector>> force;  // [heading][frequency] X per unit amplitude
  std::string source;
};

// Constant coefficients: the cheapest radiation model (A and B at one frequency, linear
// interpolation between tabulated frequencies; clamped to the table's ends).
struct ConstantRadiation {
  PlanarMatrix added_mass = PlanarMatrix::Zero();
  PlanarMatrix damping = PlanarMatrix::Zero();
};
ConstantRadiation radiation_at(const PlanarRadiation& radiation, double omega);

}  // namespace ffrf::hydro
