// The largest stable fixed step of ARKODE's explicit Runge–Kutta (integrate_explicit, Zonneveld
// 4(3)) on a second-order system, measured by running it, and the table's stability region to compare with.
//
// Stability region: R(w) = 1 + w bᵀ(I − wA)⁻¹𝟙 of the same Butcher table; along a ray w = s d the
// step h is stable for a mode λ while h|λ| ≤ s*(λ/|λ|), the first s where |R(s d)| > 1.
//
// Measurement (measure_stable_step): trial runs of integrate_explicit at fixed h, each judged stable
// (the window completes) or unstable (SolverFailure whose cause starts "unstable:", its per-step
// kinetic-energy watch: E_kin > 10⁶ (E_ref + E_floor)); no second integrator. Design:
//  * Seed. integrate_explicit starts at rest (ż = 0), so the seed is a displacement: every minimal
//    coordinate is moved by δz_j = seed_size · scale_j · cos(2 + 2.39996 j) (deterministic, no zero
//    entries, no mode of a beam or of the crane orthogonal to it). A displacement excites each
//    mode with its own amplitude just as a velocity seed would: the linear growth |R(hλ)|ⁿ does not
//    care which; round-off never has to supply the unstable mode. The hull and cargo coordinates
//    are seeded too, so that the wire–cargo bounce mode (the rigid boom's limit) grows as well.
//  * Window. A mode just beyond the boundary, at h = (1 + p/2) h*, grows per step by
//    g = min over rays of |R((1 + p/2) s*(d) d)| (rays from the imaginary to the negative real
//    axis: undamped and overdamped modes). The watch fires after an energy growth of 10⁶ over
//    E_ref + E_floor (E_floor = ½ tr M ≈ 10¹⁰ J here, dominated by the hull's pitch inertia), i.e.
//    an amplitude growth G of 10³ × (E_floor / E_seed)^½ from a seed of energy E_seed; G = 10¹¹
//    covers seeds down to ≈ 10⁻⁶ J. The window is n = ln G / ln g steps (≈ 800 for p = 2 %), at
//    least min_window_steps. On the reference crane the measured limits move by < 2 % between
//    G = 10¹¹ and 10⁴⁰ and between seed sizes 10⁻⁶ and 10⁻⁹ (rigid, nodal N = 1, 2, 4, 16, modal
//    k = 2 + static): the window is long enough. Outputs every n/32 steps keep E_ref (the kinetic
//    energy of the first output) from absorbing the growth it is meant to detect.
//  * Search. From h0 (e.g. the linearized limit), expand or shrink by 1.5 until a stable and an
//    unstable step bracket the limit, then geometric bisection until h_u/h_s − 1 ≤ p.
//  * Cap. At most max_trials runs and max_rhs_evaluations right-hand sides (all trials, counted by
//    a wrapper around the equations, including the linearized-limit Jacobian each failure report
//    evaluates); a capped search returns converged = false with the bracket found so far.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "solve/second_order_system.hpp"
#include "solve/erk_stability_region.hpp"

namespace ffrf::solve {

// Largest stable step of one linear mode with eigenvalue λ (Re λ ≤ 0): s*(λ/|λ|) / |λ|.
double explicit_mode_step_limit(std::complex<double> eigenvalue);

struct StableStepSearch {
  double relative_precision = 0.02;   // p: stop when h_unstable / h_stable − 1 ≤ p
  double seed_size = 1e-6;            // seed displacement per coordinate, in units of coordinate_scale()
  double detection_growth = 1e11;     // G: amplitude growth from seed to detection the window allows
  long min_window_steps = 400;
  int max_trials = 40;
  long max_rhs_evaluations = 50'000'000;
};

struct StabilityTrial {
  double step;  // [s]
  bool stable;
};

struct StableStepMeasurement {
  double stable_step = 0.0;     // largest trial step that stayed stable over the window [s] (0: none)
  double unstable_step = 0.0;   // smallest trial step that blew up [s] (0: none)
  int trials = 0;
  long rhs_evaluations = 0;     // over all trials
  long window_steps = 0;        // steps per trial
  bool converged = false;       // bracket narrowed to the precision within the caps
  std::string failure;          // the cause reported by the smallest unstable trial
  std::vector<StabilityTrial> trial_log;  // every trial in the order run

  double relative_width() const { return unstable_step / stable_step - 1.0; }
};

// Steps per trial window for a precision p and growth G (see the header comment).
long stability_window_steps(const StableStepSearch& search);

// The seed displacement δz added to z0 before every trial.
Eigen::VectorXd stability_seed(SecondOrderSystem& equations, double seed_size);

// Measures the largest stable fixed ERK step about z0 (a static equilibrium), starting the
// bracket at h0 > 0. Throws SolverFailure for failures that are not instability.
StableStepMeasurement measure_stable_step(SecondOrderSystem& equations, const Eigen::VectorXd& z0, double h0,
                                          const StableStepSearch& search = {});

}  // namespace ffrf::solve
