// `ffrf compare SCENE`: the converged reference, then the boom models of study::compared_models()
// on one scene, each from the scene's initial state, with their errors against the reference
// (study::compare) and the verdict against --tolerance (default 1 %): a text summary (or --json) and, with --out DIR, each model's time series,
// overlaid charts, summary.json and report.md, written completely or not at all. Exit 2 for bad
// input, 3 when a solver fails.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/radiation_option.hpp"
#include "study/radiation_compare.hpp"
#include "app/commands.hpp"
#include "report/boom_stress_report.hpp"
#include "report/chart_notes.hpp"
#include "report/compare_report.hpp"
#include "report/crane_charts.hpp"
#include "report/gnuplot.hpp"
#include "report/output_directory.hpp"
#include "report/reference_report.hpp"

namespace ffrf::app {
namespace {

struct CompareOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  DynamicsOptions dynamics;
  study::ReferenceOptions reference;
  std::string stiffening;
  std::string radiation;  // overrides bem.radiation_model
  std::string tolerance = "1%";
  bool json = false;
  std::string out;
};

void write_outputs(report::StagedDirectory& out, const report::RunContext& context, const study::Comparison& comparison) {
  const scene::Scene& scene = *context.scene;
  report::ChartSet charts;
  for (std::size_t m = 0; m < comparison.runs.size(); ++m) {
    const study::ModelRun& run = comparison.runs[m];
    out.write(report::timeseries_name(run), report::timeseries_csv(run));
    if (comparison.plotted[m]) {
      charts.sources.push_back({report::timeseries_name(run), run.choice.label(), run.choice.kind != scene::BoomKind::rigid, false});
    }
  }
  out.write(report::reference_timeseries_name, report::timeseries_csv(comparison.reference.run));
  charts.sources.push_back({report::reference_timeseries_name, report::reference_label(comparison.reference), true, true});
  charts.names = report::crane_chart_names(scene);
  charts.subtitle = fmt::format("{}, {} (rtol {:g})", scene.name.empty() ? context.scene_file : scene.name,
                                solve::to_string(context.settings.kind), context.settings.relative_tolerance);
  charts.command = "ffrf compare --out";
  charts.window_start = comparison.window_start;
  charts.differences_csv = "differences.csv";
  charts.difference_floors = report::difference_floors(comparison, charts.names);
  out.write(charts.differences_csv, report::difference_csv(comparison, charts.names));
  report::draw_crane_charts(out, charts);
  std::vector<report::StressChartSource> stress;
  for (std::size_t m = 0; m < comparison.runs.size(); ++m) {
    const study::ModelRun& run = comparison.runs[m];
    if (!comparison.plotted[m] || run.result.boom_stress.empty()) continue;
    const std::string name = "boom_stress_" + report::slug(run.choice.label()) + ".csv";
    out.write(name, report::boom_stress_csv(run.result.boom_stress));
    stress.push_back({name, run.choice.label(), false});
  }
  if (!comparison.reference.run.result.boom_stress.empty()) {
    out.write("boom_stress_reference.csv", report::boom_stress_csv(comparison.reference.run.result.boom_stress));
    stress.push_back({"boom_stress_reference.csv", report::reference_label(comparison.reference), true});
  }
  report::draw_boom_stress_chart(out, stress, scene, charts.subtitle, charts.command);
  out.write("report.md", report::compare_markdown(context, comparison) + report::charts_markdown(out));
  out.write("summary.json", report::with_charts_json(report::compare_json(context, comparison), out));
  out.commit();
  fmt::print(stderr, "{}", report::chart_notes_text("compare", out));
}

int run_compare(const CompareOptions& options) {
  std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "compare", true);
  if (!scene) return exit_bad_input;
  study::CompareRequest request;
  try {
    apply_radiation_option(*scene, options.radiation);
    request.stiffening = stiffening_option(options.stiffening);
    request.tolerance = parse_tolerance(options.tolerance);
    request.settings = integrator_settings(options.dynamics, *scene);
    request.reference = options.reference;
    study::validate(request.reference);
  } catch (const BadOption& error) {
    return bad_input("compare", error.what());
  } catch (const study::SettingError& error) {
    return bad_input("compare", option_message(error));
  }
  std::optional<report::StagedDirectory> out;
  if (!options.out.empty()) {
    report::png_terminal();  // fail before the computation when gnuplot is missing
    out.emplace(options.out, "summary.json");
  }
  std::string running;
  study::Comparison comparison;
  try {
    comparison = study::compare(*scene, request, [&](const std::string& what) {
      running = what;
      progress("compare", what == "reference" ? "converged reference (nodal, refined level by level) ..." : what + " ...", true);
    });
  } catch (const scene::SceneError& error) {
    return scene_error("compare", options.scene, error, "the " + running + " crane");
  } catch (const solve::SolverFailure& failure) {
    return solver_failure("compare", running, failure, options.out);
  }
  scene->boom.stiffening = comparison.stiffening;  // what every model ran with
  const report::RunContext context = report::make_context(options.scene, *scene, request.settings);
  // A scene with BEM coefficients: the radiation models compared on the chosen boom model (or the
  // most accurate one), like the boom models, against the Cummins convolution.
  std::optional<study::RadiationComparison> radiation;
  if (scene->bem) {
    const auto& verdict = comparison.verdict;
    const std::size_t boom = verdict.cheapest ? *verdict.cheapest : verdict.most_accurate.value_or(0);
    try {
      running = "radiation models";
      progress("compare", "radiation models (constant, state-space, convolution) ...", true);
      radiation = study::compare_radiation(*scene, comparison.runs[boom].choice, request.settings, request.tolerance);
    } catch (const scene::SceneError& error) {
      return scene_error("compare", options.scene, error, "the radiation-model crane");
    } catch (const solve::SolverFailure& failure) {
      return solver_failure("compare", running, failure, options.out);
    }
  }
  if (out) {
    if (radiation) out->write("radiation.txt", study::radiation_comparison_text(*radiation));
    write_outputs(*out, context, comparison);
  }
  fmt::print("{}", options.json ? report::compare_json(context, comparison) : report::compare_text(context, comparison));
  if (radiation && !options.json) fmt::print("{}", study::radiation_comparison_text(*radiation));
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {} (report.md)\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_compare_command(CLI::App& parent) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* sub = parent.add_subcommand(
      "compare", "Rigid, nodal N = 1 (the paper's model), nodal N = 16 and modal k = 1, 2, 4 (with and without static modes) booms on "
      "one scene against a converged reference: charts, errors, costs");
  sub->add_option("scene", options->scene, "Scene file (TOML) with [hull], [boom], [cargo] and [wire], or a [hub]")->required();
  add_set_option(*sub, options->set);
  add_dynamics_options(*sub, options->dynamics);
  add_reference_options(*sub, options->reference);
  add_stiffening_option(*sub, options->stiffening);
  add_radiation_option(*sub, options->radiation);
  add_tolerance_option(*sub, options->tolerance,
                       "a model passes when its worst normalized RMS error over the judged outputs is within it");
  sub->add_flag("--json", options->json, "Print the JSON summary on stdout instead of the text summary");
  sub->add_option("--out", options->out,
                  "Write report.md, summary.json, each model's timeseries_MODEL.csv and the overlaid PNG charts (with "
                  "their gnuplot scripts) into this directory");
  return {sub, [options] { return run_compare(*options); }};
}

}  // namespace ffrf::app
