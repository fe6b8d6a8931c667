// The converged reference for the crane commands (see crane_reference.hpp).
#include "app/crane_reference.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ffrf::app {

void add_reference_options(CLI::App& sub, ReferenceOptions& options) {
  sub.add_option("--reference-elements", options.start_elements, "Reference: elements of the first level")
      ->capture_default_str();
  sub.add_option("--reference-rtol", options.start_rtol, "Reference: CVODE relative tolerance of the first level")
      ->capture_default_str();
  sub.add_option("--reference-bound", options.bound,
                 "Reference: converged when the worst normalized RMS change between two levels is below this")
      ->capture_default_str();
  sub.add_option("--reference-levels", options.max_levels,
                 "Reference: at most this many levels (each doubles the elements and tightens rtol 10x)")
      ->capture_default_str();
}

std::optional<std::string> reference_options_error(const ReferenceOptions& o) {
  if (o.start_elements < 1) {
    return fmt::format("--reference-elements {}: not a valid element count (valid range [1, inf))", o.start_elements);
  }
  if (!(o.start_rtol > 0.0 && o.start_rtol < 1.0)) {
    return fmt::format("--reference-rtol {}: not a valid tolerance (valid range (0, 1))", o.start_rtol);
  }
  if (!(o.bound > 0.0 && std::isfinite(o.bound))) {
    return fmt::format("--reference-bound {}: not a valid bound (valid range (0, inf))", o.bound);
  }
  if (o.max_levels < 1 || o.max_levels > 6) {
    return fmt::format("--reference-levels {}: not a valid level count (valid range [1, 6])", o.max_levels);
  }
  return std::nullopt;
}

double error_window(const cases::Scene& scene, double duration) {
  const double ramp = cases::ramp_end(scene);
  return duration > ramp + 1e-9 ? ramp : 0.0;
}

cases::ConvergedReference compute_reference(const cases::Scene& scene, const ReferenceOptions& options, double duration) {
  cases::ReferenceRequest request;
  request.start_elements = options.start_elements;
  request.start_relative_tolerance = options.start_rtol;
  request.bound = options.bound;
  request.max_levels = error_window(scene, duration) > 0.0 || cases::ramp_end(scene) == 0.0 ? options.max_levels : 1;
  request.duration = duration;
  return cases::converged_reference(scene, request);
}

std::string reference_label(const cases::ConvergedReference& r) {
  return fmt::format("reference ({}, rtol {:g})", r.choice.label(), r.settings.relative_tolerance);
}

ModelRun reference_model_run(const cases::Scene& scene, const cases::ConvergedReference& r) {
  ModelRun run;
  run.choice = r.choice;
  run.elastic_dof = 3 * r.choice.elements;
  run.result = r.run;
  run.statics.outputs = r.run.samples.front();  // the run starts at rest in static equilibrium
  summarize_run(scene, r.settings.duration, run);
  return run;
}

std::string reference_verdict(const cases::ConvergedReference& r) {
  if (r.levels.size() < 2) {
    return "**Not checked for convergence**: only one level was run (the run ends within the wave ramp, or "
           "--reference-levels 1), so the reference is merely the finest model here.";
  }
  const double change = r.levels.back().change;
  if (r.converged) {
    return fmt::format("**Converged**: the last refinement changed the outputs by {:.3g} (worst normalized RMS over the "
                       "channels), below the bound {:g}; errors smaller than about {:.1g} cannot be resolved against it.",
                       change, r.bound, change);
  }
  return fmt::format("**Not converged**: after {} levels the last refinement still changed the outputs by {:.3g}, above "
                     "the bound {:g}; errors below about {:.1g} are not meaningful (raise --reference-levels).",
                     r.levels.size(), change, r.bound, change);
}

std::string reference_levels_markdown(const cases::ConvergedReference& r) {
  std::string t = "| level | elements N | CVODE rtol | change vs previous level | steps | RHS evaluations | wall time [s] |\n"
                  "|--:|--:|--:|--:|--:|--:|--:|\n";
  for (std::size_t i = 0; i < r.levels.size(); ++i) {
    const cases::ReferenceLevel& l = r.levels[i];
    t += fmt::format("| {} | {} | {:g} | {} | {} | {} | {:.3g} |\n", i, l.elements, l.relative_tolerance,
                     i == 0 ? std::string("-") : fmt::format("{:.3g}", l.change), l.stats.steps,
                     l.stats.function_evaluations, l.stats.wall_seconds);
  }
  return t;
}

std::string reference_levels_text(const cases::ConvergedReference& r) {
  std::string t = fmt::format("{:>5} {:>4} {:>8} {:>10} {:>8} {:>9}\n", "level", "N", "rtol", "change", "steps", "wall [s]");
  for (std::size_t i = 0; i < r.levels.size(); ++i) {
    const cases::ReferenceLevel& l = r.levels[i];
    t += fmt::format("{:>5} {:>4} {:>8.0e} {:>10} {:>8} {:>9.3g}\n", i, l.elements, l.relative_tolerance,
                     i == 0 ? std::string("-") : fmt::format("{:.3g}", l.change), l.stats.steps, l.stats.wall_seconds);
  }
  t += fmt::format("{} (bound {:g})\n", r.converged ? "converged" : "NOT converged", r.bound);
  return t;
}

void write_reference_json(JsonWriter& json, const cases::ConvergedReference& r) {
  json.field("model", r.choice.label());
  json.field("relative_tolerance", r.settings.relative_tolerance);
  json.field("converged", r.converged).field("bound", r.bound).field("window_start_s", r.window_start);
  json.key("levels").begin_array();
  for (const cases::ReferenceLevel& l : r.levels) {
    json.begin_object();
    json.field("elements", l.elements).field("relative_tolerance", l.relative_tolerance).field("change", l.change);
    json.field("steps", static_cast<double>(l.stats.steps)).field("wall_s", l.stats.wall_seconds);
    json.end_object();
  }
  json.end_array();
}

}  // namespace ffrf::app
