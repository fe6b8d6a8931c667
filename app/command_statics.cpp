// `ffrf statics SCENE`: the static equilibrium of one crane model without running the dynamics
// (study::solve_statics, the run pipeline's equilibrium): hull offsets, draft and trim, cargo
// position, wire tension and stretch, boom root moment and tip deflection, the force balance and
// how KINSOL reached it. --json prints the JSON document; --out DIR gets statics.json, written
// completely or not at all. Exit 2 for bad input, 3 when the solver fails or the equilibrium puts a
// deck edge or the cargo under water.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/radiation_option.hpp"
#include "report/output_directory.hpp"
#include "report/statics_report.hpp"
#include "study/statics.hpp"

namespace ffrf::app {
namespace {

struct StaticsOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  ModelOptions model;
  std::string radiation;  // overrides bem.radiation_model
  bool json = false;
  std::string out;
};

int run_statics(const StaticsOptions& options) {
  std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "statics", true);
  if (!scene) return exit_bad_input;
  scene::BoomChoice choice;
  try {
    apply_radiation_option(*scene, options.radiation);
    choice = boom_choice(options.model, default_boom_choice(*scene));
  } catch (const BadOption& error) {
    return bad_input("statics", error.what());
  }
  // The input is valid: from here on, DIR's old completeness marker no longer describes DIR.
  std::optional<report::StagedDirectory> out;
  if (!options.out.empty()) out.emplace(options.out, "statics.json");
  study::StaticsResult result;
  try {
    result = study::solve_statics(*scene, choice);
  } catch (const scene::SceneError& error) {
    return scene_error("statics", options.scene, error, "this crane");
  } catch (const solve::SolverFailure& failure) {
    if (options.json) fmt::print("{}", report::statics_failure_json(options.scene, *scene, choice.label(), failure));
    return solver_failure("statics", std::string(solve::to_string(failure.kind())), failure, options.out);
  }
  const std::string json = report::statics_json(options.scene, *scene, result);
  if (out) {
    out->write("statics.json", json);
    out->commit();
  }
  fmt::print("{}", options.json ? json : report::statics_text(options.scene, *scene, result));
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {}\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_statics_command(CLI::App& parent) {
  auto options = std::make_shared<StaticsOptions>();
  CLI::App* sub = parent.add_subcommand("statics", "The static equilibrium of one crane model in calm water, without the dynamics");
  sub->add_option("scene", options->scene, "Scene file (TOML) with [hull], [boom], [cargo] and [wire], or a [hub]")->required();
  add_set_option(*sub, options->set);
  add_model_options(*sub, options->model);
  add_radiation_option(*sub, options->radiation);
  sub->add_flag("--json", options->json, "Print the JSON document on stdout instead of the text report");
  sub->add_option("--out", options->out, "Write statics.json into this directory");
  return {sub, [options] { return run_statics(*options); }};
}

}  // namespace ffrf::app
