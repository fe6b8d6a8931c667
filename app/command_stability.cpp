// `ffrf stability SCENE`: the stability map report — which method fails where (issue 5). Runs the
// experiments that apply to the scene (app/stability_section.hpp): explicit RK step limits (every
// scene), constraint drift per formulation (every scene: the clamp at B is a constraint), spin with
// and without centrifugal stiffening (a spinning [hub]), slack wire and snap loads (a cargo), the
// BDF order on undamped stiff modes (a hub with an undamped boom), the buckling margin (gravity and a
// cargo). Writes report.md (embedding the PNG charts), summary.json (every cell: status, failure
// kind, time, value) and the CSVs into --out DIR, completely or not at all; without --out the
// charts go to a temporary directory that is removed. Solver failures inside the experiments are
// results (red cells); bad input exits 2.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "app/crane_run.hpp"
#include "app/gnuplot.hpp"
#include "app/output_directory.hpp"
#include "app/stability_section.hpp"
#include "cases/scene_loader.hpp"

namespace ffrf::app {
namespace {

struct StabilityCommandOptions {
  std::string scene;
  std::string out;
  bool json = false;
  bool quick = false;
};

using SectionFunction = StabilitySection (*)(const cases::Scene&, const StabilityOptions&, const StagedDirectory&);

// The experiments that apply to the scene, in report order.
std::vector<SectionFunction> applicable_sections(const cases::Scene& scene) {
  std::vector<SectionFunction> sections{explicit_step_section, constraint_drift_section};
  const bool spins = scene.hub && scene.hub->motion != cases::HubMotion::fixed && scene.hub->spin_rate != 0.0;
  if (spins) sections.push_back(spin_section);
  if (scene.has_cargo()) sections.push_back(wire_section);
  if (scene.hub && scene.boom.damping_ratio == 0.0) sections.push_back(bdf_order_section);
  if (scene.has_cargo() && scene.environment.gravity > 0.0) sections.push_back(buckling_section);
  return sections;
}

std::string report_markdown(const cases::Scene& scene, const std::string& file, bool quick,
                            const std::vector<StabilitySection>& sections, double wall) {
  std::string md = fmt::format(
      "# Stability map: {}\n\nScene `{}`{}. Which method fails where: each experiment below names every failure "
      "(✅ held, with the number that says how well; ❌ the failure kind, when it was detected and the number behind "
      "it). docs/stability.md explains each failure, its detector and its remedy. Computed in {} s.\n\n",
      scene.name.empty() ? file : scene.name, file, quick ? " (--quick: fewer models, shorter horizons)" : "", shown(wall, 3));
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const StabilitySection& s = sections[i];
    md += fmt::format("## {}. {}\n\n**What was run.** {}\n\n{}\n", i + 1, s.title, s.provenance, s.table);
    for (const std::string& chart : s.charts) md += fmt::format("![{}]({})\n\n", chart, chart);
    md += fmt::format("**What it shows.** {}\n\n", s.finding);
  }
  return md;
}

std::string summary_json(const cases::Scene& scene, const std::string& file, bool quick,
                         const std::vector<StabilitySection>& sections, double wall) {
  JsonWriter json;
  json.begin_object();
  json.field("command", "stability");
  json.field("scene_file", file);
  json.field("scene_name", scene.name);
  json.field("quick", quick);
  json.field("wall_seconds", wall);
  json.key("sections").begin_object();
  for (const StabilitySection& section : sections) {
    json.key(section.key);
    write_section_json(json, section);
  }
  json.end_object();
  json.end_object();
  return json.str();
}

int run_stability(const StabilityCommandOptions& options) {
  const std::optional<cases::Scene> scene = load_crane_scene(options.scene, "stability");
  if (!scene) return exit_bad_input;
  png_terminal();  // fail before the computation when gnuplot is missing
  std::filesystem::path target = options.out;
  const bool temporary = options.out.empty();
  if (temporary) target = std::filesystem::temp_directory_path() / fmt::format("ffrf-stability-{}", ::getpid());
  StabilityOptions settings{options.quick, ::isatty(STDERR_FILENO) != 0};
  const auto start = std::chrono::steady_clock::now();
  std::vector<StabilitySection> sections;
  std::string report, summary;
  {
    StagedDirectory out(target, "summary.json");
    try {
      for (SectionFunction section : applicable_sections(*scene)) sections.push_back(section(*scene, settings, out));
    } catch (const cases::SceneError& error) {
      for (const auto& problem : error.problems()) fmt::print(stderr, "{}\n", cases::format_problem(problem));
      fmt::print(stderr, "ffrf stability: error: {}: the scene cannot make this crane\n", options.scene);
      return exit_bad_input;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report = report_markdown(*scene, options.scene, options.quick, sections, wall);
    summary = summary_json(*scene, options.scene, options.quick, sections, wall);
    out.write("report.md", report);
    out.write("summary.json", summary);
    out.commit();
  }
  if (temporary) std::filesystem::remove_all(target);
  fmt::print("{}", options.json ? summary : report);
  if (!temporary && !options.json) fmt::print("wrote {}\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_stability_command(CLI::App& parent) {
  auto options = std::make_shared<StabilityCommandOptions>();
  CLI::App* sub = parent.add_subcommand(
      "stability", "The stability map: where each method fails (explicit step limits, constraint drift, spin "
                   "divergence, slack wire and snap loads, BDF order, buckling margin), each failure named");
  sub->add_option("scene", options->scene, "Scene file (TOML) with a [hull] or a [hub]")->required();
  sub->add_option("--out", options->out, "Write report.md, summary.json, the CSVs and the PNG charts into this directory");
  sub->add_flag("--json", options->json, "Print summary.json on stdout instead of the Markdown report");
  sub->add_flag("--quick", options->quick, "Fewer models and shorter horizons (a quick look)");
  return {sub, [options] { return run_stability(*options); }};
}

}  // namespace ffrf::app
