// `ffrf compare SCENE`: the converged reference first, then the boom models of compared_models()
// (rigid, nodal N = 1 as in the paper, nodal N = 16, modal k = 1, 2, 4 with and without static
// modes) on one scene, each from its static equilibrium, with their errors against the reference:
// a text summary (or --json) and, with --out DIR, each model's time series, overlaid charts,
// summary.json and report.md, written completely or not at all. Exit 2 for bad input, 3 when a
// solver fails.
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/compare_report.hpp"
#include "app/crane_charts.hpp"
#include "app/crane_commands.hpp"
#include "app/gnuplot.hpp"
#include "app/output_directory.hpp"
#include "cases/scene_loader.hpp"

namespace ffrf::app {
namespace {

struct CompareOptions {
  std::string scene;
  DynamicsOptions dynamics;
  ReferenceOptions reference;
  bool json = false;
  std::string out;
};

void write_outputs(StagedDirectory& out, const Comparison& comparison) {
  std::vector<ChartSource> sources;
  for (std::size_t m = 0; m < comparison.runs.size(); ++m) {
    const ModelRun& run = comparison.runs[m];
    out.write(timeseries_name(run), timeseries_csv(run));
    if (comparison.plotted[m]) sources.push_back({timeseries_name(run), run.choice.label()});
  }
  out.write(reference_timeseries_name, timeseries_csv(comparison.reference_run));
  sources.push_back({reference_timeseries_name, reference_label(comparison.reference)});
  const RunContext& c = comparison.context;
  draw_crane_charts(out, sources,
                    fmt::format("{}, {} (rtol {:g})", c.scene->name.empty() ? c.scene_file : c.scene->name,
                                coupling::to_string(c.settings.kind), c.settings.relative_tolerance),
                    "ffrf compare --out");
  out.write("report.md", compare_markdown(comparison));
  out.write("summary.json", compare_json(comparison));
  out.commit();
}

int run_compare(const CompareOptions& options) {
  const std::optional<cases::Scene> scene = load_crane_scene(options.scene, "compare");
  if (!scene) return exit_bad_input;
  const SettingsOrError settings = integrator_settings(options.dynamics, *scene);
  if (!settings.settings) {
    fmt::print(stderr, "ffrf compare: error: {}\n", settings.error);
    return exit_bad_input;
  }
  if (const auto error = reference_options_error(options.reference)) {
    fmt::print(stderr, "ffrf compare: error: {}\n", *error);
    return exit_bad_input;
  }
  std::optional<StagedDirectory> out;
  if (!options.out.empty()) {
    png_terminal();  // fail before the computation when gnuplot is missing
    out.emplace(options.out, "summary.json");
  }
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  const auto solver_failure = [&](const std::string& what, const coupling::SolverFailure& failure) {
    fmt::print(stderr, "ffrf compare: solver failure ({}): {}\n", what, failure.what());
    if (out) fmt::print(stderr, "ffrf compare: nothing written to {}\n", options.out);
    return exit_solver_failure;
  };
  const auto scene_error = [&](const std::string& what, const cases::SceneError& error) {
    for (const auto& problem : error.problems()) fmt::print(stderr, "{}\n", cases::format_problem(problem));
    fmt::print(stderr, "ffrf compare: error: {}: the scene cannot make the {} crane\n", options.scene, what);
    return exit_bad_input;
  };
  if (terminal) fmt::print(stderr, "ffrf compare: converged reference (nodal, refined level by level) ...\n");
  cases::ConvergedReference reference;
  try {
    reference = compute_reference(*scene, options.reference, settings.settings->duration);
  } catch (const cases::SceneError& error) {
    return scene_error("reference", error);
  } catch (const coupling::SolverFailure& failure) {
    return solver_failure("reference", failure);
  }
  std::vector<ModelRun> runs;
  std::vector<bool> plotted;
  for (const ComparedModel& model : compared_models()) {
    if (terminal) fmt::print(stderr, "\r\033[Kffrf compare: {} ...\n", model.choice.label());
    try {
      runs.push_back(run_model(*scene, model.choice, *settings.settings));
      plotted.push_back(model.plotted);
    } catch (const cases::SceneError& error) {
      return scene_error(model.choice.label(), error);
    } catch (const coupling::SolverFailure& failure) {
      return solver_failure(model.choice.label(), failure);
    }
  }
  const Comparison comparison = make_comparison(make_context(options.scene, *scene, *settings.settings),
                                                std::move(reference), std::move(runs), std::move(plotted));
  if (out) write_outputs(*out, comparison);
  fmt::print("{}", options.json ? compare_json(comparison) : compare_text(comparison));
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {} (report.md)\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_compare_command(CLI::App& parent) {
  auto options = std::make_shared<CompareOptions>();
  // CVODE on the minimal coordinates by default, as `ffrf run` (the faster of the two on this
  // scene; IDA with --integrator ida).
  options->dynamics.integrator = "cvode";
  CLI::App* sub = parent.add_subcommand(
      "compare", "Rigid, nodal N = 1 (the paper's model), nodal N = 16 and modal k = 1, 2, 4 (with and without static modes) booms on "
      "one scene against a converged reference: charts, errors, costs");
  sub->add_option("scene", options->scene, "Scene file (TOML) with [hull], [boom], [cargo] and [wire]")->required();
  add_dynamics_options(*sub, options->dynamics);
  add_reference_options(*sub, options->reference);
  sub->add_flag("--json", options->json, "Print the JSON summary on stdout instead of the text summary");
  sub->add_option("--out", options->out,
                  "Write report.md, summary.json, each model's timeseries_MODEL.csv and the overlaid PNG charts (with "
                  "their gnuplot scripts) into this directory");
  return {sub, [options] { return run_compare(*options); }};
}

}  // namespace ffrf::app
