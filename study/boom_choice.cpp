// The boom model of a run from the scene's default and a request (see boom_choice.hpp).
#include "study/boom_choice.hpp"

#include <fmt/format.h>

#include "fem/mesh.hpp"
#include "study/run_pipeline.hpp"
#include "study/work_limits.hpp"

namespace ffrf::study {

scene::BoomChoice default_boom_choice(const scene::Scene& scene) {
  scene::BoomChoice choice;
  choice.kind = scene::BoomKind::nodal;
  choice.elements = scene.boom.mesh.element_count;
  choice.modes = default_modal_modes;
  choice.static_modes = true;
  return choice;
}

std::optional<scene::Stiffening> stiffening_setting(const std::string& name) {
  if (name.empty()) return std::nullopt;
  const auto stiffening = scene::parse_stiffening(name);
  if (!stiffening) throw SettingError(Setting::stiffening, name, "unknown stiffening; choose one of none, static, centrifugal, both");
  return stiffening;
}

scene::BoomChoice boom_choice(const BoomRequest& request, scene::BoomChoice choice) {
  if (!request.kind.empty()) {
    const auto kind = scene::parse_boom_kind(request.kind);
    if (!kind)
      throw SettingError(Setting::boom_model, request.kind,
                         fmt::format("unknown boom model; choose one of {}", scene::boom_kind_choices()));
    choice.kind = *kind;
  }
  choice.elements = request.elements.value_or(choice.elements);
  if (choice.elements < 1)
    throw SettingError(Setting::elements, std::to_string(choice.elements), "not a valid element count (valid range [1, inf))");
  choice.modes = request.modes.value_or(choice.modes);
  choice.static_modes = request.static_modes.value_or(choice.static_modes);
  if (!request.stiffening.empty()) choice.stiffening = stiffening_setting(request.stiffening);
  if (!request.mode_set.empty()) {
    const auto set = fem::parse_boundary(request.mode_set);
    if (!set) {
      throw SettingError(Setting::mode_set, request.mode_set,
                         fmt::format("unknown mode set; choose one of {}", fem::boundary_choices()));
    }
    if (choice.kind != scene::BoomKind::modal && *set != fem::Boundary::clamped_free) {
      throw SettingError(Setting::mode_set, request.mode_set, "a mode set belongs to a modal boom (--boom modal)");
    }
    choice.mode_set = *set;
  }
  if (!request.stress_recovery.empty()) {
    const auto method = multibody::parse_stress_recovery(request.stress_recovery);
    if (!method) {
      throw SettingError(Setting::stress_recovery, request.stress_recovery,
                         fmt::format("unknown stress recovery; choose one of {} (mode displacement or mode acceleration)",
                                     multibody::stress_recovery_choices()));
    }
    if (choice.kind != scene::BoomKind::modal) {
      throw SettingError(Setting::stress_recovery, request.stress_recovery,
                         "a stress recovery is a modal boom's choice (--boom modal): a nodal boom's stresses are its own "
                         "displacements', a rigid boom's the quasi-static ones");
    }
    choice.stress_recovery = *method;
  }
  if (choice.kind == scene::BoomKind::modal) {
    const int dof = fem::clamped_free_dof_count(choice.elements);
    if (choice.modes < 1 || choice.modes >= dof) {
      throw SettingError(Setting::modes, std::to_string(choice.modes),
                         fmt::format("not a valid mode count for N = {} elements ({} elastic DOFs) (valid range [1, {}])",
                                     choice.elements, dof, dof - 1));
    }
  }
  check_run_memory(choice);
  return choice;
}

}  // namespace ffrf::study
