// Under- and over-modelling warnings of `ffrf run` (see run_warnings.hpp).
#include "app/run_warnings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/recommend_reasoning.hpp"

namespace ffrf::app {
namespace {

// Vibration modes the model keeps (nodal: every FE mode of its mesh; rigid: none).
int retained_modes(const cases::BoomChoice& choice) {
  switch (choice.kind) {
    case cases::BoomKind::rigid: return 0;
    case cases::BoomKind::modal: return choice.modes;
    case cases::BoomKind::nodal: return 3 * choice.elements;
  }
  return 0;
}

bool has(cases::Stiffening have, bool static_part) {
  return static_part ? cases::has_static_stiffening(have) : cases::has_centrifugal_stiffening(have);
}

}  // namespace

ModelWarnings model_warnings(const cases::Scene& scene, const cases::BoomChoice& choice, double tolerance) {
  ModelWarnings w;
  w.tolerance = tolerance;
  const RecommendReasoning r = reason_about(scene, tolerance, default_recommend_outputs(scene));
  const int kept = retained_modes(choice);
  const cases::Stiffening stiffening = choice.stiffening.value_or(scene.boom.stiffening);

  if (choice.kind == cases::BoomKind::rigid && r.rigid_error > tolerance) {
    w.below.push_back(fmt::format("rigid boom: it misses the quasi-static tip deflection {:.3g} m under the load "
                                  "(estimated error {:.2g} of the outputs, tolerance {:g}); use --boom modal --static-modes",
                                  r.static_tip_deflection, r.rigid_error, tolerance));
  }
  if (choice.kind == cases::BoomKind::modal && kept < r.dynamic_modes) {
    const BoomMode& missed = r.modes[static_cast<std::size_t>(kept)];
    w.below.push_back(fmt::format("retained-mode cut-off below the excitation band: k = {} but mode {} ({:.4g} rad/s) "
                                  "responds dynamically to the excitation up to {:.4g} rad/s (quasi-static error {:.2g}); "
                                  "keep k >= {}",
                                  kept, kept + 1, missed.angular_frequency, r.excitation_top,
                                  quasi_static_error(r.excitation_top, missed.angular_frequency), r.dynamic_modes));
  }
  if (choice.kind == cases::BoomKind::modal && !choice.static_modes && scene.has_cargo()) {
    const double missing = missing_flexibility(scene, r.modes, kept);
    if (missing > tolerance) {
      w.below.push_back(fmt::format("no static correction modes under the tip load: the {} vibration modes miss {:.2g} of "
                                    "the tip's static flexibility; add --static-modes",
                                    kept, missing));
    }
  }
  if (choice.kind != cases::BoomKind::rigid) {
    if (has(r.required_stiffening, true) && !has(stiffening, true)) {
      w.below.push_back(fmt::format("static stiffening off near buckling: the boom's compression is {:.2g} of its Euler "
                                    "load, changing the outputs by ~{:.2g}; use --stiffening static",
                                    r.axial_load / r.euler_load, r.static_stiffening_effect));
    }
    if (has(r.required_stiffening, false) && !has(stiffening, false)) {
      w.below.push_back(fmt::format("centrifugal stiffening off at high spin: Ω²/ω1² = {:.2g}{}; use --stiffening centrifugal",
                                    r.centrifugal_softening,
                                    r.centrifugal_softening >= 1.0 ? " (the linear boom diverges)" : ""));
    }
  }
  // Far above: many more dynamic modes than the excitation reaches (nodal meshes, large k).
  const int needed = std::max(r.dynamic_modes, 1);
  if (choice.kind != cases::BoomKind::rigid && kept >= 4 * needed + 4) {
    w.above.push_back(fmt::format("{} keeps {} vibration modes where {} respond{} dynamically (excitation up to {:.3g} "
                                  "rad/s, first mode {:.4g} rad/s): `ffrf recommend` finds the cheapest adequate model",
                                  choice.label(), kept, r.dynamic_modes, r.dynamic_modes == 1 ? "s" : "",
                                  r.excitation_top, r.modes.empty() ? 0.0 : r.modes.front().angular_frequency));
  }
  return w;
}

std::string warnings_text(const ModelWarnings& warnings) {
  std::string text;
  for (const std::string& line : warnings.below) text += "ffrf run: warning: modelled below need: " + line + "\n";
  for (const std::string& line : warnings.above) text += "ffrf run: note: modelled above need: " + line + "\n";
  return text;
}

void write_warnings_json(JsonWriter& json, const ModelWarnings& warnings) {
  json.begin_object().field("tolerance", warnings.tolerance);
  json.key("below").begin_array();
  for (const std::string& line : warnings.below) json.value(line);
  json.end_array();
  json.key("above").begin_array();
  for (const std::string& line : warnings.above) json.value(line);
  json.end_array().end_object();
}

}  // namespace ffrf::app
