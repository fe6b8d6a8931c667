// `ffrf sweep SCENE`: the accuracy–speed study. The converged reference first, then every
// configuration of the grid (sweep_grid.hpp; --quick by default, --medium, --full), or the slice
// --shard i/n, over --jobs threads; one CSV row per run, the accuracy–speed and mode-count charts
// and report.md naming the Pareto-optimal configurations. `--merge A.csv B.csv ... --out DIR`
// joins shard CSVs into the same outputs. Exit 2 for bad input, 3 when the reference fails; a
// failing configuration is a row, not an error.
#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "app/crane_commands.hpp"
#include "app/crane_reference.hpp"
#include "app/gnuplot.hpp"
#include "app/output_directory.hpp"
#include "app/sweep_report.hpp"
#include "app/sweep_run.hpp"
#include "cases/scene_loader.hpp"

namespace ffrf::app {
namespace {

struct SweepOptions {
  std::string scene;
  std::string out;
  int jobs = 0;
  std::string shard;
  std::vector<std::string> merge;
  std::optional<double> duration;
  bool quick = false, medium = false, full = false;
  ReferenceOptions reference;
};

constexpr const char* context_file = "sweep_context.md";  // the report's preamble, reused by --merge
constexpr double quick_duration = 40.0;

int bad_input(const std::string& message) {
  fmt::print(stderr, "ffrf sweep: error: {}\n", message);
  return exit_bad_input;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The duration is the first line of the context file: "<!-- duration_s: 40 -->".
double context_duration(const std::string& context) {
  const std::string tag = "<!-- duration_s: ";
  return context.rfind(tag, 0) == 0 ? std::stod(context.substr(tag.size())) : 0.0;
}

std::string pareto_text(const std::vector<SweepRow>& rows) {
  std::string t = fmt::format("{:>4}  {:<26} {:<28} {:>11} {:>10}\n", "id", "model", "integrator", "worst error", "wall [s]");
  for (std::size_t i : pareto_front(rows)) {
    t += fmt::format("{:>4}  {:<26} {:<28} {:>11.3e} {:>10.3g}\n", rows[i].id, rows[i].model, rows[i].settings(),
                     *rows[i].worst, *rows[i].wall);
  }
  return t;
}

// Writes sweep.csv, the charts, the context and report.md (the completeness marker) into DIR.
void write_outputs(const std::string& dir, std::vector<SweepRow>& rows, const std::string& context, double duration) {
  StagedDirectory out(dir, "report.md");
  out.write("sweep.csv", sweep_csv(rows));
  out.write(context_file, context);
  draw_sweep_charts(out, rows, fmt::format("{:g} s simulated", duration));
  out.write("report.md", sweep_markdown(rows, context, duration));
  out.commit();
}

int merge(const SweepOptions& options) {
  if (options.out.empty()) return bad_input("--merge needs --out DIR for the merged outputs");
  std::vector<SweepRow> rows;
  for (const std::string& file : options.merge) {
    std::string text;
    try {
      text = read_file(file);
    } catch (const std::runtime_error& error) {
      return bad_input(error.what());
    }
    std::vector<SweepRow> part;
    try {
      part = read_sweep_csv(text, file);
    } catch (const std::runtime_error& error) {
      return bad_input(error.what());
    }
    rows.insert(rows.end(), part.begin(), part.end());
  }
  const std::filesystem::path context_path = std::filesystem::path(options.merge.front()).parent_path() / context_file;
  const std::string context = std::filesystem::exists(context_path)
                                  ? read_file(context_path)
                                  : std::string("# Sweep (merged)\n\nThe shards' context file was not found.\n");
  png_terminal();
  try {
    write_outputs(options.out, rows, context, context_duration(context));
  } catch (const std::runtime_error& error) {
    if (std::string(error.what()).find("appears twice") != std::string::npos) return bad_input(error.what());
    throw;
  }
  fmt::print("merged {} rows from {} files\n{}\nwrote {} (report.md)\n", rows.size(), options.merge.size(),
             pareto_text(rows), options.out);
  return exit_ok;
}

int run_sweep_command(const SweepOptions& options) {
  if (!options.merge.empty()) return merge(options);
  if (options.scene.empty()) return bad_input("give a SCENE file to sweep, or --merge CSV... --out DIR");
  if (int(options.quick) + int(options.medium) + int(options.full) > 1) {
    return bad_input("--quick, --medium and --full exclude each other");
  }
  const SweepGrid grid = options.full ? SweepGrid::full : options.medium ? SweepGrid::medium : SweepGrid::quick;
  Shard shard;
  if (!options.shard.empty()) {
    const auto parsed = parse_shard(options.shard);
    if (!parsed) return bad_input(fmt::format("--shard {}: not a shard i/n with 0 <= i < n", options.shard));
    shard = *parsed;
  }
  if (options.jobs < 0) return bad_input(fmt::format("--jobs {}: not a thread count (valid range [1, inf), 0: all cores)", options.jobs));
  if (const auto error = reference_options_error(options.reference)) return bad_input(*error);
  const std::optional<cases::Scene> scene = load_crane_scene(options.scene, "sweep");
  if (!scene) return exit_bad_input;
  const double duration = options.duration.value_or(grid == SweepGrid::quick ? quick_duration : scene->simulation.duration);
  if (!(duration >= scene->simulation.output_interval) || !std::isfinite(duration)) {
    return bad_input(fmt::format("--duration {}: shorter than one output interval of the scene ({} s) (valid range [{}, inf) s)",
                                 duration, scene->simulation.output_interval, scene->simulation.output_interval));
  }
  if (!options.out.empty()) png_terminal();  // fail before the computation when gnuplot is missing

  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  if (terminal) fmt::print(stderr, "ffrf sweep: converged reference (nodal, refined level by level) ...\n");
  cases::ConvergedReference reference;
  try {
    reference = compute_reference(*scene, options.reference, duration);
  } catch (const coupling::SolverFailure& failure) {
    fmt::print(stderr, "ffrf sweep: solver failure (reference): {}\n", failure.what());
    return exit_solver_failure;
  }
  std::vector<SweepConfig> configs;
  for (const SweepConfig& config : sweep_grid(grid)) {
    if (config.id % shard.count == shard.index) configs.push_back(config);
  }
  const int jobs = options.jobs > 0 ? options.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const SweepSetup setup{&*scene, &reference.run, error_window(*scene, duration), duration,
                         scene->simulation.output_interval};
  const std::vector<SweepResult> results = run_sweep(setup, configs, jobs, [&](const SweepResult& r, std::size_t done) {
    if (!terminal) return;
    fmt::print(stderr, "\r\033[K[{}/{}] {} {}: {}", done, configs.size(), r.config.choice.label(),
               integrator_label(r.config), to_string(r.status));
    if (done == configs.size()) fmt::print(stderr, "\n");
  });

  std::string csv = sweep_csv_header();
  for (const SweepResult& r : results) csv += sweep_csv_line(r);
  std::vector<SweepRow> rows = read_sweep_csv(csv, "sweep.csv");
  const std::string context = fmt::format(
      "<!-- duration_s: {} -->\n# Accuracy–speed sweep: {}\n\n- scene: `{}`, {:g} s simulated, output every {:g} s\n- {}\n"
      "- errors against {}, {}\n\n## Converged reference\n\n{}\n\n{}",
      duration, scene->name.empty() ? options.scene : scene->name, options.scene, duration,
      scene->simulation.output_interval, grid_description(grid), reference_label(reference),
      setup.window_start > 0.0 ? fmt::format("for t ≥ {:g} s (after the wave ramp)", setup.window_start)
                               : std::string("over the whole run"),
      reference_verdict(reference), reference_levels_markdown(reference));
  if (!options.out.empty()) write_outputs(options.out, rows, context, duration);
  std::size_t failed = 0;
  for (const SweepRow& row : rows) failed += row.ok() ? 0 : 1;
  fmt::print("{} configurations{} of the {} grid, {} s simulated, {} threads: {} ok, {} failed or skipped\n"
             "reference: {}\n{}\nPareto-optimal (worst normalized RMS error vs wall time):\n{}",
             rows.size(), options.shard.empty() ? "" : " (shard " + options.shard + ")", to_string(grid), duration, jobs,
             rows.size() - failed, failed, reference_label(reference), reference_levels_text(reference), pareto_text(rows));
  if (!options.out.empty()) fmt::print("\nwrote {} (report.md)\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_sweep_command(CLI::App& parent) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* sub = parent.add_subcommand(
      "sweep", "Boom model x integrator x tolerance grid against a converged reference: accuracy-speed chart, Pareto front");
  sub->add_option("scene", options->scene, "Scene file (TOML) of a crane");
  sub->add_option("--out", options->out,
                  "Write sweep.csv, accuracy_speed.png, mode_count.png (with gnuplot scripts and data) and report.md here");
  sub->add_option("--jobs,-j", options->jobs, "Worker threads (0: one per core)")->capture_default_str();
  sub->add_option("--shard", options->shard, "Run only the configurations with id % n == i (i/n)");
  sub->add_option("--merge", options->merge, "Join these shard CSVs (sweep.csv of each shard's --out) into --out DIR")
      ->expected(1, -1);
  sub->add_option("--duration", options->duration,
                  fmt::format("Simulated time [s] (default: {:g} s with --quick, the scene's duration otherwise)", quick_duration));
  sub->add_flag("--quick", options->quick,
                "The small grid (the default): rigid, nodal N 1/4/16, modal k 1/2/4 +- static; cvode and generalized-alpha");
  sub->add_flag("--medium", options->medium,
                "The medium grid: nodal N 1..32, modal k 1..12 (7 values) +- static; cvode 3 tolerances, generalized-alpha, "
                "explicit RK");
  sub->add_flag("--full", options->full,
                "The full grid: nodal N 1..64, modal k 1..12 +- static; cvode, ida, arkode at 3 tolerances, "
                "generalized-alpha at 3 steps, explicit RK at 0.5x and 2x its stability limit");
  add_reference_options(*sub, options->reference);
  return {sub, [options] { return run_sweep_command(*options); }};
}

}  // namespace ffrf::app
