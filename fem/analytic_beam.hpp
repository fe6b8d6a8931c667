// Closed-form natural frequencies of a uniform Euler–Bernoulli beam (the references the FE modes
// are checked against): bending ω = (βL)² √(EI/(ρA L⁴)) with βL the roots of the frequency
// equation of the boundary condition (clamped-free: 1 + cos βL cosh βL = 0; free-free:
// 1 − cos βL cosh βL = 0 plus two rigid modes; pinned-pinned: βL = nπ), and axial
// ω = c √(EA/(ρA)) / L with c = (2n − 1)π/2 (fixed-free) or nπ (free-free). The roots are found
// by bracketing and bisection of the frequency equation, not tabulated.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::fem {

enum class ModeKind { rigid, bending, axial };
std::string_view to_string(ModeKind kind);

struct AnalyticMode {
  ModeKind kind;
  int order;                // 1-based within its kind
  double angular_frequency; // ω [rad/s]
  double beta_l;            // βL (bending), c (axial), 0 (rigid)
};

// The lowest `count` bending modes (ascending βL) of the boundary condition.
std::vector<AnalyticMode> analytic_bending_modes(const BeamMesh& mesh, Boundary boundary, int count);
// The lowest `count` axial modes of the boundary condition.
std::vector<AnalyticMode> analytic_axial_modes(const BeamMesh& mesh, Boundary boundary, int count);
// Euler buckling load of the uniform column [N]: π²EI/(4L²) clamped–free, π²EI/L² pinned–pinned;
// none for free–free.
std::optional<double> euler_buckling_load(const BeamMesh& mesh, Boundary boundary);
// Number of zero-frequency rigid-body modes in the plane (3 for free-free, 0 otherwise).
int rigid_mode_count(Boundary boundary);

}  // namespace ffrf::fem
