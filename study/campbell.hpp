// The computation behind `ffrf modes --spin`, `--spin-range` and `--axial-force`: the beam's
// modes in the rotating floating frame at a constant spin Ω (with and without centrifugal
// stiffening) and/or about a state prestressed by a uniform axial force P, next to the power-series
// reference of the clamped-free beam; and the Campbell diagram (the lowest bending frequencies over
// a range of spin rates). Physics: modal/rotating_beam_modes.hpp, fem/analytic_rotating_beam.hpp.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fem/analytic_beam.hpp"
#include "fem/beam_model.hpp"
#include "modal/eigen_solver.hpp"

namespace ffrf::study {

// n spin rates evenly spaced in [first, last] (first ≥ 0, last > first, n ≥ 2).
struct SpinRange {
  double first;  // [rad/s]
  double last;   // [rad/s]
  int count;
  double at(int i) const { return first + (last - first) * i / (count - 1); }
};


// One mode at one spin: ω² [rad²/s²] (negative: divergence) without geometric stiffness (K − Ω²M:
// no centrifugal stiffening, no P) and with it (K + Ω²K_c + P K_g,1 − Ω²M), and the power series
// (clamped-free bending modes below buckling only).
struct SpinModeRow {
  fem::ModeKind kind;
  int order;
  std::optional<double> plain_omega2;      // without geometric stiffness, same kind and order
  double stiffened_omega2;
  std::optional<double> reference_omega2;  // power series
  double axial_energy_share;
};

struct SpinModesResult {
  fem::BeamMesh mesh;
  fem::Boundary boundary;
  modal::EigenSolverKind solver;
  int dof;
  double spin_rate;    // Ω [rad/s]
  double hub_radius;   // r [m]
  double axial_force;  // P [N]
  std::optional<double> buckling_load;  // [N]
  double shift;                         // σ of the stiffened solve [rad²/s²]
  std::vector<SpinModeRow> rows;        // the lowest `count` stiffened modes, ascending
  double solve_seconds;
  std::vector<std::string> warnings;
};

// Throws std::invalid_argument for a free–free beam or invalid values, modal::EigenSolverError.
SpinModesResult solve_spin_modes(const fem::BeamModel& model, double spin_rate, double hub_radius, double axial_force,
                                 int count, modal::EigenSolverKind solver);

// The Campbell diagram: ω² of the lowest `bending_count` bending modes at every spin of the range.
struct CampbellPoint {
  double spin_rate;                                 // Ω [rad/s]
  std::vector<double> stiffened_omega2;             // per bending order 1..k
  std::vector<double> plain_omega2;                 // without stiffening (and without P)
  std::vector<std::optional<double>> reference_omega2;  // power series with stiffening
};

struct CampbellResult {
  fem::BeamMesh mesh;
  fem::Boundary boundary;
  modal::EigenSolverKind solver;
  int dof;
  double hub_radius;
  double axial_force;
  int bending_count;
  std::vector<CampbellPoint> points;
  double solve_seconds;
};

CampbellResult campbell_diagram(const fem::BeamModel& model, const SpinRange& range, double hub_radius,
                                double axial_force, int bending_count, modal::EigenSolverKind solver,
                                const std::function<void(int)>& progress);

}  // namespace ffrf::study
