// Experiment 6 of the stability map: the buckling margin of the boom (scenes with gravity and a
// cargo). The boom's root compression P from the static equilibrium (self-weight and the hanging
// cargo) against the Euler load of the clamped–free column P_E = π²EI/(4L²), and the compression
// softening of the first bending mode: ω1 of the beam prestressed by a uniform axial force equal
// to the root value (K + P K_g, conservative: the compression is largest at the root) next to ω1
// without prestress and the power series of the prestressed beam (study/campbell.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "study/stability.hpp"

namespace ffrf::study {

BucklingStudy buckling_study(const scene::Scene& scene, const StabilityOptions& options) {
  BucklingStudy study;
  const int elements = scene.boom.mesh.element_count;
  study.choice = {scene::BoomKind::nodal, elements};
  if (options.progress) options.progress(fmt::format("buckling margin: static equilibrium of {}", study.choice.label()));
  const PreparedRun prepared = prepare_run(scene, study.choice);
  study.axial_force = prepared.statics.outputs.root_axial_force;  // tension > 0
  const multibody::MonitorLimits limits = monitor_limits(scene);
  study.euler_load = limits.buckling_load;
  study.load_ratio = std::max(0.0, -study.axial_force) / study.euler_load;
  study.warning_ratio = limits.buckling_warning_ratio;
  try {
    const SpinModesResult modes = solve_spin_modes(*scene::boom_beam(scene, elements), 0.0, 0.0, study.axial_force, 3,
                                                   modal::EigenSolverKind::arpack);
    for (const SpinModeRow& row : modes.rows) {
      if (row.kind != fem::ModeKind::bending || row.order != 1) continue;
      study.omega1_prestressed = row.stiffened_omega2 > 0.0 ? std::sqrt(row.stiffened_omega2) : 0.0;
      if (row.plain_omega2) study.omega1_unstressed = std::sqrt(*row.plain_omega2);
      if (row.reference_omega2) study.omega1_series = std::sqrt(*row.reference_omega2);
    }
  } catch (const std::exception& error) {
    study.modes_failure = error.what();
  }
  return study;
}

}  // namespace ffrf::study
