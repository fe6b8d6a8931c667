// The radiation models compared against the Cummins convolution (see the header).
#include "study/radiation_compare.hpp"

#include <cmath>
#include <numbers>
#include <fmt/format.h>

#include "scene/bem_hull_model.hpp"
#include "scene/scene_loader.hpp"
#include "study/error_measure.hpp"

namespace ffrf::study {

std::string radiation_label(const scene::Scene& scene) {
  if (!scene.bem) return "constant (scene [radiation])";
  const scene::BemHull& bem = *scene.bem;
  const auto model = scene::bem_radiation_model(scene);
  switch (bem.radiation_model) {
    case hydro::RadiationKind::constant:
      return fmt::format("constant A, B at T = {:.3g} s", 2.0 * std::numbers::pi / scene::constant_radiation_frequency(scene));
    case hydro::RadiationKind::state_space:
      return fmt::format("state-space r = {} (e_r {:.2g} %)", model->order, 100.0 * model->fit_error);
    case hydro::RadiationKind::convolution:
      return fmt::format("convolution T_c = {:.3g} s ({} samples)", model->kernel.truncation_time, model->kernel.kernel.size());
  }
  return "?";
}

RadiationComparison compare_radiation(const scene::Scene& scene, const scene::BoomChoice& choice,
                                      const multibody::RunSettings& settings, double tolerance) {
  judge({}, 0.0, 0.0, tolerance);  // the tolerance is valid before anything runs
  RadiationComparison c;
  c.choice = choice;
  const scene::Scene reference_scene = with_radiation(scene, hydro::RadiationKind::convolution);
  c.reference_label = radiation_label(reference_scene);
  c.reference = run_model(reference_scene, choice, settings);
  c.window_start = error_window(scene, settings.duration);
  const auto judged = judged_outputs(scene);
  std::vector<MeasuredModel> measured;
  for (const hydro::RadiationKind kind : {hydro::RadiationKind::constant, hydro::RadiationKind::state_space}) {
    const scene::Scene modelled = with_radiation(scene, kind);
    c.kinds.push_back(kind);
    c.labels.push_back(radiation_label(modelled));
    c.runs.push_back(run_model(modelled, choice, settings));
    c.worst.push_back(worst_error(multibody::compare_runs(c.runs.back().result, c.reference.result, c.window_start), judged));
    MeasuredModel m;
    m.label = c.labels.back();
    m.error = c.worst.back().error;
    m.worst_output = std::string(multibody::channel_name(c.worst.back().channel));
    m.wall_seconds = c.runs.back().result.stats.wall_seconds;
    // The radiation model changes the cost of a right-hand side, not the state size: its cost is
    // the integration's wall time.
    m.work = m.wall_seconds;
    measured.push_back(std::move(m));
  }
  const double reference_wall = c.reference.result.stats.wall_seconds;
  c.verdict = judge(measured, reference_wall, reference_wall, tolerance);
  return c;
}

std::string radiation_comparison_text(const RadiationComparison& c) {
  std::string text = fmt::format("\nradiation models ({} boom, reference: {}; errors for t >= {:g} s)\n", c.choice.label(),
                                 c.reference_label, c.window_start);
  text += fmt::format("  {:<38} {:>10} {:>16} {:>9} {:>8} {:>8}  {}\n", "model", "error", "worst output", "wall [s]",
                      "steps", "speed-up", "verdict");
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    const ModelVerdict& v = c.verdict.models[m];
    text += fmt::format("  {:<38} {:>9.3g}% {:>16} {:>9.3f} {:>8} {:>7.2f}x  {}\n", c.labels[m], 100.0 * c.worst[m].error,
                        multibody::channel_name(c.worst[m].channel), c.runs[m].result.stats.wall_seconds,
                        c.runs[m].result.stats.steps, v.wall_speedup, v.passed ? "pass" : "FAIL");
  }
  text += fmt::format("  {:<38} {:>10} {:>16} {:>9.3f} {:>8} {:>8}  {}\n", c.reference_label, "reference", "-",
                      c.reference.result.stats.wall_seconds, c.reference.result.stats.steps, "1.00x", "-");
  if (c.verdict.cheapest) {
    text += fmt::format("  verdict at {:g} %: {} is the cheapest radiation model within the tolerance\n",
                        100.0 * c.verdict.tolerance, c.labels[*c.verdict.cheapest]);
  } else {
    text += fmt::format("  verdict at {:g} %: no cheaper radiation model is within the tolerance: keep the convolution\n",
                        100.0 * c.verdict.tolerance);
  }
  return text;
}

}  // namespace ffrf::study
