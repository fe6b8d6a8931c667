// Spinning / prestressed modes and the Campbell diagram for `ffrf modes` (see header).
#include "study/campbell.hpp"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <stdexcept>

#include "fem/analytic_rotating_beam.hpp"
#include "modal/rotating_beam_modes.hpp"
#include "study/wall_clock.hpp"

namespace ffrf::study {
namespace {

// Power-series ω² of the lowest `count` bending modes, or nothing where no reference exists
// (boundary other than clamped-free, or buckled).
std::vector<std::optional<double>> reference_omega2(const fem::BeamMesh& mesh, fem::Boundary boundary, double spin,
                                                    double hub_radius, double axial_force, int count) {
  std::vector<std::optional<double>> out(static_cast<std::size_t>(count));
  if (boundary != fem::Boundary::clamped_free || count < 1) return out;
  const auto problem = fem::rotating_beam_problem(mesh, spin, hub_radius, axial_force, true);
  if (problem.axial_force_parameter <= -std::numbers::pi * std::numbers::pi / 4.0) return out;
  const double scale = fem::rotating_beam_frequency_scale(mesh);
  const auto mu = fem::rotating_beam_eigenvalues(problem, count);
  for (int i = 0; i < count; ++i) out[static_cast<std::size_t>(i)] = mu[static_cast<std::size_t>(i)] * scale * scale;
  return out;
}

// ω² of the lowest `count` bending modes: asks for more eigenpairs until that many bending modes
// are among them (axial modes may lie between).
std::vector<double> lowest_bending(const fem::BeamModel& model, const modal::RotatingBeamState& state, int count,
                                   modal::EigenSolverKind solver) {
  const int available = model.dofs.free_count() - 1;
  for (int nev = std::min(available, count + 2);; nev = std::min(available, 2 * nev)) {
    const auto result = modal::rotating_beam_modes(model, state, nev, solver);
    std::vector<double> bending;
    for (const auto& mode : result.modes) {
      if (mode.kind == fem::ModeKind::bending && static_cast<int>(bending.size()) < count) bending.push_back(mode.omega_squared);
    }
    if (static_cast<int>(bending.size()) == count) return bending;
    if (nev == available) {
      throw std::invalid_argument(fmt::format("only {} bending modes among the {} modes of N = {}; ask for fewer modes or "
                                              "refine the mesh", bending.size(), available, model.mesh.element_count));
    }
  }
}

}  // namespace

SpinModesResult solve_spin_modes(const fem::BeamModel& model, double spin_rate, double hub_radius, double axial_force,
                                 int count, modal::EigenSolverKind solver) {
  const auto start = std::chrono::steady_clock::now();
  modal::RotatingBeamState stiffened{spin_rate, hub_radius, true, axial_force};
  modal::RotatingBeamState plain{spin_rate, hub_radius, false, 0.0};
  const auto with = modal::rotating_beam_modes(model, stiffened, count, solver);
  const auto without = modal::rotating_beam_modes(model, plain, count, solver);
  int bending_count = 0;
  for (const auto& mode : with.modes) bending_count += mode.kind == fem::ModeKind::bending ? 1 : 0;
  const auto reference = reference_omega2(model.mesh, model.boundary, spin_rate, hub_radius, axial_force, bending_count);

  SpinModesResult out{model.mesh, model.boundary, solver, model.dofs.free_count(), spin_rate, hub_radius, axial_force,
                      fem::euler_buckling_load(model.mesh, model.boundary), with.shift, {}, 0.0, {}};
  for (const auto& mode : with.modes) {
    SpinModeRow row{mode.kind, mode.order, std::nullopt, mode.omega_squared, std::nullopt, mode.axial_energy_share};
    for (const auto& other : without.modes) {
      if (other.kind == mode.kind && other.order == mode.order) row.plain_omega2 = other.omega_squared;
    }
    if (mode.kind == fem::ModeKind::bending) row.reference_omega2 = reference[static_cast<std::size_t>(mode.order - 1)];
    out.rows.push_back(row);
  }
  if (out.buckling_load && axial_force <= -*out.buckling_load) {
    out.warnings.push_back(fmt::format("buckled: the compression |P| = {:.6g} N reaches the buckling load P_cr = {:.6g} N "
                                       "(|P|/P_cr = {:.4g}); the lowest mode diverges", -axial_force, *out.buckling_load,
                                       -axial_force / *out.buckling_load));
  }
  out.solve_seconds = seconds_since(start);
  return out;
}

CampbellResult campbell_diagram(const fem::BeamModel& model, const SpinRange& range, double hub_radius,
                                double axial_force, int bending_count, modal::EigenSolverKind solver,
                                const std::function<void(int)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  CampbellResult out{model.mesh, model.boundary, solver, model.dofs.free_count(), hub_radius, axial_force, bending_count, {}, 0.0};
  for (int i = 0; i < range.count; ++i) {
    if (progress) progress(i);
    const double spin = range.at(i);
    CampbellPoint point{spin, {}, {}, {}};
    point.stiffened_omega2 = lowest_bending(model, {spin, hub_radius, true, axial_force}, bending_count, solver);
    point.plain_omega2 = lowest_bending(model, {spin, hub_radius, false, 0.0}, bending_count, solver);
    point.reference_omega2 = reference_omega2(model.mesh, model.boundary, spin, hub_radius, axial_force, bending_count);
    out.points.push_back(std::move(point));
  }
  out.solve_seconds = seconds_since(start);
  return out;
}

}  // namespace ffrf::study
