// Section 6 of the stability report: the buckling margin and compression softening of the boom
// (study/stability.hpp, experiment 6): the root compression against the Euler load, and ω1 with and
// without the prestress next to the power series.
#include <fmt/format.h>

#include <cmath>

#include "report/stability_section.hpp"

namespace ffrf::report {

StabilitySection buckling_section(const scene::Scene& scene, const study::BucklingStudy& study) {
  const fem::BeamMesh& mesh = scene.boom.mesh;
  const int elements = mesh.element_count;
  const double axial = study.axial_force, euler = study.euler_load, ratio = study.load_ratio;
  const double warning = study.warning_ratio;
  const double plain = study.omega1_unstressed, prestressed = study.omega1_prestressed, series = study.omega1_series;
  const scene::BoomChoice& choice = study.choice;
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
                       ratio < warning ? "ok" : std::string(solve::to_string(solve::FailureKind::buckling)), NAN,
                       ratio, "", fmt::format("root axial force {} N (tension > 0), Euler load {} N, warning from {}",
                                              shown(axial, 6), shown(euler, 6), warning),
                       {{"root_axial_force_N", axial}, {"euler_load_N", euler}}};
  if (!study.modes_failure.empty()) margin.detail += fmt::format("; prestressed modes not computed: {}", study.modes_failure);
  const double drop = 1.0 - prestressed / plain;
  StabilityCell softening{"first bending frequency", "with the root compression", std::isfinite(prestressed) && prestressed > 0.0,
                          prestressed > 0.0 ? "ok" : std::string(solve::to_string(solve::FailureKind::buckling)), NAN,
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

}  // namespace ffrf::report
