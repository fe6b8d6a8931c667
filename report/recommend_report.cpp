// Text, Markdown and JSON reports of `ffrf recommend` (see recommend_report.hpp).
#include "report/recommend_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "fem/mesh.hpp"
#include "report/json.hpp"
#include "report/reference_report.hpp"
#include "report/verdict_report.hpp"
#include "study/error_measure.hpp"

namespace ffrf::report {
namespace {

using study::Candidate;
using study::CandidateStatus;
using study::Recommendation;
using study::output_list;

std::string number(double value, const char* format = "{:.3g}") {
  return std::isfinite(value) ? fmt::format(fmt::runtime(format), value) : std::string("-");
}

std::string decision_sentence(const RecommendContext& ctx, const Recommendation& rec) {
  if (!rec.chosen && !rec.reference.converged) {
    // Not a model to recommend: the reference's own levels disagree, so no candidate's error means much.
    const double change = rec.reference.levels.empty() ? 0.0 : rec.reference.levels.back().change;
    return fmt::format("No candidate kept its error on {} within τ = {:g}, and the reference itself did not converge "
                       "(its last refinement changed the outputs by {:.3g}, bound {:.3g}): no model of this scene can be "
                       "verified at this tolerance. The response is too sensitive to small differences (slack wire and "
                       "snap loads, or the cargo turning over its hook: see the runs' detections); try a shorter window, "
                       "a smaller sea state, or judge statistics instead of time histories (ffrf compare).",
                       output_list(rec.outputs), ctx.tolerance, change, rec.reference.bound);
  }
  if (!rec.chosen) {
    return fmt::format("No candidate kept its error on {} within τ = {:g}: model the scene with the reference ({}).",
                       output_list(rec.outputs), ctx.tolerance, rec.reference.choice.label());
  }
  const Candidate& c = rec.candidates[*rec.chosen];
  std::size_t passed = 0;
  for (const Candidate& x : rec.candidates) passed += x.status == CandidateStatus::passed ? 1 : 0;
  std::string s = fmt::format("Recommended, the cheapest by solver work ({}) of the {} candidate{} that pass: {} at rtol {:g}, "
                              "error {:.3g} (worst: {}) ≤ τ = {:g} against {}; {} solver work than the reference; wall "
                              "time {} (measured; not decisive: it varies with the machine's load).",
                              study::solver_work_measure, passed, passed == 1 ? "" : "s", c.label(),
                              rec.reasoning.relative_tolerance, c.error, c.worst_output, ctx.tolerance,
                              reference_label(rec.reference), speedup_words(rec.work_speedup()),
                              speedup_words(rec.wall_speedup()));
  if (rec.next_cheaper) {
    const Candidate& n = rec.candidates[*rec.next_cheaper];
    s += fmt::format(" The next cheaper candidate of the ladder, {}, fails: {}.", n.label(),
                     n.status == CandidateStatus::solver_failure ? n.failure : fmt::format("error {:.3g}", n.error));
  } else {
    s += " It is the cheapest candidate of the ladder.";
  }
  return s;
}

std::string run_line(const RecommendContext& ctx, const Recommendation& rec) {
  return rec.chosen ? run_command_line(ctx.scene_file, rec.candidates[*rec.chosen], rec.reasoning.relative_tolerance,
                                       rec.duration, rec.reference_scene)
                    : std::string();
}

std::string outcome(const Candidate& c) {
  switch (c.status) {
    case CandidateStatus::pruned: return "pruned: " + c.prune_reason;
    case CandidateStatus::not_run: return "not run (a cheaper one passed)";
    case CandidateStatus::solver_failure: return "FAILED: " + c.failure;
    case CandidateStatus::passed:
    case CandidateStatus::failed:
      return fmt::format("{} ({}){}", c.status == CandidateStatus::passed ? "passed" : "failed", c.worst_output,
                         c.minimality_check ? ", run to prove minimality" : "");
  }
  return "";
}

bool ran(const Candidate& c) {
  return c.status == CandidateStatus::passed || c.status == CandidateStatus::failed || c.status == CandidateStatus::solver_failure;
}

}  // namespace

std::string recommend_text(const RecommendContext& ctx, const Recommendation& rec) {
  std::string t = fmt::format("scene       {}\ntolerance   {:g} (worst normalized RMS error over {}, after t = {:g} s)\n"
                              "reference   {}\n\n",
                              ctx.scene_file, ctx.tolerance, output_list(rec.outputs),
                              rec.reference.window_start, reference_label(rec.reference));
  t += "reasoning\n";
  for (const std::string& s : rec.reasoning.statements) t += "  - " + s + "\n";
  t += fmt::format("\nwork = solver work, {}; expected: before the run (the ladder's order)\n", study::solver_work_measure);
  t += fmt::format("{:<50} {:>5} {:>9} {:>9} {:>9} {:>7} {:>9} {:>8}  {}\n", "candidate (cheapest expected first)", "DOFs",
                   "expected", "estimate", "error", "steps", "work", "wall [s]", "outcome");
  for (const Candidate& c : rec.candidates) {
    const bool r = ran(c) && c.status != CandidateStatus::solver_failure;
    t += fmt::format("{:<50} {:>5} {:>9} {:>9} {:>9} {:>7} {:>9} {:>8}  {}\n", c.label(), c.elastic_dof,
                     number(c.expected_work, "{:.2g}"), number(c.estimated_error, "{:.2g}"), r ? number(c.error) : "-",
                     r ? std::to_string(c.steps) : "-", r ? number(c.work()) : "-", r ? number(c.wall_seconds) : "-",
                     outcome(c));
  }
  t += fmt::format("{:<50} {:>5} {:>9} {:>9} {:>9} {:>7} {:>9} {:>8}  reference\n", reference_label(rec.reference),
                   fem::clamped_free_dof_count(rec.reference.choice.elements), "-", "-", "-", rec.reference.run.result.stats.steps,
                   number(rec.reference.run.work()), number(rec.reference.run.result.stats.wall_seconds));
  t += "\n" + decision_sentence(ctx, rec) + "\n";
  if (rec.chosen) t += "\nrun it with\n  " + run_line(ctx, rec) + "\n";
  return t;
}

std::string recommend_markdown(const RecommendContext& ctx, const Recommendation& rec) {
  std::string m = fmt::format("# ffrf recommend: {}\n\nScene `{}`, tolerance τ = {:g} on the worst normalized RMS error of "
                              "{} after t = {:g} s, {:g} s simulated.\n\n## Decision\n\n{}\n\n",
                              ctx.scene->name.empty() ? ctx.scene_file : ctx.scene->name, ctx.scene_file,
                              ctx.tolerance, output_list(rec.outputs), rec.reference.window_start,
                              rec.duration, decision_sentence(ctx, rec));
  if (rec.chosen) m += "```\n" + run_line(ctx, rec) + "\n```\n\n";
  m += "## Reasoning\n\n";
  for (const std::string& s : rec.reasoning.statements) m += "* " + s + "\n";
  m += fmt::format("\n## Candidates, cheapest expected first\n\nWork = solver work, {} (not seconds); expected: "
                   "before the run, the ladder's order (docs/recommend.md).\n\n"
                   "| candidate | elastic DOFs | expected work | a-priori estimate | error | steps | RHS evaluations | work | wall [s] | "
                   "outcome |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|---|\n",
                   study::solver_work_measure);
  for (const Candidate& c : rec.candidates) {
    const bool r = ran(c) && c.status != CandidateStatus::solver_failure;
    m += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", c.label(), c.elastic_dof,
                     number(c.expected_work, "{:.2g}"), number(c.estimated_error, "{:.2g}"), r ? number(c.error) : "-", r ? std::to_string(c.steps) : "-",
                     r ? std::to_string(c.rhs_evaluations) : "-", r ? number(c.work()) : "-",
                     r ? number(c.wall_seconds) : "-", outcome(c));
  }
  m += fmt::format("\n## Reference\n\n{}\n\n{}", reference_verdict(rec.reference), reference_levels_markdown(rec.reference));
  return m;
}

