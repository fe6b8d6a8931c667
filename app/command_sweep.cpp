// `ffrf sweep SCENE`: the accuracy–speed study on the distributed engine (study::sweep_on_engine). The
// converged reference first, then every configuration of the grid (--quick by default, --medium,
// --full), or the slice --shard i/n, as farm tasks over --jobs threads and, under mpirun or srun, the
// MPI ranks; finished rows journaled in --out (journal.tsv) and resumed on a rerun; one CSV row per run, the accuracy–speed and mode-count charts and
// report.md naming the Pareto-optimal configurations and the verdict against --tolerance (default
// 1 %). `--merge A.csv B.csv ... --out DIR` joins shard CSVs into the same outputs. Exit 2 for bad
// input, 3 when the reference fails; a failing configuration is a row, not an error.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>
#include <thread>

#include <unistd.h>

#include "app/cli_options.hpp"
#include "app/radiation_option.hpp"
#include "scene/scene_key.hpp"
#include "study/radiation_compare.hpp"
#include "app/commands.hpp"
#include "app/option_checks.hpp"
#include "app/version.hpp"
#include "distributed/errors.hpp"
#include "distributed/session.hpp"
#include "distributed/shard.hpp"
#include "report/output_directory.hpp"
#include "report/gnuplot.hpp"
#include "report/reference_report.hpp"
#include "report/sweep_report.hpp"

namespace ffrf::app {
namespace {

struct SweepOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  std::string out;
  std::string radiation;  // overrides bem.radiation_model of every configuration
  int jobs = 0;
  std::string shard;
  std::vector<std::string> merge;
  std::optional<double> duration;
  bool quick = false, medium = false, full = false;
  study::ReferenceOptions reference;
  std::string stiffening;
  std::string tolerance = "1%";
};

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int merge(const SweepOptions& options) {
  if (options.out.empty()) return bad_input("sweep", "--merge needs --out DIR for the merged outputs");
  report::check_output_directory(options.out, "report.md");
  std::vector<report::SweepRow> rows;
  for (const std::string& file : options.merge) {
    try {
      const std::vector<report::SweepRow> part = report::read_sweep_csv(read_file(file), file);
      rows.insert(rows.end(), part.begin(), part.end());
    } catch (const std::runtime_error& error) {
      return bad_input("sweep", error.what());
    }
  }
  const auto context_path = std::filesystem::path(options.merge.front()).parent_path() / report::sweep_context_file;
  const std::string context = std::filesystem::exists(context_path)
                                  ? read_file(context_path)
                                  : std::string("# Sweep (merged)\n\nThe shards' context file was not found.\n");
  report::png_terminal();
  try {
    fmt::print(stderr, "{}", report::write_sweep_outputs(options.out, rows, context));
  } catch (const std::runtime_error& error) {
    if (std::string(error.what()).find("appears twice") != std::string::npos) return bad_input("sweep", error.what());
    throw;
  }
  fmt::print("merged {} rows from {} files\n{}\nwrote {} (report.md)\n", rows.size(), options.merge.size(),
             report::pareto_text(rows, report::context_facts(context)), options.out);
  return exit_ok;
}

int run_sweep(const SweepOptions& options) {
  if (!options.merge.empty()) return merge(options);
  if (options.scene.empty()) return bad_input("sweep", "give a SCENE file to sweep, or --merge CSV... --out DIR");
  if (int(options.quick) + int(options.medium) + int(options.full) > 1) {
    return bad_input("sweep", "--quick, --medium and --full exclude each other");
  }
  study::SweepRequest request;
  request.grid = options.full ? study::SweepGrid::full : options.medium ? study::SweepGrid::medium : study::SweepGrid::quick;
  if (!options.shard.empty()) {
    const auto shard = distributed::parse_shard(options.shard);
    if (!shard) return bad_input("sweep", fmt::format("--shard {}: not a shard i/n with 0 <= i < n", options.shard));
    request.shard = *shard;
  }
  if (options.jobs < 0) {
    return bad_input("sweep", fmt::format("--jobs {}: not a thread count (valid range [1, inf), 0: all cores)", options.jobs));
  }
  request.jobs = study::worker_threads(options.jobs);
  request.reference = options.reference;
  std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "sweep", true);
  if (!scene) return exit_bad_input;
  try {
    apply_radiation_option(*scene, options.radiation);
    // A [bem] scene: the radiation models are an axis of the grid, unless --radiation fixes one; a
    // pinned boom: the modal boom's mode set is an axis too.
    study::add_scene_axes(request, *scene, !options.radiation.empty());
    request.stiffening = stiffening_option(options.stiffening);
    request.tolerance = parse_tolerance(options.tolerance);
    study::validate(request.reference);
    DynamicsOptions dynamics;  // checks the duration against the scene
    dynamics.duration = options.duration.value_or(study::default_sweep_duration(*scene, request.grid));
    request.duration = integrator_settings(dynamics, *scene).duration;
  } catch (const BadOption& error) {
    return bad_input("sweep", error.what());
  } catch (const study::SettingError& error) {
    return bad_input("sweep", option_message(error));
  }
  if (!options.out.empty()) {
    report::png_terminal();                                   // fail before the computation when gnuplot is missing
    report::check_output_directory(options.out, "report.md");  // or when DIR cannot be written
  }

