// Section 6 of `ffrf stability`: the buckling margin of the boom (scenes with gravity and a cargo).
// The boom's root compression P from the static equilibrium (self-weight and the hanging cargo)
// against the Euler load of the clamped–free column P_E = π²EI/(4L²), and the compression
// softening of the first bending mode: ω1 of the beam prestressed by a uniform axial force equal
// to the root value (K + P K_g, conservative: the compression is largest at the root) next to ω1
// without prestress and the power series of the prestressed beam (app/campbell_analysis.hpp).
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "app/campbell_analysis.hpp"
#include "app/crane_run.hpp"
#include "app/stability_section.hpp"

namespace ffrf::app {

StabilitySection buckling_section(const cases::Scene& scene, const StabilityOptions& options, const StagedDirectory&) {
  const int elements = scene.boom.mesh.element_count;
  const cases::BoomChoice choice{cases::BoomKind::nodal, elements};
  stability_progress(options, fmt::format("buckling margin: static equilibrium of {}", choice.label()));
  const auto equations = cases::build_crane(scene, choice);
  const coupling::StaticEquilibrium statics = coupling::solve_static_equilibrium(*equations, equations->initial_guess());
  const double axial = statics.outputs.root_axial_force;  // tension > 0
  const fem::BeamMesh& mesh = scene.boom.mesh;
  const coupling::MonitorLimits limits = monitor_limits(scene);
  const double euler = limits.buckling_load;
  const double ratio = std::max(0.0, -axial) / euler;
  const double warning = limits.buckling_warning_ratio;

  StabilitySection section;
  section.key = "buckling";
  section.title = "Buckling margin and compression softening";
  section.provenance = fmt::format(
      "Static equilibrium of {} (KINSOL) in calm water; the root axial force from the clamp reaction; Euler load of the "
      "clamped–free column π²EI/(4L²) with EI = {} N m², L = {} m; the first bending frequency of the {}-element beam "
      "with a uniform axial force equal to the root force (ARPACK shift-invert) and the power series of the same "
      "prestressed beam.",
      choice.label(), shown(mesh.section.bending_rigidity()), shown(mesh.length), elements);
  StabilityCell margin{"boom root", "compression / Euler load", ratio < warning,
                       ratio < warning ? "ok" : std::string(coupling::to_string(coupling::FailureKind::buckling)), NAN,
                       ratio, "", fmt::format("root axial force {} N (tension > 0), Euler load {} N, warning from {}",
                                              shown(axial, 6), shown(euler, 6), warning),
                       {{"root_axial_force_N", axial}, {"euler_load_N", euler}}};
  double plain = NAN, prestressed = NAN, series = NAN;
  try {
    const SpinModesResult modes = solve_spin_modes(*cases::boom_beam(scene, elements), 0.0, 0.0, axial, 3,
                                                   modal::EigenSolverKind::arpack);
    for (const SpinModeRow& row : modes.rows) {
      if (row.kind != fem::ModeKind::bending || row.order != 1) continue;
      prestressed = row.stiffened_omega2 > 0.0 ? std::sqrt(row.stiffened_omega2) : 0.0;
      if (row.plain_omega2) plain = std::sqrt(*row.plain_omega2);
      if (row.reference_omega2) series = std::sqrt(*row.reference_omega2);
    }
  } catch (const std::exception& error) {
    margin.detail += fmt::format("; prestressed modes not computed: {}", error.what());
  }
  const double drop = 1.0 - prestressed / plain;
  StabilityCell softening{"first bending frequency", "with the root compression", std::isfinite(prestressed) && prestressed > 0.0,
                          prestressed > 0.0 ? "ok" : std::string(coupling::to_string(coupling::FailureKind::buckling)), NAN,
                          prestressed, "rad/s",
                          fmt::format("without prestress {} rad/s, power series {} rad/s: {} % lower", shown(plain),
                                      shown(series), shown(100.0 * drop, 3)),
                          {{"unstressed_rad_per_s", plain}, {"series_rad_per_s", series}}};
  section.table = markdown_table(
      {"quantity", "value", "status"},
      {{"root axial force [N]", shown(axial, 5), axial < 0.0 ? "compression" : "tension"},
       {"Euler load π²EI/(4L²) [N]", shown(euler, 5), ""},
       {"compression / Euler load", shown(ratio, 3), cell_markdown(margin)},
       {"ω1 without prestress [rad/s]", shown(plain, 5), ""},
       {"ω1 with the root compression [rad/s]", shown(prestressed, 5), cell_markdown(softening)},
       {"ω1 power series, prestressed [rad/s]", shown(series, 5), ""}});
  section.cells = {margin, softening};
  section.numbers = {{"root_axial_force_N", axial}, {"euler_load_N", euler}, {"load_ratio", ratio},
                     {"omega1_unstressed_rad_per_s", plain}, {"omega1_prestressed_rad_per_s", prestressed}};
  section.finding = fmt::format(
      "The boom carries {} × its Euler load at the root. Compression adds −|P|K_g to the bending stiffness: to first "
      "order ω1²(P) ≈ ω1²(1 − |P|/P_E), so ω1 falls by {} % ({} → {} rad/s; series {} rad/s). The margin is {}; the run "
      "monitor reports a buckling detection from {} of the Euler load (run_monitor: max_buckling_load_ratio). Remedy "
      "near the limit: model the static prestress (boom.stiffening = static or both) so the frequencies and the "
      "deflection under load are right, and check the section.",
      shown(ratio, 3), shown(100.0 * drop, 3), shown(plain), shown(prestressed), shown(series),
      ratio < warning ? "ample" : "small", warning);
  return section;
}

}  // namespace ffrf::app
