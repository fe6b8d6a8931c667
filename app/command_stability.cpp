// `ffrf stability SCENE`: the stability map report — which method fails where, and how ffrf names it. Runs the
// experiments that apply to the scene (study::stability_map) and writes report.md (embedding the
// PNG charts), summary.json (every cell: status, failure kind, time, value) and the CSVs into
// --out DIR, completely or not at all; without --out the charts go to a temporary directory that
// is removed. Solver failures inside the experiments are results (red cells); bad input exits 2.
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "report/chart_notes.hpp"
#include "report/gnuplot.hpp"
#include "report/stability_section.hpp"

namespace ffrf::app {
namespace {

struct StabilityCommandOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  std::string out;
  bool json = false;
  bool quick = false;
};

int run_stability(const StabilityCommandOptions& options) {
  const std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "stability", true);
  if (!scene) return exit_bad_input;
  report::png_terminal();  // fail before the computation when gnuplot is missing
  std::filesystem::path target = options.out;
  const bool temporary = options.out.empty();
  if (temporary) target = std::filesystem::temp_directory_path() / fmt::format("ffrf-stability-{}", ::getpid());
  study::StabilityOptions settings;
  settings.quick = options.quick;
  if (stderr_is_terminal()) {
    settings.progress = [](const std::string& line) {
      fmt::print(stderr, "ffrf stability: {}\n", line);
      std::fflush(stderr);
    };
  }
  report::StabilityReport report;
  {
    report::StagedDirectory out(target, "summary.json");
    try {
      report = report::stability_report(*scene, options.scene, options.quick, study::stability_map(*scene, settings), out);
    } catch (const scene::SceneError& error) {
      return scene_error("stability", options.scene, error, "this crane");
    }
    report.markdown += report::charts_markdown(out);
    report.json = report::with_charts_json(report.json, out);
    out.write("report.md", report.markdown);
    out.write("summary.json", report.json);
    out.commit();
    fmt::print(stderr, "{}", report::chart_notes_text("stability", out));
  }
  if (temporary) std::filesystem::remove_all(target);
  fmt::print("{}", options.json ? report.json : report.markdown);
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
  add_set_option(*sub, options->set);
  sub->add_option("--out", options->out, "Write report.md, summary.json, the CSVs and the PNG charts into this directory");
  sub->add_flag("--json", options->json, "Print summary.json on stdout instead of the Markdown report");
  sub->add_flag("--quick", options->quick, "Fewer models and shorter horizons (a quick look)");
  return {sub, [options] { return run_stability(*options); }};
}

}  // namespace ffrf::app
