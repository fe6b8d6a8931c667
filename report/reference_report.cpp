// The converged reference in the reports (see reference_report.hpp).
#include "report/reference_report.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

namespace ffrf::report {

std::string reference_label(const study::ConvergedReference& r) {
  return fmt::format("reference ({}, rtol {:g})", r.choice.label(), r.settings.relative_tolerance);
}

std::string reference_verdict(const study::ConvergedReference& r) {
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

std::string reference_levels_markdown(const study::ConvergedReference& r) {
  std::string t = "| level | elements N | CVODE rtol | change vs previous level | steps | RHS evaluations | wall time [s] |\n"
                  "|--:|--:|--:|--:|--:|--:|--:|\n";
  for (std::size_t i = 0; i < r.levels.size(); ++i) {
    const study::ReferenceLevel& l = r.levels[i];
    t += fmt::format("| {} | {} | {:g} | {} | {} | {} | {:.3g} |\n", i, l.elements, l.relative_tolerance,
                     i == 0 ? std::string("-") : fmt::format("{:.3g}", l.change), l.stats.steps,
                     l.stats.function_evaluations, l.stats.wall_seconds);
  }
  return t;
}

std::string reference_levels_text(const study::ConvergedReference& r) {
  std::string t = fmt::format("{:>5} {:>4} {:>8} {:>10} {:>8} {:>9}\n", "level", "N", "rtol", "change", "steps", "wall [s]");
  for (std::size_t i = 0; i < r.levels.size(); ++i) {
    const study::ReferenceLevel& l = r.levels[i];
    t += fmt::format("{:>5} {:>4} {:>8.0e} {:>10} {:>8} {:>9.3g}\n", i, l.elements, l.relative_tolerance,
                     i == 0 ? std::string("-") : fmt::format("{:.3g}", l.change), l.stats.steps, l.stats.wall_seconds);
  }
  t += fmt::format("{} (bound {:g})\n", r.converged ? "converged" : "NOT converged", r.bound);
  return t;
}

Json reference_json(const study::ConvergedReference& r) {
  Json json;
  json["model"] = r.choice.label();
  json["relative_tolerance"] = r.settings.relative_tolerance;
  json["converged"] = r.converged;
  json["bound"] = r.bound;
  json["window_start_s"] = r.window_start;
  json["levels"] = Json::array();
  for (const study::ReferenceLevel& l : r.levels) {
    json["levels"].push_back(Json{{"elements", l.elements},
                                  {"relative_tolerance", l.relative_tolerance},
                                  {"change", l.change},
                                  {"steps", l.stats.steps},
                                  {"wall_s", l.stats.wall_seconds}});
  }
  return json;
}

}  // namespace ffrf::report
