// The reports of `ffrf compare` (see compare_report.hpp).
#include "report/compare_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "report/compare_tables.hpp"
#include "report/crane_charts.hpp"
#include "report/irregular_report.hpp"
#include "report/quantities.hpp"
#include "report/verdict_report.hpp"
#include "report/reference_report.hpp"

namespace ffrf::report {
namespace {

using multibody::all_channels;
using study::Comparison;
using study::ModelRun;
using multibody::channel_name;


std::string window_text(double start) {
  return start > 0.0 ? fmt::format("after the wave ramp (t ≥ {:g} s)", start)
                     : std::string("over the whole run (it ends within the wave ramp, or calm water)");
}

std::string settings_text(const RunContext& c) {
  return fmt::format("integrator {}, rtol {:g}, atol {:g}, {:g} s simulated, output every {:g} s", solve::to_string(c.settings.kind),
                     c.settings.relative_tolerance, c.settings.absolute_tolerance, c.settings.duration,
                     c.settings.output_interval);
}

// The verdict in words: the headline and what failed.
std::string verdict_sentence(const Comparison& c) {
  const std::vector<study::MeasuredModel> measured = study::measured_models(c);
  const std::string failed = failed_list(c.verdict, measured);
  const double rtol = c.settings.relative_tolerance, choice_rtol = study::model_choice_rtol(c.verdict.tolerance);
  std::string s = verdict_headline(c.verdict, measured, reference_label(c.reference), "models",
                                   fmt::format(" (all at {} rtol {:g})", solve::to_string(c.settings.kind), rtol)) +
                  (failed.empty() ? "" : " " + failed);
  // recommend and sweep name their cheapest model from runs at the model-choice rtol: say when these are not.
  if (rtol != choice_rtol) {
    s += fmt::format(" These models ran at rtol {:g}, not at the model-choice rtol {:g} of τ = {:g} at which recommend and "
                     "sweep name the cheapest model: run them at rtol = atol = {:g} to compare like for like.",
                     rtol, choice_rtol, c.verdict.tolerance, choice_rtol);
  }
  return s;
}

// Why the verdict judges the total error, and what the two parts are.
std::string measure_text(const Comparison& c) {
  return fmt::format(
      "The verdict judges each model's **worst total error** over the judged outputs ({}): the normalized RMS error "
      "RMS(x − x_ref) / S, S = RMS(x_ref − mean x_ref), {} — the error of `ffrf sweep` and `ffrf recommend` too. It has "
      "two parts, reported per output below: the **static error** |x_s − x_ref_s| / S (the model's static equilibrium "
      "against the reference's: the static table) and the **dynamic error** RMS(d − d_ref) / S (the displacement d from "
      "each model's own equilibrium against the reference's: what the charts draw, their lower panels the difference); "
      "total ≤ static + dynamic. The verdict uses the total because a design reads absolute positions and loads: an "
      "equilibrium that is off counts as much as a motion that is off. Errors below the reference's own last change "
      "({}) are not resolved.",
      study::output_list(c.judged), window_text(c.window_start),
      c.reference.levels.size() > 1 ? fmt::format("{:.2g}", c.reference.levels.back().change) : std::string("not measured"));
}

bool has_irregular_errors(const Comparison& c) {
  return std::any_of(c.irregular.begin(), c.irregular.end(), [](const auto& e) { return e.has_value(); });
}

std::vector<std::string> model_labels(const Comparison& c) {
  std::vector<std::string> labels;
  for (const ModelRun& run : c.runs) labels.push_back(run.choice.label());
  return labels;
}

}  // namespace

std::string timeseries_name(const ModelRun& run) { return "timeseries_" + slug(run.choice.label()) + ".csv"; }

namespace {

// What the boom models (all of them, the reference included) say about geometric stiffening.
std::string stiffening_sentence(const Comparison& c) {
  const std::string why = c.stiffening_from_physics
                              ? " — what the physics needs here (the same reference physics as `ffrf recommend`; "
                                "--stiffening sets it)"
                              : " (--stiffening)";
  switch (c.stiffening) {
    case scene::Stiffening::none:
      return "The boom is linear-elastic in every model: geometric stiffening is not modelled" + why + ".";
    case scene::Stiffening::static_load:
      return "Every model, the reference included, models the static (prestress) geometric stiffening of the boom under its "
             "own weight and the hanging cargo" + why + ".";
    case scene::Stiffening::centrifugal:
      return "Every model, the reference included, models the centrifugal geometric stiffening of the spinning boom" + why + ".";
    case scene::Stiffening::both:
      return "Every model, the reference included, models both the static (prestress) and the centrifugal geometric "
             "stiffening of the boom" + why + ".";
  }
  return "";
}

}  // namespace

std::string compare_markdown(const RunContext& ctx, const Comparison& c) {
  const scene::Scene& scene = *ctx.scene;
  std::string labels, plotted;
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    labels += (m == 0 ? "" : ", ") + c.runs[m].choice.label();
    if (c.plotted[m]) plotted += c.runs[m].choice.label() + ", ";
  }
  std::string r = fmt::format("# Boom models compared: {}\n\n", scene.name.empty() ? ctx.scene_file : scene.name);
  r += fmt::format("- scene: `{}`{}\n", ctx.scene_file, scene.description.empty() ? "" : " — " + scene.description);
  r += fmt::format("- models: {}; modal bases on the N = 16 mesh\n", labels);
  r += fmt::format("- settings: {}; each model starts from the scene's initial state{}\n", settings_text(ctx),
                   scene.simulation.cargo_lift > 0.0
                       ? fmt::format(" (its static equilibrium, the cargo raised {:g} m)", scene.simulation.cargo_lift)
                       : std::string(" (its own static equilibrium)"));
  r += fmt::format("- errors against: {}, {}\n", reference_label(c.reference), window_text(c.window_start));
  r += fmt::format("- tolerance of the verdict: τ = {:g} on the worst total error over {}\n", c.verdict.tolerance,
                   study::output_list(c.judged));
  r += fmt::format("- ffrf {}, {}\n\n", ffrf_version(), ctx.date);
  r += stiffening_sentence(c) + "\n\n";
  // The marks let scripts/regenerate-docs.sh quote this section (the README does).
  r += "## Verdict\n\n<!-- verdict:begin -->\n**" + verdict_sentence(c) + "**\n\n";
  r += verdict_table(c) + "<!-- verdict:end -->\n\n";
  r += "Speed-ups: the reference's wall time (integration) and solver work (RHS evaluations × state size, the cost measure of "
       "`ffrf recommend`: independent of the machine's load) over the model's. Static and dynamic error: the two parts of "
       "the worst output's error.\n\n";
  r += measure_text(c) + "\n\n";
  r += "## Converged reference\n\n";
  r += fmt::format("Nodal model refined level by level (elements doubled, CVODE tolerance tightened 10×) until the worst "
                   "normalized RMS change of the outputs between two levels, {}, falls below the bound. ",
                   window_text(c.window_start));
  r += reference_verdict(c.reference) + "\n\n" + reference_levels_markdown(c.reference) + "\n";
  r += "## Static equilibrium\n\n" + static_table(scene, c) + "\n";
  r += fmt::format(
      "## Time histories\n\nDrawn: {}and the reference (dashed black, drawn last; every model is in the tables and has its "
      "CSV). Upper panels: motions are displacements from each model's own static equilibrium; the wire tension and the tip "
      "deflection are absolute (a rigid boom has no tip deflection and is left off those charts). Lower panels: "
      "|d − d_ref|, the difference of each model's displacement from its own static value against the reference's, on a "
      "log axis (`differences.csv`) — what the dynamic error measures; the static offsets are in the tables. The dotted "
      "line marks the start of the error window. Pitch in degrees.\n\n",
      plotted);
  for (const std::string& name : crane_chart_names(scene)) r += fmt::format("![{0}]({0}.png)\n\n", name);
  r += fmt::format("## Errors against the reference, per output\n\nPer output channel, {}. Pitch channels in degrees "
                   "where absolute. The tip deflection is reported, not judged (docs/validation.md says why).\n\n",
                   window_text(c.window_start));
  r += "### Total error (normalized RMS): what the verdict judges\n\nRMS(x − x_ref) / S; DAF error = |DAF − DAF_ref| / "
       "DAF_ref of the wire tension's dynamic amplification factor (max tension / static tension) in the window; worst = "
       "the largest over the judged outputs.\n\n" +
       error_table(c, ErrorKind::total) + "\n";
  r += "### Static error (normalized): |x_s − x_ref_s| / S\n\n" + error_table(c, ErrorKind::static_part) + "\n";
  r += "### Dynamic error (normalized RMS): RMS(d − d_ref) / S\n\n" + error_table(c, ErrorKind::dynamic_part) + "\n";
  r += "### Static offset x_s − x_ref_s\n\n" + error_table(c, ErrorKind::static_offset) + "\n";
  r += "### Largest dynamic difference max |d − d_ref|\n\n" + error_table(c, ErrorKind::dynamic_max) + "\n";
  r += "### Largest total difference max |x − x_ref|\n\n" + error_table(c, ErrorKind::total_max) + "\n";
  if (has_irregular_errors(c)) {
    r += "## Irregular sea: statistics and spectra against the reference\n\nIn an irregular sea a small phase drift "
         "spoils a time history while every statistic a design uses agrees, so each model's statistics and Welch "
         "spectra are compared with the reference's too (not judged by the verdict; cells: error of σ / error of the "
         "Rayleigh MPM / spectral distance D).\n\n```\n" + irregular_errors_text(model_labels(c), c.irregular) + "```\n\n";
    if (c.reference.run.irregular) r += "Reference run's statistics:\n\n```" + irregular_text(*c.reference.run.irregular) + "```\n\n";
  }
  r += "## Stresses along the boom\n\nThe largest extreme-fibre stress |N|/A + |M|c/I over the boom's sections at each output "
       "(c = " + fmt::format("{:.3g}", scene.boom.fibre_distance) + " m), recovered from each modal boom both ways in the same run: "
       "by **mode displacement** (from the modes' own deflection Φη) and by **mode acceleration** (the static response of the "
       "nodal model to every load the modes leave unbalanced added: Φη + K⁻¹r); a nodal boom's stresses are its own "
       "displacements', a rigid boom's the quasi-static ones. History error: the normalized RMS error of the peak-stress history "
       "against the reference's, " + window_text(c.window_start) + "; largest peak: its largest value there, and the relative "
       "error of that design value. The verdict judges the peak stress of a pinned boom by the recovery each model names "
       "(`--stress-recovery`).\n\n![boom_stress](boom_stress.png)\n\n" + stress_recovery_table(c) + "\n";
  r += "## Wire rope\n\nDynamic amplification factor here: the maximum tension over the whole run divided by the static "
       "tension.\n\n" + wire_table(c) + "\n";
  r += "## Solver costs\n\nWall time of the integration alone; real-time factor = simulated time / wall time; work = steps × "
       "state size.\n\n" + cost_table(c) + "\n";
  r += "Files: ";
  for (const ModelRun& run : c.runs) r += fmt::format("`{}`, ", timeseries_name(run));
  r += fmt::format("`{}`, `differences.csv`, `summary.json`; every chart with its gnuplot script (`NAME.gp`).\n",
                   reference_timeseries_name);
  return r;
}

