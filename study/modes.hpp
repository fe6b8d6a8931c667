// The computation behind `ffrf modes`: assemble the beam on the free DOFs of a boundary
// condition, solve K φ = ω² M φ for the lowest modes, classify them against the analytic
// Euler–Bernoulli values, and the mesh-convergence study of the bending frequencies.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "fem/boundary.hpp"
#include "fem/mesh.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/mode_kind.hpp"
#include "study/supported_boom.hpp"

namespace ffrf::study {

struct ModesResult {
  fem::BeamMesh mesh;
  fem::Boundary boundary;
  modal::EigenSolverKind solver;
  fem::DofMap dofs;
  double shift;  // σ [rad²/s²]
  modal::EigenPairs pairs;
  std::vector<modal::ClassifiedMode> modes;
  double assembly_seconds;
  double solve_seconds;
  std::vector<std::string> warnings;  // results to distrust, in words
  // A pinned boom's modes as the crane supports it (add_supported_boom); empty for a clamped boom.
  std::optional<SupportedBoomModes> supported;
};

// Shift for the shift-invert solvers (modal::rigid_mode_shift).
double modes_shift(const fem::BeamMesh& mesh, fem::Boundary boundary);

// Distance r [m] from the spin axis to the boom root on the beam axis, for `--spin` and
// `--spin-range` (the centrifugal force N(x)/Ω² = ρA [r (L − x) + (L² − x²)/2]): hub.radius of a hub
// scene, the same r the time-domain model uses for a hull crane (scene::centrifugal_hub_radius), 0
// for a single beam. Everything downstream takes the hub radius as a parameter.
double spin_hub_radius(const scene::Scene& scene);

// Free DOFs of the mesh under the boundary condition.
int free_dof_count(const fem::BeamMesh& mesh, fem::Boundary boundary);

// What `ffrf modes` and `ffrf.modes` are asked for; an unset field is the scene's (boom.elements,
// boom.boundary) or the default: default_elastic_modes elastic modes (and the rigid modes of a
// free–free beam), at most the free DOFs less one, by ARPACK.
inline constexpr int default_elastic_modes = 6;
struct ModesRequest {
  std::optional<int> elements;
  std::optional<int> count;
  std::string boundary;           // fem::boundary_choices(); empty: the scene's
  std::string solver = "arpack";  // modal::eigen_solver_choices()
};
// The mesh, boundary, solver and mode count of a request on a scene. Throws SettingError (elements,
// boundary, eigen_solver, modes) naming the value and the valid range or choices.
struct ModesSetup {
  fem::BeamMesh mesh{};
  fem::Boundary boundary = fem::Boundary::clamped_free;
  modal::EigenSolverKind solver = modal::EigenSolverKind::arpack;
  int count = 0;
};
ModesSetup modes_setup(const scene::Scene& scene, const ModesRequest& request);

// For a pinned scene: the supported boom's lowest `count` modes on the result's mesh into
// result.supported (study/supported_boom.hpp); when its static equilibrium or eigenproblem fails,
// a warning that says why instead. Nothing for a clamped boom.
void add_supported_boom(const scene::Scene& scene, int count, ModesResult& result);

// The lowest `count` modes (1 <= count < free DOFs); throws modal::EigenSolverError on failure.
ModesResult solve_modes(const fem::BeamMesh& mesh, fem::Boundary boundary, modal::EigenSolverKind solver, int count);

// Relative error |f_FE − f_analytic| / f_analytic of the first four bending modes at one mesh.
struct ConvergencePoint {
  int elements;
  int dof;
  std::array<std::optional<double>, 4> bending_error;
  double solve_seconds;
};

// N = 2, 4, ..., 128 with the given solver; `progress(N)` is called before each solve.
std::vector<ConvergencePoint> frequency_convergence(const fem::BeamMesh& mesh, fem::Boundary boundary,
                                                    modal::EigenSolverKind solver,
                                                    const std::function<void(int)>& progress);

}  // namespace ffrf::study
