// Warnings of `ffrf run`: a model below what its scene needs — retained modes cut off
// below the excitation band, no static correction modes under a tip load, a rigid boom whose
// quasi-static deflection matters, geometric stiffening off near buckling or at high spin — and,
// quietly, a model far above it. Judged by the same physics as `ffrf recommend`
// (study/recommend_reasoning.hpp) at a 1 % tolerance on the judged outputs. Each warning names
// its finding with its numbers and a remedy in model terms; the report words the remedy.
#pragma once

#include <string>
#include <vector>

#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"

namespace ffrf::study {

// What to change in the model.
enum class Remedy {
  modal_with_static_modes,  // replace the rigid boom by a modal one with static correction modes
  keep_vibration_modes,     // keep at least `modes` vibration modes
  add_static_modes,         // add the static correction modes
  static_stiffening,        // model static (prestress) stiffening
  centrifugal_stiffening,   // model centrifugal stiffening
  cheaper_model,            // ask recommend for the cheapest adequate model
};

struct ModelWarning {
  std::string finding;  // what is wrong, with its numbers
  Remedy remedy;
  int modes = 0;        // keep_vibration_modes: how many
};

struct ModelWarnings {
  double tolerance = 0.01;
  std::vector<ModelWarning> below;  // the model misses physics the scene excites
  std::vector<ModelWarning> above;  // the model resolves far more than the scene needs
};

ModelWarnings model_warnings(const scene::Scene& scene, const scene::BoomChoice& choice, double tolerance = 0.01);

}  // namespace ffrf::study
