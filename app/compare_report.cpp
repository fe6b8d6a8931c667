// The model list of `ffrf compare` and its reports (see compare_report.hpp).
#include "app/compare_report.hpp"

#include <fmt/format.h>

#include <numbers>
#include <stdexcept>

#include "app/crane_charts.hpp"
#include "app/json_writer.hpp"

namespace ffrf::app {
namespace {

constexpr double degrees = 180.0 / std::numbers::pi;

std::string md(double value) { return format_value(value); }

const ModelRun& reference_run(const Comparison& c) { return c.runs[c.reference]; }

std::string window_text(const ModelRun& run) {
  return run.window.after_ramp ? fmt::format("after the wave ramp (t > {:g} s)", run.window.start_s)
                               : std::string("over the whole run (it ends within the wave ramp, or calm water)");
}

std::string settings_text(const RunContext& c) {
  return fmt::format("integrator {}, rtol {:g}, atol {:g}, {:g} s simulated, output every {:g} s", coupling::to_string(c.settings.kind),
                     c.settings.relative_tolerance, c.settings.absolute_tolerance, c.settings.duration,
                     c.settings.output_interval);
}

std::string static_table(const Comparison& c) {
  std::string t =
      "| model | elastic DOFs | draft at mid-length [m] | trim [deg] | tip transverse [m] | tip axial [m] | wire stretch [m] | "
      "wire tension [N] | joint moment at B [N m] |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  const cases::Scene& scene = *c.context.scene;
  for (const ModelRun& run : c.runs) {
    const coupling::CraneOutputs& o = run.static_outputs();
    t += fmt::format("| {} | {} | {:.4f} | {:+.4f} | {:+.5f} | {:+.5f} | {:.5f} | {} | {} |\n", run.choice.label(),
                     run.elastic_dof, draft_at_mid_length(scene, o), o.hull.z() * degrees, o.tip_deflection.y(),
                     o.tip_deflection.x(), o.wire_length - scene.wire->unstretched_length, md(o.wire_tension),
                     md(o.joint_reaction.z()));
  }
  return t;
}

std::string extremes_table(const Comparison& c) {
  std::string head = "| output |", rule = "|---|";
  for (const ModelRun& run : c.runs) {
    head += fmt::format(" {0} max | {0} RMS |", run.choice.label());
    rule += "--:|--:|";
  }
  std::string t = head + "\n" + rule + "\n";
  const auto series = crane_series();
  for (std::size_t i = 0; i < series.size(); ++i) {
    t += fmt::format("| `{}` |", series[i].column);
    for (const ModelRun& run : c.runs) t += fmt::format(" {} | {} |", md(run.stats[i].max), md(run.stats[i].rms));
    t += "\n";
  }
  return t;
}

std::string differences_table(const Comparison& c) {
  std::string head = "| output |", rule = "|---|";
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    if (m == c.reference) continue;
    head += fmt::format(" {0}: max abs diff | {0}: RMS diff |", c.runs[m].choice.label());
    rule += "--:|--:|";
  }
  std::string t = head + "\n" + rule + "\n";
  const auto series = crane_series();
  for (std::size_t i = 0; i < series.size(); ++i) {
    t += fmt::format("| `{}` |", series[i].column);
    for (std::size_t m = 0; m < c.runs.size(); ++m) {
      if (m == c.reference) continue;
      t += fmt::format(" {} | {} |", md(c.differences[m][i].max_abs), md(c.differences[m][i].rms));
    }
    t += "\n";
  }
  return t;
}

std::string wire_table(const Comparison& c) {
  std::string t = "| model | static tension [N] | max tension [N] | dynamic amplification factor | slack events |\n"
                  "|---|--:|--:|--:|--:|\n";
  for (const ModelRun& run : c.runs) {
    t += fmt::format("| {} | {} | {} | {:.4f} | {} |\n", run.choice.label(), md(run.static_outputs().wire_tension),
                     md(run.amplification * run.static_outputs().wire_tension), run.amplification, run.slack_events());
  }
  return t;
}

std::string cost_table(const Comparison& c) {
  std::string t = "| model | wall time [s] | real-time factor | steps | function evaluations | Jacobian evaluations | "
                  "Newton iterations | error-test failures | convergence failures | static equilibrium [s] | "
                  "max constraint residual [m] |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const ModelRun& run : c.runs) {
    const coupling::SolverStats& s = run.result.stats;
    t += fmt::format("| {} | {:.3g} | {:.4g} | {} | {} | {} | {} | {} | {} | {:.2g} | {:.2g} |\n", run.choice.label(),
                     s.wall_seconds, run.real_time_factor, s.steps, s.function_evaluations, s.jacobian_evaluations,
                     s.newton_iterations, s.error_test_failures, s.convergence_failures, run.statics.wall_seconds,
                     run.max_constraint_residual);
  }
  return t;
}

}  // namespace

std::vector<ComparedModel> compared_models() {
  using cases::BoomKind;
  return {
      {{BoomKind::rigid, 1}, false},
      {{BoomKind::nodal, 1}, false},  // the paper's one-element boom
      {{BoomKind::nodal, 16}, true},  // the finest model here, not a converged reference
  };
}

Comparison make_comparison(RunContext context, std::vector<ModelRun> runs, std::size_t reference) {
  Comparison c{std::move(context), std::move(runs), reference, {}};
  const ModelRun& ref = reference_run(c);
  for (const ModelRun& run : c.runs) {
    c.differences.push_back(series_differences(run.result.samples, run.static_outputs(), ref.result.samples,
                                               ref.static_outputs(), ref.window));
  }
  return c;
}

