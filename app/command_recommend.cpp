// `ffrf recommend SCENE --tolerance 1%`: the cheapest boom model and integrator whose error on the
// judged outputs stays within the tolerance, decided by physics first and proved by verification
// runs against the converged reference (study::recommend). Prints the decision (or --json); --out
// DIR gets recommendation.md and recommendation.json, written completely or not at all. Exit 0 with
// a recommendation, 1 when no candidate meets the tolerance, 2 for bad input, 3 when the
// reference's solver fails.
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/radiation_option.hpp"
#include "scene/scene_key.hpp"
#include "study/radiation_compare.hpp"
#include "app/commands.hpp"
#include "app/option_checks.hpp"
#include "report/output_directory.hpp"
#include "report/recommend_report.hpp"

namespace ffrf::app {
namespace {

struct RecommendOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  std::string tolerance = "1%";
  std::string outputs;  // empty: the judged outputs of the scene
  std::string radiation;  // overrides bem.radiation_model
  std::optional<double> duration;
  study::ReferenceOptions reference;
  bool json = false;
  std::string out;
};

// "cargo_heave,wire_tension" → the channels (study::channels_named); throws BadOption naming an unknown one.
std::vector<multibody::OutputChannel> parse_outputs(const std::string& text) {
  std::vector<std::string> names;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) names.push_back(item);
  try {
    return study::channels_named(names);
  } catch (const study::SettingError& error) {
    throw BadOption(option_message(error));
  }
}

int run_recommend(const RecommendOptions& options) {
  std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "recommend", true);
  if (!scene) return exit_bad_input;
  study::RecommendRequest request;
  multibody::RunSettings radiation_settings;
  try {
    apply_radiation_option(*scene, options.radiation);
    request.tolerance = parse_tolerance(options.tolerance);
    if (!options.outputs.empty()) request.outputs = parse_outputs(options.outputs);
    DynamicsOptions dynamics;  // checks the duration against the scene
    dynamics.duration = options.duration;
    radiation_settings = integrator_settings(dynamics, *scene);
    request.duration = radiation_settings.duration;
    request.reference = options.reference;
    study::validate(request.reference);
  } catch (const BadOption& error) {
    return bad_input("recommend", error.what());
  } catch (const study::SettingError& error) {
    return bad_input("recommend", option_message(error));
  }
  std::optional<report::StagedDirectory> out;
  if (!options.out.empty()) out.emplace(options.out, "recommendation.json");
  study::Recommendation rec;
  try {
    rec = study::recommend(*scene, request, [&](const std::string& what) { progress("recommend", what); });
    progress("recommend", "");
  } catch (const scene::SceneError& error) {
    return scene_error("recommend", options.scene, error, "the reference crane");
  } catch (const solve::SolverFailure& failure) {
    return solver_failure("recommend", "reference, " + std::string(solve::to_string(failure.kind())), failure, options.out);
  }
  // A scene with BEM coefficients: the cheapest radiation model within the tolerance, verified against
  // the Cummins convolution on the chosen boom model.
  std::optional<study::RadiationComparison> radiation;
  if (scene->bem && rec.chosen) {
    try {
      progress("recommend", "radiation models (constant, state-space, convolution)");
      radiation = study::compare_radiation(*scene, rec.candidates[*rec.chosen].choice, radiation_settings, request.tolerance);
      progress("recommend", "");
    } catch (const scene::SceneError& error) {
      return scene_error("recommend", options.scene, error, "the radiation-model crane");
    } catch (const solve::SolverFailure& failure) {
      return solver_failure("recommend", "radiation models", failure, options.out);
    }
  }
  const report::RecommendContext context{options.scene, &*scene, request.tolerance};
  if (out) {
    out->write("recommendation.md", report::recommend_markdown(context, rec));
    out->write("recommendation.json", report::recommend_json(context, rec));
    out->commit();
  }
  fmt::print("{}", options.json ? report::recommend_json(context, rec) : report::recommend_text(context, rec));
  if (radiation && !options.json) fmt::print("{}", study::radiation_comparison_text(*radiation));
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {}\n", options.out);
  return rec.chosen ? exit_ok : exit_failure;
}

}  // namespace

Command add_recommend_command(CLI::App& parent) {
  auto options = std::make_shared<RecommendOptions>();
  CLI::App* sub = parent.add_subcommand(
      "recommend", "The cheapest boom model and integrator whose error stays within a tolerance: reasoned from the "
                   "physics, then proved by verification runs against a converged reference");
  sub->add_option("scene", options->scene, "Scene file (TOML) of a crane or a hub")->required();
  add_set_option(*sub, options->set);
  sub->add_option("--tolerance", options->tolerance,
                  "Largest worst normalized RMS error over the outputs, in (0, 1) or as a percentage (1%)")
      ->capture_default_str();
  sub->add_option("--outputs", options->outputs,
                  "Comma-separated outputs the tolerance applies to (default: cargo_heave,cargo_pitch,crane_heave,"
                  "crane_pitch,wire_tension,joint_moment for a crane; tip_deflection for a hub)");
  sub->add_option("--duration", options->duration, "Simulated time [s] of every run (default: simulation.duration of the scene)")
      ->check(scene_key_range(scene::scene_key("simulation.duration")));
  add_reference_options(*sub, options->reference);
  add_radiation_option(*sub, options->radiation);
  sub->add_flag("--json", options->json, "Print the JSON report on stdout instead of the text report");
  sub->add_option("--out", options->out, "Write recommendation.md and recommendation.json into this directory");
  return {sub, [options] { return run_recommend(*options); }};
}

}  // namespace ffrf::app
