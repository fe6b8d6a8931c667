// Natural frequencies of the beam spinning at a constant rate Ω in the plane and/or prestressed by
// a uniform axial force P. In the rotating floating frame, the linear in-plane equation of the
// beam (root held by the frame) is
//   M η̈ + (K + s Ω² K_c + P K_g,1 − Ω² M) η = 0,
// where −Ω²M is the centrifugal softening of the floating-frame quadratic-velocity term θ̇² M_ff η,
// K_c the geometric stiffness of the centrifugal axial force per unit Ω² (fem/axial_force.hpp,
// hub a distance r behind the root), s = 1 with centrifugal stiffening and 0 without, and K_g,1 the
// geometric stiffness of a 1 N tension. The Coriolis coupling 2Ω S̃ η̇ to the far stiffer axial
// modes is neglected in this frequency analysis. Hence without stiffening (and P = 0) ω² = ω₀² − Ω²
// exactly for every mode; ω² < 0 is divergence with growth rate √(−ω²). The generalized symmetric
// problem (K_Ω, M) is solved by the solvers of modal/eigen_solver.hpp with a shift σ proven below
// the whole spectrum (inertia of the LDLᵀ factors of K_Ω − σM, Sylvester's law), so the lowest
// modes are found even when K_Ω is indefinite. docs/theory.md, "Rotating and prestressed beam
// frequencies".
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "fem/analytic_beam.hpp"
#include "fem/beam_model.hpp"
#include "modal/eigen_solver.hpp"

namespace ffrf::modal {

struct RotatingBeamState {
  double spin_rate = 0.0;              // Ω [rad/s], ≥ 0
  double hub_radius = 0.0;             // r [m], ≥ 0: spin axis a distance r behind the root
  bool centrifugal_stiffening = true;  // s: include Ω² K_c
  double axial_force = 0.0;            // P [N], uniform, tension > 0, compression < 0
};

struct RotatingMode {
  double omega_squared;       // ω² [rad²/s²]; negative: divergence
  fem::ModeKind kind;         // bending or axial (by the axial share of the kinetic energy)
  int order;                  // 1-based within its kind
  double axial_energy_share;  // in [0, 1]

  bool stable() const { return omega_squared >= 0.0; }
  double angular_frequency() const;  // √ω² [rad/s], 0 when unstable
  double growth_rate() const;        // √(−ω²) [1/s], 0 when stable
};

struct RotatingBeamModes {
  RotatingBeamState state;
  double shift;                     // σ [rad²/s²] used, below every eigenvalue
  EigenPairs pairs;                 // ω² ascending, M-normalized shapes on the free DOFs
  std::vector<RotatingMode> modes;  // one per eigenpair
};

// K_Ω = K + s Ω² K_c + P K_g,1 − Ω² M on the free DOFs of the model.
// Throws std::invalid_argument for a negative or non-finite Ω, r or a non-finite P, and for a
// free–free beam (nothing holds the root against the centrifugal or axial force).
Eigen::SparseMatrix<double> rotating_stiffness(const fem::BeamModel& model, const RotatingBeamState& state);

// A shift σ ≤ start with K − σM positive definite (no negative LDLᵀ pivot), lowered step by step
// from `start`; throws EigenSolverError when none is found in 200 steps.
double shift_below_spectrum(const SparseMatrix& stiffness, const SparseMatrix& mass, double start);

// The lowest `count` modes of (K_Ω, M), 1 ≤ count < free DOFs; throws std::invalid_argument
// (see rotating_stiffness) or EigenSolverError.
RotatingBeamModes rotating_beam_modes(const fem::BeamModel& model, const RotatingBeamState& state, int count,
                                      EigenSolverKind solver = EigenSolverKind::arpack);

}  // namespace ffrf::modal