std::string recommend_json(const RecommendContext& ctx, const Recommendation& rec) {
  Json json;
  json["scene"] = ctx.scene_file;
  json["tolerance"] = ctx.tolerance;
  json["duration_s"] = rec.duration;
  json["outputs"] = Json::array();
  for (const auto channel : rec.outputs) json["outputs"].push_back(multibody::channel_name(channel));
  const study::RecommendReasoning& r = rec.reasoning;
  Json reasoning;
  reasoning["boom_angular_frequencies_rad_s"] = Json::array();
  for (const study::BoomMode& mode : r.modes) reasoning["boom_angular_frequencies_rad_s"].push_back(mode.angular_frequency);
  reasoning["wave_frequency_rad_s"] = r.wave_frequency;
  reasoning["spin_rate_rad_s"] = r.spin_rate;
  reasoning["excitation_top_rad_s"] = r.excitation_top;
  reasoning["dynamic_modes"] = r.dynamic_modes;
  reasoning["static_tip_deflection_m"] = r.static_tip_deflection;
  reasoning["rigid_error_estimate"] = r.rigid_error;
  reasoning["axial_load_N"] = r.axial_load;
  reasoning["euler_load_N"] = r.euler_load;
  reasoning["static_stiffening_effect"] = r.static_stiffening_effect;
  reasoning["centrifugal_softening"] = r.centrifugal_softening;
  reasoning["required_stiffening"] = scene::to_string(r.required_stiffening);
  reasoning["relative_tolerance"] = r.relative_tolerance;
  reasoning["statements"] = r.statements;
  json["reasoning"] = std::move(reasoning);
  Json reference = reference_json(rec.reference);
  reference["stiffening"] = scene::to_string(rec.reference_scene.boom.stiffening);
  reference["steps"] = rec.reference.run.result.stats.steps;
  reference["state_size"] = rec.reference.run.state_size;
  reference["work"] = rec.reference.run.work();
  reference["wall_s"] = rec.reference.run.result.stats.wall_seconds;
  json["reference"] = std::move(reference);
  json["candidates"] = Json::array();
  for (std::size_t i = 0; i < rec.candidates.size(); ++i) {
    const Candidate& c = rec.candidates[i];
    json["candidates"].push_back(
        Json{{"index", i},
             {"model", c.choice.label()},
             {"boom", scene::to_string(c.choice.kind)},
             {"elements", c.choice.elements},
             {"modes", c.choice.modes},
             {"static_modes", c.choice.static_modes},
             {"stiffening", scene::to_string(c.choice.stiffening.value_or(rec.reference_scene.boom.stiffening))},
             {"integrator", solve::to_string(c.integrator)},
             {"elastic_dof", c.elastic_dof},
             {"estimated_error", c.estimated_error},
             {"expected_work", c.expected_work},
             {"status", study::to_string(c.status)},
             {"reason", c.status == CandidateStatus::solver_failure ? c.failure : c.prune_reason},
             {"minimality_check", c.minimality_check},
             {"error", c.error},
             {"worst_output", c.worst_output},
             {"steps", c.steps},
             {"rhs_evaluations", c.rhs_evaluations},
             {"state_size", c.state_size},
             {"work", c.work()},
             {"wall_s", c.wall_seconds}});
  }
  json["chosen"] = rec.chosen ? Json(*rec.chosen) : Json(nullptr);
  json["next_cheaper"] = rec.next_cheaper ? Json(*rec.next_cheaper) : Json(nullptr);
  json["work_speedup"] = rec.work_speedup();
  json["wall_speedup"] = rec.wall_speedup();
  json["run_command"] = run_line(ctx, rec);
  json["decision"] = decision_sentence(ctx, rec);
  return json_text(json);
}

std::string run_command_line(const std::string& scene_file, const Candidate& c, double rtol, double duration,
                             const scene::Scene& scene) {
  std::string line = fmt::format("ffrf run {}", scene_file);
  for (const std::string& value : scene.overrides) line += fmt::format(" --set '{}'", value);  // the values set beside the file
  line += fmt::format(" --boom {}", scene::to_string(c.choice.kind));
  if (c.choice.kind != scene::BoomKind::rigid) line += fmt::format(" --elements {}", c.choice.elements);
  if (c.choice.kind == scene::BoomKind::modal) {
    line += fmt::format(" --modes {} {}", c.choice.modes, c.choice.static_modes ? "--static-modes" : "--no-static-modes");
  }
  const scene::Stiffening stiffening = c.choice.stiffening.value_or(scene.boom.stiffening);
  if (c.choice.kind != scene::BoomKind::rigid) line += fmt::format(" --stiffening {}", scene::to_string(stiffening));
  line += fmt::format(" --integrator {} --rtol {:g} --atol {:g}", solve::to_string(c.integrator), rtol, rtol);
  return line + fmt::format(" --duration {:g}", duration);
}

}  // namespace ffrf::report