std::string compare_json(const RunContext& ctx, const Comparison& c) {
  Json json;
  json["command"] = "compare";
  json["provenance"] = settings_json(ctx);
  json["geometric_stiffening"] = scene::to_string(c.stiffening);
  json["stiffening_from_physics"] = c.stiffening_from_physics;
  json["verdict"] = verdict_json(c.verdict, study::measured_models(c), verdict_sentence(c));
  json["reference"] = reference_json(c.reference);
  json["reference"]["timeseries"] = reference_timeseries_name;
  json["reference"]["steps"] = c.reference.run.result.stats.steps;
  json["reference"]["state_size"] = c.reference.run.state_size;
  json["reference"]["work"] = c.reference.run.work();
  json["reference"]["wall_s"] = c.reference.run.result.stats.wall_seconds;
  json["error_window_start_s"] = c.window_start;
  json["judged_outputs"] = Json::array();
  for (const auto channel : c.judged) json["judged_outputs"].push_back(channel_name(channel));
  json["models"] = Json::array();
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    Json model = model_json(*ctx.scene, c.runs[m]);
    model["timeseries"] = timeseries_name(c.runs[m]);
    model["state_size"] = c.runs[m].state_size;
    model["work"] = c.runs[m].work();
    Json errors = Json::object();
    for (const auto channel : all_channels) {
      const multibody::ChannelError& e = c.errors[m][channel];
      const study::SplitError& s = c.split[m][static_cast<std::size_t>(channel)];
      const double unit = display_scale(channel);
      errors[std::string(channel_name(channel))] = Json{{"normalized_rms", e.normalized_rms},
                                                        {"static_error", s.static_error},
                                                        {"dynamic_error", s.dynamic_error},
                                                        {"unit", display_unit(channel)},
                                                        {"max_abs", e.max_abs * unit},
                                                        {"normalized_max", e.normalized_max},
                                                        {"static_offset", s.static_offset * unit},
                                                        {"dynamic_max_abs", s.dynamic_max * unit},
                                                        {"scale", s.scale * unit}};
    }
    errors["daf_error"] = c.errors[m].daf_error;
    if (m < c.stress.size()) {
      Json stress = Json::object();
      for (const multibody::StressRecovery method : multibody::all_stress_recoveries) {
        const study::PeakStressError& e = c.stress[m][method];
        stress[std::string(multibody::to_string(method))] =
            Json{{"normalized_rms", e.normalized_rms}, {"largest_peak_MPa", e.peak * 1e-6}, {"largest_peak_error", e.design_peak}};
      }
      stress["reference_largest_peak_MPa"] = c.stress[m].reference_peak * 1e-6;
      errors["boom_peak_stress_by_recovery"] = std::move(stress);
    }
    errors["worst_normalized_rms"] = c.worst[m].error;
    errors["worst_output"] = channel_name(c.worst[m].channel);
    model["errors_to_reference"] = std::move(errors);
    if (m < c.irregular.size() && c.irregular[m]) model["irregular_sea_errors"] = irregular_errors_json(*c.irregular[m]);
    model["verdict"] = Json{{"passed", c.verdict.models[m].passed},
                            {"wall_speedup", c.verdict.models[m].wall_speedup},
                            {"work_speedup", c.verdict.models[m].work_speedup}};
    json["models"].push_back(std::move(model));
  }
  return json_text(json);
}