std::string timeseries_name(const ModelRun& run) { return "timeseries_" + slug(run.choice.label()) + ".csv"; }

std::string compare_markdown(const Comparison& c) {
  const RunContext& ctx = c.context;
  const cases::Scene& scene = *ctx.scene;
  const ModelRun& ref = reference_run(c);
  std::string labels;
  for (std::size_t m = 0; m < c.runs.size(); ++m) labels += (m == 0 ? "" : ", ") + c.runs[m].choice.label();
  std::string r = fmt::format("# Boom models compared: {}\n\n", scene.name.empty() ? ctx.scene_file : scene.name);
  r += fmt::format("- scene: `{}`{}\n", ctx.scene_file, scene.description.empty() ? "" : " — " + scene.description);
  r += fmt::format("- models: {}\n", labels);
  r += fmt::format("- settings: {}; each model starts from its own static equilibrium\n", settings_text(ctx));
  r += fmt::format("- ffrf {}, {}\n\n", ffrf_version(), ctx.date);
  r += fmt::format(
      "**{} is the finest model of this comparison, not a converged reference**: the differences below "
      "are relative to it and say how far the coarser models are from it, not how far any model is from the exact "
      "answer. The boom is linear-elastic in every model: geometric stiffening from its axial compression is not "
      "modelled.\n\n",
      ref.choice.label());
  r += "Motions (surge, heave, pitch of the crane hull G1 and of the cargo G2) are displacements from each model's "
       "static equilibrium; the other outputs are absolute. RMS values are about the static value; statistics are " +
       window_text(ref) + ".\n\n";
  r += "## Static equilibrium\n\n" + static_table(c) + "\n";
  r += "## Time histories\n\n";
  for (const std::string& name : crane_chart_names()) r += fmt::format("![{0}]({0}.png)\n\n", name);
  r += "## Maximum and RMS of each output\n\n" + extremes_table(c) + "\n";
  r += fmt::format("## Differences relative to {}\n\nmax |Δ| and RMS of Δ = model − {}, sample by sample, {}.\n\n",
                   ref.choice.label(), ref.choice.label(), window_text(ref));
  r += differences_table(c) + "\n";
  r += "## Wire rope\n\nThe dynamic amplification factor is the maximum tension over the whole run divided by the "
       "static tension.\n\n" + wire_table(c) + "\n";
  r += "## Solver costs\n\nWall time of the integration alone; real-time factor = simulated time / wall time.\n\n" +
       cost_table(c) + "\n";
  r += "Files: ";
  for (const ModelRun& run : c.runs) r += fmt::format("`{}`, ", timeseries_name(run));
  r += "`summary.json`; every chart with its gnuplot script (`NAME.gp`).\n";
  return r;
}

std::string compare_json(const Comparison& c) {
  JsonWriter json;
  json.begin_object();
  json.field("command", "compare");
  json.key("provenance").begin_object();
  write_settings_json(json, c.context);
  json.end_object();
  json.field("reference_model", reference_run(c).choice.label());
  json.field("reference_note", "the finest model of this comparison, not a converged reference");
  json.key("models").begin_array();
  const auto series = crane_series();
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    json.begin_object();
    write_model_json(json, *c.context.scene, c.runs[m]);
    json.field("timeseries", timeseries_name(c.runs[m]));
    json.key("differences_to_reference").begin_object();
    for (std::size_t i = 0; i < series.size(); ++i) {
      json.key(series[i].column).begin_object();
      json.field("max_abs", c.differences[m][i].max_abs).field("rms", c.differences[m][i].rms);
      json.end_object();
    }
    json.end_object();
    json.end_object();
  }
  json.end_array();
  json.end_object();
  return json.str();
}

std::string compare_text(const Comparison& c) {
  const ModelRun& ref = reference_run(c);
  const std::size_t heave = series_index("cargo_heave_m");
  std::string t = fmt::format("scene       {}\nsettings    {}\nstatistics  {}; differences to {}\n\n", c.context.scene_file,
                              settings_text(c.context), window_text(ref), ref.choice.label());
  t += fmt::format("{:<12} {:>5} {:>10} {:>11} {:>11} {:>8} {:>12} {:>14} {:>9} {:>11}\n", "model", "DOFs", "draft [m]",
                   "trim [deg]", "tip v [m]", "DAF", "cargo RMS", "cargo max|d|", "wall [s]", "x real time");
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    const ModelRun& run = c.runs[m];
    const coupling::CraneOutputs& o = run.static_outputs();
    t += fmt::format("{:<12} {:>5} {:>10.4f} {:>+11.4f} {:>+11.5f} {:>8.4f} {:>12.5g} {:>14} {:>9.3g} {:>11.4g}\n",
                     run.choice.label(), run.elastic_dof, draft_at_mid_length(*c.context.scene, o), o.hull.z() * degrees,
                     o.tip_deflection.y(), run.amplification, run.stats[heave].rms,
                     m == c.reference ? std::string("(reference)") : fmt::format("{:.4g}", c.differences[m][heave].max_abs),
                     run.result.stats.wall_seconds, run.real_time_factor);
  }
  t += "(cargo RMS and max|d|: cargo heave [m] about static equilibrium; DAF: wire tension max / static)\n";
  t += fmt::format("note: {} is the finest model of this comparison, not a converged reference\n", ref.choice.label());
  return t;
}

}  // namespace ffrf::app
