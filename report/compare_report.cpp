// The reports of `ffrf compare` (see compare_report.hpp).
#include "report/compare_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <numbers>
#include <stdexcept>

#include "report/crane_charts.hpp"
#include "report/reference_report.hpp"

namespace ffrf::report {
namespace {

using coupling::all_channels;
using study::Comparison;
using study::ModelRun;
using coupling::channel_name;
using coupling::channel_unit;

constexpr double degrees = 180.0 / std::numbers::pi;

std::string md(double value) { return format_value(value); }
std::string sci(double value) { return std::isfinite(value) ? fmt::format("{:.2e}", value) : "-"; }

std::string window_text(double start) {
  return start > 0.0 ? fmt::format("after the wave ramp (t ≥ {:g} s)", start)
                     : std::string("over the whole run (it ends within the wave ramp, or calm water)");
}

std::string settings_text(const RunContext& c) {
  return fmt::format("integrator {}, rtol {:g}, atol {:g}, {:g} s simulated, output every {:g} s", coupling::to_string(c.settings.kind),
                     c.settings.relative_tolerance, c.settings.absolute_tolerance, c.settings.duration,
                     c.settings.output_interval);
}

// Every run of the report, the reference last, with its label.
std::vector<std::pair<const ModelRun*, std::string>> all_runs(const Comparison& c) {
  std::vector<std::pair<const ModelRun*, std::string>> rows;
  for (const ModelRun& run : c.runs) rows.emplace_back(&run, run.choice.label());
  rows.emplace_back(&c.reference.run, reference_label(c.reference));
  return rows;
}

std::string static_table(const scene::Scene& scene, const Comparison& c) {
  std::string t =
      "| model | elastic DOFs | draft at mid-length [m] | trim [deg] | tip transverse [m] | tip axial [m] | wire stretch [m] | "
      "wire tension [N] | joint moment at B [N m] |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& [run, label] : all_runs(c)) {
    const coupling::CraneOutputs& o = run->static_outputs();
    t += fmt::format("| {} | {} | {:.4f} | {:+.4f} | {:+.5f} | {:+.5f} | {:.5f} | {} | {} |\n", label, run->elastic_dof,
                     study::draft_at_mid_length(scene, o), o.hull.z() * degrees, o.tip_deflection.y(), o.tip_deflection.x(),
                     scene.wire ? o.wire_length - scene.wire->unstretched_length : 0.0, md(o.wire_tension), md(o.joint_reaction.z()));
  }
  return t;
}

std::string error_table(const Comparison& c, bool normalized) {
  std::string t = "| model |", rule = "|---|";
  for (const auto channel : all_channels) {
    t += normalized ? fmt::format(" {} |", channel_name(channel))
                    : fmt::format(" {} [{}] |", channel_name(channel), channel_unit(channel));
    rule += "--:|";
  }
  t += normalized ? " DAF error | worst |\n" + rule + "--:|--:|\n" : "\n" + rule + "\n";
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    t += fmt::format("| {} |", c.runs[m].choice.label());
    for (const auto channel : all_channels) {
      const coupling::ChannelError& e = c.errors[m][channel];
      t += fmt::format(" {} |", sci(normalized ? e.normalized_rms : e.max_abs));
    }
    if (normalized) t += fmt::format(" {} | {} |", sci(c.errors[m].daf_error), sci(c.worst[m].error));
    t += "\n";
  }
  return t;
}

std::string wire_table(const Comparison& c) {
  std::string t = "| model | static tension [N] | max tension [N] | dynamic amplification factor | slack events |\n"
                  "|---|--:|--:|--:|--:|\n";
  for (const auto& [run, label] : all_runs(c)) {
    t += fmt::format("| {} | {} | {} | {:.4f} | {} |\n", label, md(run->static_outputs().wire_tension),
                     md(run->amplification * run->static_outputs().wire_tension), run->amplification, run->slack_events());
  }
  return t;
}

