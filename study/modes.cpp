// Assembly, eigen solve, classification and the convergence study for `ffrf modes`.
#include "study/modes.hpp"

#include "scene/crane_builder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>

#include "fem/analytic_beam.hpp"
#include "fem/assembly.hpp"
#include "modal/mode_cache.hpp"
#include "study/run_pipeline.hpp"
#include "study/wall_clock.hpp"

namespace ffrf::study {

double modes_shift(const fem::BeamMesh& mesh, fem::Boundary boundary) { return modal::rigid_mode_shift(mesh, boundary); }

double spin_hub_radius(const scene::Scene& scene) { return scene::centrifugal_hub_radius(scene); }

int free_dof_count(const fem::BeamMesh& mesh, fem::Boundary boundary) {
  return fem::make_dof_map(mesh, boundary).free_count();
}

ModesSetup modes_setup(const scene::Scene& scene, const ModesRequest& request) {
  ModesSetup setup{scene.boom.mesh, scene.boom.boundary, modal::EigenSolverKind::arpack, 0};
  if (request.elements) {
    if (*request.elements < 1) {
      throw SettingError(Setting::elements, std::to_string(*request.elements), "not a valid element count (valid range [1, inf))");
    }
    setup.mesh.element_count = *request.elements;
  }
  if (!request.boundary.empty()) {
    const auto parsed = fem::parse_boundary(request.boundary);
    if (!parsed) {
      throw SettingError(Setting::boundary, request.boundary,
                         "unknown boundary condition; choose one of " + fem::boundary_choices());
    }
    setup.boundary = *parsed;
  }
  const auto solver = modal::parse_eigen_solver(request.solver);
  if (!solver) throw SettingError(Setting::eigen_solver, request.solver, "unknown solver; choose one of " + modal::eigen_solver_choices());
  setup.solver = *solver;
  const int dof = free_dof_count(setup.mesh, setup.boundary);
  setup.count = request.count.value_or(std::min(dof - 1, default_elastic_modes + fem::rigid_mode_count(setup.boundary)));
  if (setup.count < 1 || setup.count >= dof) {
    throw SettingError(Setting::modes, std::to_string(setup.count),
                       fmt::format("not a mode count of the {} free DOFs of N = {} {} (valid range [1, {}])", dof,
                                   setup.mesh.element_count, fem::to_string(setup.boundary), dof - 1));
  }
  return setup;
}

void add_supported_boom(const scene::Scene& scene, int count, ModesResult& result) {
  try {
    result.supported = supported_boom_modes(scene, result.mesh.element_count, count);
  } catch (const std::exception& error) {
    result.warnings.push_back(fmt::format("the supported boom's modes were not computed: {}", error.what()));
  }
}

ModesResult solve_modes(const fem::BeamMesh& mesh, fem::Boundary boundary, modal::EigenSolverKind solver, int count) {
  fem::validate(mesh);
  const auto assembly_start = std::chrono::steady_clock::now();
  fem::FreeMatrices matrices = fem::assemble_free(mesh, boundary);
  const double assembly_seconds = seconds_since(assembly_start);

  modal::EigenRequest request;
  request.nev = count;
  request.sigma = modes_shift(mesh, boundary);
  const auto solve_start = std::chrono::steady_clock::now();
  modal::EigenPairs pairs = modal::solve_generalized(matrices.stiffness, matrices.mass, request, solver);
  const double solve_seconds = seconds_since(solve_start);

  auto modes = modal::classify_modes(mesh, boundary, matrices.dofs, matrices.mass, pairs.eigenvalues, pairs.eigenvectors);
  std::vector<std::string> warnings;
  const auto rigid_found = std::count_if(modes.begin(), modes.end(),
                                         [](const modal::ClassifiedMode& m) { return m.kind == fem::ModeKind::rigid; });
  const int rigid_expected = std::min(count, fem::rigid_mode_count(boundary));
  if (rigid_found != rigid_expected) {
    warnings.push_back(fmt::format(
        "expected {} rigid-body modes, found {}: the lowest eigenvalues are spoiled by rounding (K is too "
        "ill-conditioned at N = {} for double precision); these frequencies are not reliable; use fewer elements",
        rigid_expected, rigid_found, mesh.element_count));
  }
  return {mesh,          boundary, solver, std::move(matrices.dofs), request.sigma, std::move(pairs), std::move(modes),
          assembly_seconds, solve_seconds, std::move(warnings), std::nullopt};
}

std::vector<ConvergencePoint> frequency_convergence(const fem::BeamMesh& mesh, fem::Boundary boundary,
                                                    modal::EigenSolverKind solver,
                                                    const std::function<void(int)>& progress) {
  std::vector<ConvergencePoint> points;
  for (int elements = 2; elements <= 128; elements *= 2) {
    if (progress) progress(elements);
    fem::BeamMesh refined = mesh;
    refined.element_count = elements;
    const int dof = free_dof_count(refined, boundary);
    // Enough modes for four bending modes among rigid and axial ones.
    const int count = std::min(dof - 1, fem::rigid_mode_count(boundary) + 12);
    const ModesResult result = solve_modes(refined, boundary, solver, count);
    ConvergencePoint point{elements, dof, {}, result.solve_seconds};
    for (const modal::ClassifiedMode& mode : result.modes) {
      if (mode.kind != fem::ModeKind::bending || mode.order > 4 || !mode.analytic_frequency) continue;
      point.bending_error[static_cast<std::size_t>(mode.order - 1)] =
          std::abs(mode.angular_frequency - *mode.analytic_frequency) / *mode.analytic_frequency;
    }
    points.push_back(point);
  }
  return points;
}

}  // namespace ffrf::study