  // On the distributed engine: the journal goes to --out (or a temporary directory removed after).
  distributed::Session session;
  const bool temporary = options.out.empty();
  const std::filesystem::path journal_dir =
      temporary ? std::filesystem::temp_directory_path() / fmt::format("ffrf-sweep-journal-{}", ::getpid())
                : std::filesystem::path(options.out);
  distributed::FarmOptions farm;
  farm.output_directory = journal_dir;
  farm.study = fmt::format("ffrf sweep {} --{}", options.scene, study::to_string(request.grid));
  farm.settings = fmt::format("{}\n{}\ngrid={} duration={:.17g} reference={} {:.17g} {:.17g} {} stiffening={} tolerance={:.17g} "
                              "max_explicit_steps={} radiation={}\n",
                              version_text(), read_file(options.scene) + overrides_text(*scene), study::to_string(request.grid), request.duration,
                              request.reference.start_elements, request.reference.start_relative_tolerance,
                              request.reference.bound, request.reference.max_levels, options.stiffening, request.tolerance,
                              request.max_explicit_steps, request.radiation_axis ? "axis" : options.radiation);
  farm.threads = options.jobs;
  farm.progress_label = "sweep configurations";
  study::SweepOnEngine result;
  try {
    if (session.is_root()) progress("sweep", "converged reference (nodal, refined level by level) ...", true);
    result = study::sweep_on_engine(session, *scene, request, farm,
                                    [](const study::SweepResult& r) { return report::sweep_csv_line(r); });
  } catch (const scene::SceneError& error) {
    return scene_error("sweep", options.scene, error, "the reference crane");
  } catch (const solve::SolverFailure& failure) {
    return solver_failure("sweep", "reference", failure, options.out);
  } catch (const distributed::JournalError& error) {
    return bad_input("sweep", error.what());
  }
  if (temporary && session.is_root()) std::filesystem::remove_all(journal_dir);
  if (!result.farm.root) return exit_ok;
  std::string csv = report::sweep_csv_header();
  for (const std::string& line : result.records) csv += line;
  std::vector<report::SweepRow> rows = report::read_sweep_csv(csv, "sweep.csv");
  const std::string context = report::sweep_context(options.scene, *scene, request.grid, request.duration, result.study);
  if (!options.out.empty()) fmt::print(stderr, "{}", report::write_sweep_outputs(options.out, rows, context));
  std::size_t failed = 0;
  for (const report::SweepRow& row : rows) failed += row.ok() ? 0 : 1;
  fmt::print("{} configurations{} of the {} grid, {} s simulated, {}, {} threads on rank 0 ({} computed, {} resumed): {} ok, "
             "{} failed or skipped\n"
             "reference: {}\n{}\nPareto-optimal (worst normalized RMS error vs wall time):\n{}",
             rows.size(), options.shard.empty() ? "" : " (shard " + options.shard + ")", study::to_string(request.grid),
             request.duration, result.farm.engine, result.farm.root_threads, result.farm.computed, result.farm.resumed,
             rows.size() - failed, failed, report::reference_label(result.study.reference),
             report::reference_levels_text(result.study.reference), report::pareto_text(rows, report::context_facts(context)));
  // A scene with BEM coefficients: a section comparing the radiation models on the scene's default
  // boom model against the Cummins convolution, at the sweep's duration and tolerance.
  if (scene->bem && options.shard.empty()) {
    try {
      progress("sweep", "radiation models (constant, state-space, convolution) ...", true);
      DynamicsOptions dynamics;
      dynamics.duration = request.duration;
      const auto radiation = study::compare_radiation(*scene, default_boom_choice(*scene), integrator_settings(dynamics, *scene),
                                                      request.tolerance);
      fmt::print("{}", study::radiation_comparison_text(radiation));
    } catch (const scene::SceneError& error) {
      return scene_error("sweep", options.scene, error, "the radiation-model crane");
    } catch (const solve::SolverFailure& failure) {
      return solver_failure("sweep", "radiation models", failure, options.out);
    }
  }
  if (!options.out.empty()) fmt::print("\nwrote {} (report.md)\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_sweep_command(CLI::App& parent) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* sub = parent.add_subcommand(
      "sweep", "Boom model x integrator x tolerance grid against a converged reference: accuracy-speed chart, Pareto front");
  sub->add_option("scene", options->scene, "Scene file (TOML) of a crane");
  add_set_option(*sub, options->set);
  sub->add_option("--out", options->out,
                  "Write sweep.csv, accuracy_speed.png, mode_count.png (with gnuplot scripts and data) and report.md here");
  sub->add_option("--jobs,-j", options->jobs, "Worker threads (0: one per core)")->capture_default_str()->check(whole_number(0, 1024));
  sub->add_option("--shard", options->shard, "Run only the configurations with id % n == i (i/n)");
  sub->add_option("--merge", options->merge, "Join these shard CSVs (sweep.csv of each shard's --out) into --out DIR")
      ->expected(1, -1);
  sub->add_option("--duration", options->duration,
                  fmt::format("Simulated time [s] (default: {:g} s with --quick, the scene's duration otherwise)", study::quick_sweep_duration))
      ->check(scene_key_range(scene::scene_key("simulation.duration")));
  sub->add_flag("--quick", options->quick,
                "The small grid (the default): rigid, nodal N 1/4/16, modal k 1/2/4 +- static; cvode and generalized-alpha");
  sub->add_flag("--medium", options->medium,
                "The medium grid: nodal N 1..32, modal k 1..12 (7 values) +- static; cvode 3 tolerances, generalized-alpha, "
                "explicit RK");
  sub->add_flag("--full", options->full,
                "The full grid: nodal N 1..64, modal k 1..12 +- static; cvode, ida, arkode at 3 tolerances, "
                "generalized-alpha at 3 steps, explicit RK at 0.5x and 2x its stability limit");
  add_reference_options(*sub, options->reference);
  add_stiffening_option(*sub, options->stiffening);
  add_radiation_option(*sub, options->radiation);
  add_tolerance_option(*sub, options->tolerance,
                       "a configuration passes when its worst normalized RMS error over the judged outputs is within it");
  return {sub, [options] { return run_sweep(*options); }};
}

}  // namespace ffrf::app
