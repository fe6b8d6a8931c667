// The boom model of a run, decided and checked in one place for every front end (the command line,
// the Python module): the scene's default (nodal on the scene's mesh, boom.elements; for a modal
// boom k = 2 vibration modes with static correction modes, the one docs/validation.md recommends
// under a hanging load) overridden by a request whose unset fields keep it.
#pragma once

#include <optional>
#include <string>

#include "scene/crane_builder.hpp"

namespace ffrf::study {

// k = 2 vibration modes with static correction modes: k = 4 without them still misses the static
// deflection under a hanging load (docs/validation.md).
inline constexpr int default_modal_modes = 2;

struct BoomRequest {
  std::string kind;                  // "rigid" | "nodal" | "modal"; empty: the base's
  std::optional<int> elements;       // N ≥ 1; unset: the base's (the scene's boom.elements)
  std::optional<int> modes;          // k ∈ [1, elastic DOFs − 1] for a modal boom; unset: the base's
  std::optional<bool> static_modes;  // unset: the base's
  std::string stiffening;            // "none" | "static" | "centrifugal" | "both"; empty: the base's
  std::string mode_set;              // "clamped-free" | "free-free" | "pinned-pinned" (modal); empty: the base's
  std::string stress_recovery;       // "displacement" | "acceleration" (modal); empty: the base's
};

// Nodal on the scene's mesh (boom.elements), default_modal_modes with static modes, the scene's
// stiffening.
scene::BoomChoice default_boom_choice(const scene::Scene& scene);

// The geometric stiffening a front end names ("none", "static", "centrifugal", "both"; empty: not
// given); throws SettingError (Setting::stiffening) naming the choices.
std::optional<scene::Stiffening> stiffening_setting(const std::string& name);

// `base` with what the request sets. Throws SettingError (study/run_pipeline.hpp) naming the
// setting (boom model, boom elements, mode count, geometric stiffening), the value and the valid
// range or choices; also when the run would not fit in memory (study/work_limits.hpp).
scene::BoomChoice boom_choice(const BoomRequest& request, scene::BoomChoice base);

}  // namespace ffrf::study
