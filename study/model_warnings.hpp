// Warnings of `ffrf run` (issue 6): a model below what its scene needs — retained modes cut off
// below the excitation band, no static correction modes under a tip load, a rigid boom whose
// quasi-static deflection matters, geometric stiffening off near buckling or at high spin — and,
// quietly, a model far above it. Judged by the same physics as `ffrf recommend`
// (app/recommend_reasoning.hpp) at a 1 % tolerance on the default outputs.
#pragma once

#include <string>
#include <vector>

#include "app/json_writer.hpp"
#include "cases/crane_builder.hpp"
#include "cases/scene.hpp"

namespace ffrf::app {

struct ModelWarnings {
  double tolerance = 0.01;
  std::vector<std::string> below;  // the model misses physics the scene excites (printed)
  std::vector<std::string> above;  // the model resolves far more than the scene needs (quiet)
};

ModelWarnings model_warnings(const cases::Scene& scene, const cases::BoomChoice& choice, double tolerance = 0.01);

// "warning: ..." lines for stderr (below) and one "note: ..." line (above).
std::string warnings_text(const ModelWarnings& warnings);
// {"tolerance", "below": [...], "above": [...]} as the value of the current JSON key.
void write_warnings_json(JsonWriter& json, const ModelWarnings& warnings);

}  // namespace ffrf::app
