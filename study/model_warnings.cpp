// Under- and over-modelling warnings of `ffrf run` (see run_warnings.hpp).
#include "study/model_warnings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fem/mesh.hpp"
#include "study/error_measure.hpp"
#include "study/recommend_reasoning.hpp"

namespace ffrf::study {
namespace {

// Vibration modes the model keeps (nodal: every FE mode of its mesh; rigid: none).
int retained_modes(const scene::BoomChoice& choice) {
  switch (choice.kind) {
    case scene::BoomKind::rigid: return 0;
    case scene::BoomKind::modal: return choice.modes;
    case scene::BoomKind::nodal: return fem::clamped_free_dof_count(choice.elements);
  }
  return 0;
}

bool has(scene::Stiffening have, bool static_part) {
  return static_part ? scene::has_static_stiffening(have) : scene::has_centrifugal_stiffening(have);
}

}  // namespace

ModelWarnings model_warnings(const scene::Scene& scene, const scene::BoomChoice& choice, double tolerance) {
  ModelWarnings w;
  w.tolerance = tolerance;
  const RecommendReasoning r = reason_about(scene, tolerance, judged_outputs(scene));
  const int kept = retained_modes(choice);
  const scene::Stiffening stiffening = choice.stiffening.value_or(scene.boom.stiffening);

  if (choice.kind == scene::BoomKind::rigid && r.rigid_error > tolerance) {
    w.below.push_back({fmt::format("rigid boom: it misses the quasi-static tip deflection {:.3g} m under the load "
                                  "(estimated error {:.2g} of the outputs, tolerance {:g})",
                                  r.static_tip_deflection, r.rigid_error, tolerance),
                      Remedy::modal_with_static_modes});
  }
  if (choice.kind == scene::BoomKind::modal && kept < r.dynamic_modes) {
    const BoomMode& missed = r.modes[static_cast<std::size_t>(kept)];
    w.below.push_back({fmt::format("retained-mode cut-off below the excitation band: k = {} but mode {} ({:.4g} rad/s) "
                                  "responds dynamically to the excitation up to {:.4g} rad/s (quasi-static error {:.2g})",
                                  kept, kept + 1, missed.angular_frequency, r.excitation_top,
                                  quasi_static_error(r.excitation_top, missed.angular_frequency)),
                      Remedy::keep_vibration_modes, r.dynamic_modes});
  }
  if (choice.kind == scene::BoomKind::modal && !choice.static_modes && scene.has_cargo()) {
    const double missing = missing_flexibility(scene, r.modes, kept);
    if (missing > tolerance) {
      w.below.push_back({fmt::format("no static correction modes under the tip load: the {} vibration modes miss {:.2g} of "
                                    "the tip's static flexibility",
                                    kept, missing),
                        Remedy::add_static_modes});
    }
  }
  if (choice.kind != scene::BoomKind::rigid) {
    if (has(r.required_stiffening, true) && !has(stiffening, true)) {
      w.below.push_back({fmt::format("static stiffening off near buckling: the boom's compression is {:.2g} of its Euler "
                                    "load, changing the outputs by ~{:.2g}",
                                    r.axial_load / r.euler_load, r.static_stiffening_effect),
                        Remedy::static_stiffening});
    }
    if (has(r.required_stiffening, false) && !has(stiffening, false)) {
      w.below.push_back({fmt::format("centrifugal stiffening off at high spin: Ω²/ω1² = {:.2g}{}", r.centrifugal_softening,
                                     r.centrifugal_softening >= 1.0 ? " (the linear boom diverges)" : ""),
                         Remedy::centrifugal_stiffening});
    }
  }
  // Far above: many more dynamic modes than the excitation reaches (nodal meshes, large k).
  const int needed = std::max(r.dynamic_modes, 1);
  if (choice.kind != scene::BoomKind::rigid && kept >= 4 * needed + 4) {
    w.above.push_back({fmt::format("{} keeps {} vibration modes where {} respond{} dynamically (excitation up to {:.3g} "
                                  "rad/s, first mode {:.4g} rad/s)",
                                  choice.label(), kept, r.dynamic_modes, r.dynamic_modes == 1 ? "s" : "",
                                  r.excitation_top, r.modes.empty() ? 0.0 : r.modes.front().angular_frequency),
                      Remedy::cheaper_model});
  }
  return w;
}

}  // namespace ffrf::study
