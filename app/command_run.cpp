// `ffrf run SCENE`: one crane model — static equilibrium, then dynamics. Prints the static report
// and a summary (or --json); --out DIR gets timeseries.csv, summary.json and the PNG charts with
// their gnuplot scripts, written completely or not at all. Exit 2 for bad input, 3 when a solver fails.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/crane_charts.hpp"
#include "app/crane_commands.hpp"
#include "app/crane_run.hpp"
#include "app/gnuplot.hpp"
#include "app/output_directory.hpp"
#include "app/run_report.hpp"
#include "cases/scene_loader.hpp"

namespace ffrf::app {
namespace {

struct RunOptions {
  std::string scene;
  std::string boom = "nodal";
  std::optional<int> elements;
  int modes = 4;
  bool static_modes = false;
  std::string stiffening;  // empty: the scene's boom.stiffening
  std::optional<double> spin_rate;  // overrides hub.spin_rate
  DynamicsOptions dynamics;
  bool json = false;
  std::string out;
};

int bad_input(const std::string& message) {
  fmt::print(stderr, "ffrf run: error: {}\n", message);
  return exit_bad_input;
}

// The boom choice from the options, or the message naming the bad option.
std::optional<std::string> boom_choice(const RunOptions& options, const cases::Scene& scene, cases::BoomChoice& choice) {
  const auto kind = cases::parse_boom_kind(options.boom);
  if (!kind) return fmt::format("--boom {}: unknown boom model; choose one of {}", options.boom, cases::boom_kind_choices());
  choice.kind = *kind;
  choice.elements = options.elements.value_or(scene.boom.mesh.element_count);
  if (choice.elements < 1) {
    return fmt::format("--elements {}: not a valid element count (valid range [1, inf))", choice.elements);
  }
  choice.modes = options.modes;
  choice.static_modes = options.static_modes;
  if (!options.stiffening.empty()) {
    choice.stiffening = cases::parse_stiffening(options.stiffening);
    if (!choice.stiffening) {
      return fmt::format("--stiffening {}: unknown stiffening; choose one of none, static, centrifugal, both", options.stiffening);
    }
  }
  if (choice.kind == cases::BoomKind::modal) {
    const int dof = 3 * choice.elements;  // (u, v, φ) per node, the root node clamped
    if (choice.modes < 1 || choice.modes >= dof) {
      return fmt::format("--modes {}: not a valid mode count for N = {} elements ({} elastic DOFs) (valid range [1, {}])",
                         choice.modes, choice.elements, dof, dof - 1);
    }
  }
  return std::nullopt;
}

void write_outputs(StagedDirectory& out, const RunContext& context, const ModelRun& run) {
  out.write("timeseries.csv", timeseries_csv(run));
  draw_crane_charts(out, {{"timeseries.csv", run.choice.label()}},
                    fmt::format("{}, {}, {} (rtol {:g})", context.scene->name.empty() ? context.scene_file : context.scene->name,
                                run.choice.label(), coupling::to_string(context.settings.kind),
                                context.settings.relative_tolerance),
                    "ffrf run --out");
  out.write("summary.json", run_json(context, run));
  out.commit();
}

int run_crane(const RunOptions& options) {
  std::optional<cases::Scene> scene = load_crane_scene(options.scene, "run");
  if (!scene) return exit_bad_input;
  if (options.spin_rate) {
    if (!scene->hub) return bad_input(fmt::format("--spin-rate {}: the scene has no [hub] to spin", *options.spin_rate));
    if (!std::isfinite(*options.spin_rate)) {
      return bad_input(fmt::format("--spin-rate {}: not a finite angular velocity (valid range (-inf, inf) rad/s)", *options.spin_rate));
    }
    scene->hub->spin_rate = *options.spin_rate;
  }
  cases::BoomChoice choice;
  if (const auto error = boom_choice(options, *scene, choice)) return bad_input(*error);
  const SettingsOrError settings = integrator_settings(options.dynamics, *scene);
  if (!settings.settings) return bad_input(settings.error);
  RunContext context = make_context(options.scene, *scene, *settings.settings);
  try {
    context.warnings = model_warnings(*scene, choice);
  } catch (const std::exception& error) {  // the boom's modes could not be solved: no advice, the run decides
    fmt::print(stderr, "ffrf run: note: no modelling advice ({})\n", error.what());
  }
  fmt::print(stderr, "{}", warnings_text(context.warnings));

  // The input is valid: from here on, DIR's old completeness marker no longer describes DIR.
  std::optional<StagedDirectory> out;
  if (!options.out.empty()) {
    png_terminal();  // fail before the computation when gnuplot is missing
    out.emplace(options.out, "summary.json");
  }
  ModelRun run;
  try {
    run = run_model(*scene, choice, *settings.settings, [&](const ModelRun& partial) {
      if (!options.json) fmt::print("{}{}", run_header_text(context, partial), static_report(*scene, partial));
      std::fflush(stdout);
    });
  } catch (const cases::SceneError& error) {
    for (const auto& problem : error.problems()) fmt::print(stderr, "{}\n", cases::format_problem(problem));
    return bad_input(fmt::format("{}: the scene cannot make this crane", options.scene));
  } catch (const coupling::SolverFailure& failure) {
    fmt::print(stderr, "ffrf run: solver failure ({}): {}\n", coupling::to_string(failure.kind()), failure.what());
    if (out) fmt::print(stderr, "ffrf run: nothing written to {}\n", options.out);
    if (options.json) fmt::print("{}", failure_json(context, choice.label(), failure));
    return exit_solver_failure;
  }
  if (out) write_outputs(*out, context, run);
  fmt::print("{}", options.json ? run_json(context, run) : dynamics_text(run));
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {}\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_run_command(CLI::App& parent) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* sub = parent.add_subcommand("run", "Static equilibrium, then the dynamics of one crane model in the scene's waves");
  sub->add_option("scene", options->scene, "Scene file (TOML) with [hull], [boom], [cargo] and [wire]")->required();
  sub->add_option("--boom", options->boom, "Boom model " + cases::boom_kind_choices())->capture_default_str();
  sub->add_option("--elements,-N", options->elements, "Number of beam elements (default: boom.elements of the scene)");
  sub->add_option("--modes,-k", options->modes, "Number of vibration modes of the modal boom")->capture_default_str();
  sub->add_flag("--static-modes", options->static_modes, "Add the tip static correction modes to the modal boom");
  sub->add_option("--spin-rate", options->spin_rate, "Final spin rate of a hub scene [rad/s] (default: hub.spin_rate)");
  sub->add_option("--stiffening", options->stiffening,
                  "Geometric stiffening none|static|centrifugal|both (default: boom.stiffening of the scene)");
  add_dynamics_options(*sub, options->dynamics);
  sub->add_flag("--json", options->json, "Print the JSON summary on stdout instead of the text report");
  sub->add_option("--out", options->out,
                  "Write timeseries.csv, summary.json and PNG charts (with their gnuplot scripts) into this directory");
  return {sub, [options] { return run_crane(*options); }};
}

}  // namespace ffrf::app
