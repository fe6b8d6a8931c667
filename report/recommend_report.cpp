// Text, Markdown and JSON reports of `ffrf recommend` (see recommend_report.hpp).
#include "app/recommend_report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "app/crane_reference.hpp"
#include "app/json_writer.hpp"

namespace ffrf::app {
namespace {

std::string number(double value, const char* format = "{:.3g}") {
  return std::isfinite(value) ? fmt::format(fmt::runtime(format), value) : std::string("-");
}

std::string decision_sentence(const RecommendContext& ctx, const Recommendation& rec) {
  if (!rec.chosen) {
    return fmt::format("No candidate kept its error on {} within τ = {:g}: model the scene with the reference ({}).",
                       output_list(ctx.request.outputs), ctx.request.tolerance, rec.reference.choice.label());
  }
  const Candidate& c = rec.candidates[*rec.chosen];
  std::string s = fmt::format("Recommended: {} at rtol {:g}: error {:.3g} (worst: {}) ≤ τ = {:g} against {}; {:.3g}× less "
                              "solver work (steps × state size) and {:.3g}× less wall time than the reference.",
                              c.label(), rec.reasoning.relative_tolerance, c.error, c.worst_output, ctx.request.tolerance,
                              reference_label(rec.reference), rec.work_speedup(), rec.wall_speedup());
  if (rec.next_cheaper) {
    const Candidate& n = rec.candidates[*rec.next_cheaper];
    s += fmt::format(" The next cheaper candidate, {}, fails: {}.", n.label(),
                     n.status == CandidateStatus::solver_failure ? n.failure : fmt::format("error {:.3g}", n.error));
  } else {
    s += " It is the cheapest candidate of the ladder.";
  }
  return s;
}

std::string run_line(const RecommendContext& ctx, const Recommendation& rec) {
  return rec.chosen ? run_command_line(ctx.scene_file, rec.candidates[*rec.chosen], rec.reasoning.relative_tolerance,
                                       ctx.request.duration, rec.reference_scene)
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

std::string output_list(const std::vector<coupling::OutputChannel>& outputs) {
  std::string s;
  for (const auto channel : outputs) s += (s.empty() ? "" : ",") + std::string(coupling::channel_name(channel));
  return s;
}

std::string recommend_text(const RecommendContext& ctx, const Recommendation& rec) {
  std::string t = fmt::format("scene       {}\ntolerance   {:g} (worst normalized RMS error over {}, after t = {:g} s)\n"
                              "reference   {}\n\n",
                              ctx.scene_file, ctx.request.tolerance, output_list(ctx.request.outputs),
                              rec.reference.window_start, reference_label(rec.reference));
  t += "reasoning\n";
  for (const std::string& s : rec.reasoning.statements) t += "  - " + s + "\n";
  t += fmt::format("\n{:<50} {:>5} {:>9} {:>9} {:>7} {:>9} {:>8}  {}\n", "candidate (cheapest first)", "DOFs", "estimate",
                   "error", "steps", "work", "wall [s]", "outcome");
  for (const Candidate& c : rec.candidates) {
    const bool r = ran(c) && c.status != CandidateStatus::solver_failure;
    t += fmt::format("{:<50} {:>5} {:>9} {:>9} {:>7} {:>9} {:>8}  {}\n", c.label(), c.elastic_dof, number(c.estimated_error, "{:.2g}"),
                     r ? number(c.error) : "-", r ? std::to_string(c.steps) : "-", r ? number(c.work()) : "-",
                     r ? number(c.wall_seconds) : "-", outcome(c));
  }
  t += fmt::format("{:<50} {:>5} {:>9} {:>9} {:>7} {:>9} {:>8}  reference\n", reference_label(rec.reference),
                   3 * rec.reference.choice.elements, "-", "-", rec.reference.run.stats.steps,
                   number(static_cast<double>(rec.reference.run.stats.steps) * rec.reference_state_size),
                   number(rec.reference.run.stats.wall_seconds));
  t += "\n" + decision_sentence(ctx, rec) + "\n";
  if (rec.chosen) t += "\nrun it with\n  " + run_line(ctx, rec) + "\n";
  return t;
}

std::string recommend_markdown(const RecommendContext& ctx, const Recommendation& rec) {
  std::string m = fmt::format("# ffrf recommend: {}\n\nScene `{}`, tolerance τ = {:g} on the worst normalized RMS error of "
                              "{} after t = {:g} s, {:g} s simulated.\n\n## Decision\n\n{}\n\n",
                              ctx.scene->name.empty() ? ctx.scene_file : ctx.scene->name, ctx.scene_file,
                              ctx.request.tolerance, output_list(ctx.request.outputs), rec.reference.window_start,
                              ctx.request.duration, decision_sentence(ctx, rec));
  if (rec.chosen) m += "```\n" + run_line(ctx, rec) + "\n```\n\n";
  m += "## Reasoning\n\n";
  for (const std::string& s : rec.reasoning.statements) m += "* " + s + "\n";
  m += "\n## Candidates, cheapest first\n\nWork = steps × state size (solver work, not seconds).\n\n"
       "| candidate | elastic DOFs | a-priori estimate | error | steps | RHS evaluations | work | wall [s] | outcome |\n"
       "|---|--:|--:|--:|--:|--:|--:|--:|---|\n";
  for (const Candidate& c : rec.candidates) {
    const bool r = ran(c) && c.status != CandidateStatus::solver_failure;
    m += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", c.label(), c.elastic_dof,
                     number(c.estimated_error, "{:.2g}"), r ? number(c.error) : "-", r ? std::to_string(c.steps) : "-",
                     r ? std::to_string(c.rhs_evaluations) : "-", r ? number(c.work()) : "-",
                     r ? number(c.wall_seconds) : "-", outcome(c));
  }
  m += fmt::format("\n## Reference\n\n{}\n\n{}", reference_verdict(rec.reference), reference_levels_markdown(rec.reference));
  return m;
}

std::string recommend_json(const RecommendContext& ctx, const Recommendation& rec) {
  JsonWriter json;
  json.begin_object();
  json.field("scene", ctx.scene_file).field("tolerance", ctx.request.tolerance).field("duration_s", ctx.request.duration);
  json.key("outputs").begin_array();
  for (const auto channel : ctx.request.outputs) json.value(coupling::channel_name(channel));
  json.end_array();
  const RecommendReasoning& r = rec.reasoning;
  json.key("reasoning").begin_object();
  json.key("boom_angular_frequencies_rad_s").begin_array();
  for (const BoomMode& mode : r.modes) json.value(mode.angular_frequency);
  json.end_array();
  json.field("wave_frequency_rad_s", r.wave_frequency).field("spin_rate_rad_s", r.spin_rate);
  json.field("excitation_top_rad_s", r.excitation_top).field("dynamic_modes", r.dynamic_modes);
  json.field("static_tip_deflection_m", r.static_tip_deflection).field("rigid_error_estimate", r.rigid_error);
  json.field("axial_load_N", r.axial_load).field("euler_load_N", r.euler_load);
  json.field("static_stiffening_effect", r.static_stiffening_effect).field("centrifugal_softening", r.centrifugal_softening);
  json.field("required_stiffening", cases::to_string(r.required_stiffening));
  json.field("relative_tolerance", r.relative_tolerance);
  json.key("statements").begin_array();
  for (const std::string& s : r.statements) json.value(s);
  json.end_array();
  json.end_object();
  json.key("reference").begin_object();
  write_reference_json(json, rec.reference);
  json.field("stiffening", cases::to_string(rec.reference_scene.boom.stiffening));
  json.field("steps", static_cast<double>(rec.reference.run.stats.steps)).field("state_size", rec.reference_state_size);
  json.field("work", static_cast<double>(rec.reference.run.stats.steps) * rec.reference_state_size);
  json.field("wall_s", rec.reference.run.stats.wall_seconds);
  json.end_object();
  json.key("candidates").begin_array();
  for (std::size_t i = 0; i < rec.candidates.size(); ++i) {
    const Candidate& c = rec.candidates[i];
    json.begin_object();
    json.field("index", static_cast<int>(i)).field("model", c.choice.label()).field("boom", cases::to_string(c.choice.kind));
    json.field("elements", c.choice.elements).field("modes", c.choice.modes).field("static_modes", c.choice.static_modes);
    json.field("stiffening", cases::to_string(c.choice.stiffening.value_or(rec.reference_scene.boom.stiffening)));
    json.field("integrator", coupling::to_string(c.integrator)).field("elastic_dof", c.elastic_dof);
    json.field("estimated_error", c.estimated_error).field("status", to_string(c.status));
    json.field("reason", c.status == CandidateStatus::solver_failure ? c.failure : c.prune_reason);
    json.field("minimality_check", c.minimality_check);
    json.field("error", c.error).field("worst_output", c.worst_output);
    json.field("steps", static_cast<double>(c.steps)).field("rhs_evaluations", static_cast<double>(c.rhs_evaluations));
    json.field("state_size", c.state_size).field("work", c.work()).field("wall_s", c.wall_seconds);
    json.end_object();
  }
  json.end_array();
  if (rec.chosen) {
    json.field("chosen", static_cast<int>(*rec.chosen));
  } else {
    json.key("chosen").null();
  }
  if (rec.next_cheaper) {
    json.field("next_cheaper", static_cast<int>(*rec.next_cheaper));
  } else {
    json.key("next_cheaper").null();
  }
  json.field("work_speedup", rec.work_speedup()).field("wall_speedup", rec.wall_speedup());
  json.field("run_command", run_line(ctx, rec));
  json.field("decision", decision_sentence(ctx, rec));
  json.end_object();
  return json.str();
}

}  // namespace ffrf::app
