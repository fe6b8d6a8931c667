// `ffrf recommend SCENE --tolerance 1%`: the cheapest boom model and integrator whose error on the
// chosen outputs stays within the tolerance, decided by physics first (recommend_reasoning.hpp) and
// proved by verification runs against the converged reference (recommend_candidates.hpp). Prints
// the decision (or --json); --out DIR gets recommendation.md and recommendation.json, written
// completely or not at all. Exit 0 with a recommendation, 1 when no candidate meets the tolerance,
// 2 for bad input, 3 when the reference's solver fails.
#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "app/crane_commands.hpp"
#include "app/crane_run.hpp"
#include "app/output_directory.hpp"
#include "app/recommend_report.hpp"
#include "cases/scene_loader.hpp"

namespace ffrf::app {
namespace {

struct RecommendOptions {
  std::string scene;
  std::string tolerance = "1%";
  std::string outputs;  // empty: by scene kind
  std::optional<double> duration;
  ReferenceOptions reference;
  bool json = false;
  std::string out;
};

int bad_input(const std::string& message) {
  fmt::print(stderr, "ffrf recommend: error: {}\n", message);
  return exit_bad_input;
}

// "1%" → 0.01, "0.01" → 0.01; nothing when not a number in (0, 1).
std::optional<double> parse_tolerance(std::string text) {
  double scale = 1.0;
  if (!text.empty() && text.back() == '%') {
    text.pop_back();
    scale = 0.01;
  }
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size()) return std::nullopt;
  value *= scale;
  if (!(value > 0.0 && value < 1.0)) return std::nullopt;
  return value;
}

std::optional<std::vector<coupling::OutputChannel>> parse_outputs(const std::string& text, std::string& error) {
  std::vector<coupling::OutputChannel> outputs;
  std::stringstream stream(text);
  std::string item;
  std::string names;
  for (const auto channel : coupling::all_channels) names += (names.empty() ? "" : ",") + std::string(coupling::channel_name(channel));
  while (std::getline(stream, item, ',')) {
    bool found = false;
    for (const auto channel : coupling::all_channels) {
      if (coupling::channel_name(channel) == item) {
        outputs.push_back(channel);
        found = true;
      }
    }
    if (!found) {
      error = fmt::format("--outputs {}: unknown output '{}'; choose from {}", text, item, names);
      return std::nullopt;
    }
  }
  if (outputs.empty()) {
    error = fmt::format("--outputs {}: no output given; choose from {}", text, names);
    return std::nullopt;
  }
  return outputs;
}


int run_recommend(const RecommendOptions& options) {
  const std::optional<cases::Scene> scene = load_crane_scene(options.scene, "recommend");
  if (!scene) return exit_bad_input;
  const std::optional<double> tolerance = parse_tolerance(options.tolerance);
  if (!tolerance) {
    return bad_input(fmt::format("--tolerance {}: not a tolerance (valid range (0, 1), or a percentage like 1%)", options.tolerance));
  }
  RecommendRequest request;
  request.tolerance = *tolerance;
  if (options.outputs.empty()) {
    request.outputs = default_recommend_outputs(*scene);
  } else {
    std::string error;
    const auto outputs = parse_outputs(options.outputs, error);
    if (!outputs) return bad_input(error);
    request.outputs = *outputs;
  }
  request.duration = options.duration.value_or(scene->simulation.duration);
  if (!(request.duration >= scene->simulation.output_interval) || !std::isfinite(request.duration)) {
    return bad_input(fmt::format("--duration {}: shorter than one output interval of the scene ({} s) (valid range [{}, inf) s)",
                                 request.duration, scene->simulation.output_interval, scene->simulation.output_interval));
  }
  if (const auto error = reference_options_error(options.reference)) return bad_input(*error);
  request.reference = options.reference;
  std::optional<StagedDirectory> out;
  if (!options.out.empty()) out.emplace(options.out, "recommendation.json");
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  Recommendation rec;
  try {
    rec = recommend(*scene, request, [&](const std::string& what) {
      if (terminal) fmt::print(stderr, "\r\033[Kffrf recommend: {}", what);
    });
    if (terminal) fmt::print(stderr, "\r\033[K");
  } catch (const cases::SceneError& error) {
    for (const auto& problem : error.problems()) fmt::print(stderr, "{}\n", cases::format_problem(problem));
    return bad_input(fmt::format("{}: the scene cannot make the reference crane", options.scene));
  } catch (const coupling::SolverFailure& failure) {
    fmt::print(stderr, "ffrf recommend: solver failure (reference, {}): {}\n", coupling::to_string(failure.kind()), failure.what());
    if (out) fmt::print(stderr, "ffrf recommend: nothing written to {}\n", options.out);
    return exit_solver_failure;
  }
  const RecommendContext context{options.scene, &*scene, request};
  if (out) {
    out->write("recommendation.md", recommend_markdown(context, rec));
    out->write("recommendation.json", recommend_json(context, rec));
    out->commit();
  }
  fmt::print("{}", options.json ? recommend_json(context, rec) : recommend_text(context, rec));
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
  sub->add_option("--tolerance", options->tolerance,
                  "Largest worst normalized RMS error over the outputs, in (0, 1) or as a percentage (1%)")
      ->capture_default_str();
  sub->add_option("--outputs", options->outputs,
                  "Comma-separated outputs the tolerance applies to (default: cargo_heave,cargo_pitch,crane_heave,"
                  "crane_pitch,wire_tension,joint_moment for a crane; tip_deflection for a hub)");
  sub->add_option("--duration", options->duration, "Simulated time [s] of every run (default: simulation.duration of the scene)");
  add_reference_options(*sub, options->reference);
  sub->add_flag("--json", options->json, "Print the JSON report on stdout instead of the text report");
  sub->add_option("--out", options->out, "Write recommendation.md and recommendation.json into this directory");
  return {sub, [options] { return run_recommend(*options); }};
}

}  // namespace ffrf::app
