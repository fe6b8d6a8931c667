// `ffrf run SCENE`: one crane model — static equilibrium, then dynamics (study::run_model). Prints
// the static report and a summary (or --json); --out DIR gets timeseries.csv, summary.json and the
// PNG charts with their gnuplot scripts, written completely or not at all (a chart with nothing to
// draw is left out, one gnuplot fails on is named: summary.json's "charts" and stderr say which).
// Exit 2 for bad input, 3 when a solver fails.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/radiation_option.hpp"
#include "app/commands.hpp"
#include "app/option_checks.hpp"
#include "report/boom_stress_report.hpp"
#include "report/chart_notes.hpp"
#include "report/crane_charts.hpp"
#include "report/gnuplot.hpp"
#include "report/output_directory.hpp"
#include "report/run_report.hpp"
#include "report/irregular_report.hpp"
#include "scene/scene_key.hpp"
#include "study/work_limits.hpp"

namespace ffrf::app {
namespace {

struct RunOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  ModelOptions model;
  std::optional<double> spin_rate;  // overrides hub.spin_rate
  std::string radiation;            // overrides bem.radiation_model
  DynamicsOptions dynamics;
  bool json = false;
  std::string out;
};

void write_outputs(report::StagedDirectory& out, const report::RunContext& context, const study::ModelRun& run) {
  out.write("timeseries.csv", report::timeseries_csv(run));
  if (run.irregular) out.write("response_spectra.csv", report::response_spectra_csv(*run.irregular));
  report::ChartSet charts;
  charts.sources = {{"timeseries.csv", run.choice.label(), run.choice.kind != scene::BoomKind::rigid, false}};
  charts.names = report::crane_chart_names(*context.scene);
  charts.subtitle = fmt::format("{}, {}, {} (rtol {:g})", context.scene->name.empty() ? context.scene_file : context.scene->name,
                                run.choice.label(), solve::to_string(context.settings.kind), context.settings.relative_tolerance);
  charts.command = "ffrf run --out";
  report::draw_crane_charts(out, charts);
  std::vector<report::StressChartSource> stress;
  if (!run.result.boom_stress.empty()) {
    out.write("boom_stress.csv", report::boom_stress_csv(run.result.boom_stress));
    stress.push_back({"boom_stress.csv", run.choice.label(), false});
  }
  report::draw_boom_stress_chart(out, stress, *context.scene, charts.subtitle, charts.command);
  out.write("summary.json", report::with_charts_json(report::run_json(context, run), out));
  out.commit();
  fmt::print(stderr, "{}", report::chart_notes_text("run", out));
}

int run_crane(const RunOptions& options) {
  std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "run", true);
  if (!scene) return exit_bad_input;
  scene::BoomChoice choice;
  multibody::RunSettings settings;
  try {
    if (options.spin_rate) {
      if (!scene->hub) throw BadOption(fmt::format("--spin-rate {}: the scene has no [hub] to spin", *options.spin_rate));
      if (!std::isfinite(*options.spin_rate)) {
        throw BadOption(fmt::format("--spin-rate {}: not a finite angular velocity (valid range (-inf, inf) rad/s)", *options.spin_rate));
      }
      scene->hub->spin_rate = *options.spin_rate;
    }
    apply_radiation_option(*scene, options.radiation);
    choice = boom_choice(options.model, default_boom_choice(*scene));
    settings = integrator_settings(options.dynamics, *scene);
  } catch (const BadOption& error) {
    return bad_input("run", error.what());
  }
  report::RunContext context = report::make_context(options.scene, *scene, settings);
  try {
    context.warnings = study::model_warnings(*scene, choice);
  } catch (const std::exception& error) {  // the boom's modes could not be solved: no advice, the run decides
    fmt::print(stderr, "ffrf run: note: no modelling advice ({})\n", error.what());
  }
  fmt::print(stderr, "{}", report::warnings_text(context.warnings));

  // The input is valid: from here on, DIR's old completeness marker no longer describes DIR.
  std::optional<report::StagedDirectory> out;
  if (!options.out.empty()) {
    report::png_terminal();  // fail before the computation when gnuplot is missing
    out.emplace(options.out, "summary.json");
  }
  study::ModelRun run;
  try {
    run = study::run_model(*scene, choice, settings, nullptr, [&](const study::ModelRun& prepared) {
      if (!options.json) fmt::print("{}{}", report::run_header_text(context, prepared), report::static_report(*scene, prepared));
      std::fflush(stdout);
    });
  } catch (const scene::SceneError& error) {
    return scene_error("run", options.scene, error, "this crane");
  } catch (const solve::SolverFailure& failure) {
    if (options.json) fmt::print("{}", report::failure_json(context, choice.label(), failure));
    return solver_failure("run", std::string(solve::to_string(failure.kind())), failure, options.out);
  }
  if (out) write_outputs(*out, context, run);
  fmt::print("{}", options.json ? report::run_json(context, run) : report::dynamics_text(*scene, run));
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {}\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_run_command(CLI::App& parent) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* sub = parent.add_subcommand("run", "Static equilibrium, then the dynamics of one crane model in the scene's waves");
  sub->add_option("scene", options->scene, "Scene file (TOML) with [hull], [boom], [cargo] and [wire], or a [hub]")->required();
  add_set_option(*sub, options->set);
  add_model_options(*sub, options->model);
  sub->add_option("--spin-rate", options->spin_rate, "Final spin rate of a hub scene [rad/s] (default: hub.spin_rate)")
      ->check(scene_key_range(scene::scene_key("hub.spin_rate")));
  add_radiation_option(*sub, options->radiation);
  add_dynamics_options(*sub, options->dynamics);
  sub->add_flag("--json", options->json, "Print the JSON summary on stdout instead of the text report");
  sub->add_option("--out", options->out,
                  "Write timeseries.csv, summary.json and PNG charts (with their gnuplot scripts) into this directory");
  return {sub, [options] { return run_crane(*options); }};
}

}  // namespace ffrf::app