namespace {

// `text` wrapped at `width` columns, every line after the first indented by `indent` spaces.
std::string wrapped(const std::string& text, std::size_t width, std::size_t indent) {
  std::string out, line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n" + std::string(indent, ' ');
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return out + line;
}

}  // namespace

std::string compare_text(const RunContext& ctx, const Comparison& c) {
  std::string t = fmt::format("scene       {}\nsettings    {}, stiffening {}\nerrors      {} against {}\n"
                              "tolerance   {:g} on the worst total error over {}\n\n",
                              ctx.scene_file, settings_text(ctx), scene::to_string(c.stiffening), window_text(c.window_start),
                              reference_label(c.reference), c.verdict.tolerance, study::output_list(c.judged));
  t += "converged reference\n" + reference_levels_text(c.reference) + "\n";
  const std::vector<study::MeasuredModel> measured = study::measured_models(c);
  std::size_t width = 24;  // the model column: as wide as the longest label
  for (const auto& run : c.runs) width = std::max(width, run.choice.label().size());
  t += fmt::format("{:<{}} {:>4} {:>9} {:<13} {:>9} {:>9} {:>7} {:>9} {:>7} {:>7}\n", "model", width, "DOFs", "worst",
                   "worst output", "static", "dynamic", "verdict", "wall [s]", "x wall", "x work");
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    const study::SplitError& s = c.split[m][static_cast<std::size_t>(c.worst[m].channel)];
    t += fmt::format("{:<{}} {:>4} {:>9} {:<13} {:>9} {:>9} {:>7} {:>9.3g} {:>7} {:>7}\n", c.runs[m].choice.label(), width,
                     c.runs[m].elastic_dof, sci(c.worst[m].error), channel_name(c.worst[m].channel), sci(s.static_error),
                     sci(s.dynamic_error), pass_cell(c.verdict, measured, m), c.runs[m].result.stats.wall_seconds,
                     speedup_cell(c.verdict.models[m].wall_speedup), speedup_cell(c.verdict.models[m].work_speedup));
  }
  t += fmt::format("{:<{}} {:>4} {:>9} {:<13} {:>9} {:>9} {:>7} {:>9.3g} {:>7} {:>7}\n", "(reference)", width,
                   c.reference.run.elastic_dof, "-", "-", "-", "-", "-", c.reference.run.result.stats.wall_seconds, "1×", "1×");
  t += "(worst: the largest total normalized RMS error over the judged outputs, what the verdict judges; static, dynamic: "
       "its two parts for that output — the equilibrium offset, and the motion about each model's own equilibrium; x wall, "
       "x work: the reference's wall time and solver work (RHS evaluations x state size) over the model's)\n\n";
  if (!c.stress.empty()) {
    t += fmt::format("boom stress: the largest peak fibre stress {}: {:.4g} MPa in the reference; each modal boom's "
                     "peak-stress history error by mode displacement / by mode acceleration (the recovery it reports marked *)\n",
                     window_text(c.window_start), c.stress.front().reference_peak * 1e-6);
    for (std::size_t m = 0; m < c.runs.size() && m < c.stress.size(); ++m) {
      const scene::BoomChoice& choice = c.runs[m].choice;
      if (choice.kind != scene::BoomKind::modal) continue;
      const bool acceleration = choice.stress_recovery == multibody::StressRecovery::mode_acceleration;
      t += fmt::format("  {:<{}} {:>9}{} / {:>9}{}\n", choice.label(), width,
                       sci(c.stress[m][multibody::StressRecovery::mode_displacement].normalized_rms), acceleration ? " " : "*",
                       sci(c.stress[m][multibody::StressRecovery::mode_acceleration].normalized_rms), acceleration ? "*" : " ");
    }
    t += "\n";
  }
  if (has_irregular_errors(c)) t += irregular_errors_text(model_labels(c), c.irregular);
  t += "verdict     " + wrapped(verdict_sentence(c), 100, 12) + "\n";
  return t;
}

}  // namespace ffrf::report