std::string cost_table(const Comparison& c) {
  std::string t = "| model | wall time [s] | real-time factor | steps | function evaluations | Jacobian evaluations | "
                  "Newton iterations | error-test failures | max constraint residual [m] |\n"
                  "|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& [run, label] : all_runs(c)) {
    const coupling::SolverStats& s = run->result.stats;
    t += fmt::format("| {} | {:.3g} | {:.4g} | {} | {} | {} | {} | {} | {:.2g} |\n", label, s.wall_seconds,
                     run->real_time_factor, s.steps, s.function_evaluations, s.jacobian_evaluations, s.newton_iterations,
                     s.error_test_failures, run->max_constraint_residual);
  }
  return t;
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
  r += fmt::format("- errors against: {}\n", reference_label(c.reference));
  r += fmt::format("- ffrf {}, {}\n\n", ffrf_version(), ctx.date);
  r += stiffening_sentence(c) + "\n\n";
  r += "## Converged reference\n\n";
  r += fmt::format("Nodal model refined level by level (elements doubled, CVODE tolerance tightened 10×) until the worst "
                   "normalized RMS change of the outputs between two levels, {}, falls below the bound. ",
                   window_text(c.window_start));
  r += reference_verdict(c.reference) + "\n\n" + reference_levels_markdown(c.reference) + "\n";
  r += "## Static equilibrium\n\n" + static_table(scene, c) + "\n";
  r += fmt::format("## Time histories\n\nDrawn: {}and the reference (every model is in the tables and has its CSV). Motions "
                   "are displacements from each model's static equilibrium.\n\n", plotted);
  for (const std::string& name : crane_chart_names()) r += fmt::format("![{0}]({0}.png)\n\n", name);
  r += fmt::format("## Errors against the reference\n\nPer output channel, {}: normalized RMS error = RMS(x − x_ref) / "
                   "RMS(x_ref − mean x_ref); DAF error = |DAF − DAF_ref| / DAF_ref of the wire tension's dynamic "
                   "amplification factor (max tension / static tension) in that window; worst = the largest normalized "
                   "RMS error over the judged outputs ({}: docs/validation.md says why). Pitch channels in rad.\n\n",
                   window_text(c.window_start), study::output_list(c.judged));
  r += "### Normalized RMS error\n\n" + error_table(c, true) + "\n";
  r += "### Maximum absolute error\n\n" + error_table(c, false) + "\n";
  r += "## Wire rope\n\nDynamic amplification factor here: the maximum tension over the whole run divided by the static "
       "tension.\n\n" + wire_table(c) + "\n";
  r += "## Solver costs\n\nWall time of the integration alone; real-time factor = simulated time / wall time.\n\n" +
       cost_table(c) + "\n";
  r += "Files: ";
  for (const ModelRun& run : c.runs) r += fmt::format("`{}`, ", timeseries_name(run));
  r += fmt::format("`{}`, `summary.json`; every chart with its gnuplot script (`NAME.gp`).\n", reference_timeseries_name);
  return r;
}

std::string compare_json(const RunContext& ctx, const Comparison& c) {
  Json json;
  json["command"] = "compare";
  json["provenance"] = settings_json(ctx);
  json["geometric_stiffening"] = scene::to_string(c.stiffening);
  json["stiffening_from_physics"] = c.stiffening_from_physics;
  json["reference"] = reference_json(c.reference);
  json["reference"]["timeseries"] = reference_timeseries_name;
  json["error_window_start_s"] = c.window_start;
  json["judged_outputs"] = Json::array();
  for (const auto channel : c.judged) json["judged_outputs"].push_back(channel_name(channel));
  json["models"] = Json::array();
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    Json model = model_json(*ctx.scene, c.runs[m]);
    model["timeseries"] = timeseries_name(c.runs[m]);
    Json errors = Json::object();
    for (const auto channel : all_channels) {
      const coupling::ChannelError& e = c.errors[m][channel];
      errors[std::string(channel_name(channel))] =
          Json{{"normalized_rms", e.normalized_rms}, {"max_abs", e.max_abs}, {"normalized_max", e.normalized_max}};
    }
    errors["daf_error"] = c.errors[m].daf_error;
    errors["worst_normalized_rms"] = c.worst[m].error;
    errors["worst_output"] = channel_name(c.worst[m].channel);
    model["errors_to_reference"] = std::move(errors);
    json["models"].push_back(std::move(model));
  }
  return json_text(json);
}

std::string compare_text(const RunContext& ctx, const Comparison& c) {
  std::string t = fmt::format("scene       {}\nsettings    {}, stiffening {}\nerrors      {} against {}\n\n", ctx.scene_file,
                              settings_text(ctx), scene::to_string(c.stiffening), window_text(c.window_start),
                              reference_label(c.reference));
  t += "converged reference\n" + reference_levels_text(c.reference) + "\n";
  t += fmt::format("{:<24} {:>5} {:>11} {:>10} {:>10} {:>10} {:>10} {:>9} {:>11}\n", "model", "DOFs", "tip v [m]",
                   "cargo hv", "wire T", "DAF err", "worst", "wall [s]", "x real time");
  auto row = [&](const std::string& label, const ModelRun& run, const coupling::RunErrors* e, const study::WorstError* w) {
    t += fmt::format("{:<24} {:>5} {:>+11.5f} {:>10} {:>10} {:>10} {:>10} {:>9.3g} {:>11.4g}\n", label, run.elastic_dof,
                     run.static_outputs().tip_deflection.y(),
                     e ? sci((*e)[coupling::OutputChannel::cargo_heave].normalized_rms) : "-",
                     e ? sci((*e)[coupling::OutputChannel::wire_tension].normalized_rms) : "-",
                     e ? sci(e->daf_error) : "-", w ? sci(w->error) : "-", run.result.stats.wall_seconds,
                     run.real_time_factor);
  };
  for (std::size_t m = 0; m < c.runs.size(); ++m) row(c.runs[m].choice.label(), c.runs[m], &c.errors[m], &c.worst[m]);
  row("(reference)", c.reference.run, nullptr, nullptr);
  t += fmt::format("(cargo hv, wire T: normalized RMS error of cargo heave and wire tension; worst: over {})\n",
                   study::output_list(c.judged));
  return t;
}

}  // namespace ffrf::report
