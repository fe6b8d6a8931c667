// Benchmark of the coupled floating crane: wall time of one dynamic run of the reference scene
// (cases/paper_floating_crane.toml, 120 s simulated, outputs every 0.05 s, from static
// equilibrium) for the rigid boom, the nodal boom with N = 1, 4, 16, 64 elements and the modal
// boom with k = 2, 4, 8 modes (N = 16 mesh) with and without the static correction modes, with
// IDA (stabilized index-2 DAE in full coordinates) and CVODE (BDF on the minimal-coordinate ODE);
// modal runs with CVODE only. Tolerances rtol = 1e-6, atol = 1e-6 (atol scaled per coordinate by
// CraneEquations::coordinate_scale(), as in `ffrf run`). Model construction (including the modal
// eigen solve) and the KINSOL static equilibrium are outside the timed region; the timed call is
// `coupling::integrate`, which includes recording the output samples.
// After Google Benchmark's own output, prints a Markdown table: wall time, real-time factor
// (simulated time / wall time), ratio to the rigid run of the same integrator, and the solver
// statistics (steps, RHS/residual evaluations including those of the difference-quotient
// Jacobians, Jacobian evaluations).
// Options (before Google Benchmark's own): --quick (or FFRF_BENCH_QUICK=1) simulates 20 s instead
// of 120 s, for smoke tests; --duration=SECONDS any other simulated time; --scene=PATH another
// scene file. (--all is accepted for compatibility: every case runs by default since CVODE got its
// own Jacobian, see docs/performance.md.)
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"
#include "coupling/simulation.hpp"
#include "coupling/static_equilibrium.hpp"

namespace {

using ffrf::scene::BoomChoice;
using ffrf::scene::BoomKind;
using ffrf::coupling::Integrator;

constexpr double kRelativeTolerance = 1e-6;
constexpr double kAbsoluteTolerance = 1e-6;
constexpr double kOutputInterval = 0.05;  // [s]
constexpr double kFullDuration = 120.0;   // [s]
constexpr double kQuickDuration = 20.0;   // [s]

struct Case {
  BoomChoice choice;
  Integrator integrator;
  int iterations;
};

// One table row's solver statistics (deterministic: the same for every iteration).
struct Row {
  std::string model;
  Integrator integrator;
  ffrf::coupling::SolverStats stats;
  std::string error;  // empty when the run finished
};

struct Context {
  ffrf::scene::Scene scene;
  double duration = kFullDuration;
  std::vector<std::string> order;  // table keys in registration order
  std::map<std::string, Row> rows;
};

std::string key_of(const BoomChoice& choice, Integrator integrator) {
  return fmt::format("{} | {}", choice.label(), to_string(integrator));
}

// "rigid", "nodal/N:16", "modal/k:4+static/N:16" (no spaces, for --benchmark_filter).
std::string benchmark_model_name(const BoomChoice& choice) {
  switch (choice.kind) {
    case BoomKind::rigid: return "rigid";
    case BoomKind::nodal: return fmt::format("nodal/N:{}", choice.elements);
    case BoomKind::modal:
      return fmt::format("modal/k:{}{}/N:{}", choice.modes, choice.static_modes ? "+static" : "", choice.elements);
  }
  return "?";
}

std::vector<Case> cases(bool /*all*/) {
  std::vector<Case> list;
  for (const Integrator integrator : {Integrator::cvode, Integrator::ida}) {
    list.push_back({{.kind = BoomKind::rigid}, integrator, 3});
    for (const int elements : {1, 4, 16, 64}) {
      const int iterations = elements <= 4 ? 3 : elements == 16 ? 2 : 1;
      list.push_back({{.kind = BoomKind::nodal, .elements = elements}, integrator, iterations});
    }
  }
  for (const bool static_modes : {false, true}) {
    for (const int modes : {2, 4, 8}) {
      list.push_back({{.kind = BoomKind::modal, .elements = 16, .modes = modes, .static_modes = static_modes},
                      Integrator::cvode, 2});
    }
  }
  return list;
}

void run_crane(benchmark::State& state, Context* context, Case c) {
  const std::string key = key_of(c.choice, c.integrator);
  state.SetLabel(key);
  std::unique_ptr<ffrf::coupling::CraneEquations> equations;
  Eigen::VectorXd z0;
  try {
    equations = ffrf::scene::build_crane(context->scene, c.choice);
    z0 = ffrf::coupling::solve_static_equilibrium(*equations, equations->initial_guess()).z;
  } catch (const std::exception& error) {
    context->rows[key] = Row{c.choice.label(), c.integrator, {}, error.what()};
    state.SkipWithError(error.what());
    return;
  }
  const ffrf::coupling::IntegratorSettings settings{.kind = c.integrator,
                                                    .relative_tolerance = kRelativeTolerance,
                                                    .absolute_tolerance = kAbsoluteTolerance,
                                                    .duration = context->duration,
                                                    .output_interval = kOutputInterval};
  ffrf::coupling::SolverStats stats;
  for (auto _ : state) {
    try {
      const auto result = ffrf::coupling::integrate(*equations, z0, settings);
      benchmark::DoNotOptimize(result.samples.data());
      stats = result.stats;
    } catch (const std::exception& error) {
      context->rows[key] = Row{c.choice.label(), c.integrator, {}, error.what()};
      state.SkipWithError(error.what());
      break;
    }
  }
  if (state.error_occurred()) return;
  context->rows[key] = Row{c.choice.label(), c.integrator, stats, {}};
  state.counters["n_minimal"] = equations->minimal_size();
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["f_evals"] = static_cast<double>(stats.function_evaluations);
  state.counters["jac_evals"] = static_cast<double>(stats.jacobian_evaluations);
  state.counters["newton"] = static_cast<double>(stats.newton_iterations);
  state.counters["err_fails"] = static_cast<double>(stats.error_test_failures);
}

// Collects the wall time per run [ms] of each case while the console reporter prints.
class TableCollector : public benchmark::ConsoleReporter {
 public:
  // Colours only on a terminal, so that a redirected log stays plain text.
  TableCollector() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}

  std::map<std::string, double> milliseconds;

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred || run.run_type != Run::RT_Iteration) continue;
      milliseconds[run.report_label] = run.GetAdjustedRealTime();  // in run.time_unit = milliseconds
    }
  }
};

void print_table(const Context& context, const TableCollector& table) {
  fmt::print("\nCoupled crane, {} s simulated from static equilibrium, rtol = {:g}, atol = {:g} "
             "(× coordinate scale), wall time per run\n\n",
             context.duration, kRelativeTolerance, kAbsoluteTolerance);
  fmt::print("| model | integrator | wall [ms] | real-time factor | / rigid | steps | f evals | Jacobian evals |\n");
  fmt::print("|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& key : context.order) {
    const auto row = context.rows.find(key);
    const auto time = table.milliseconds.find(key);
    if (row == context.rows.end()) continue;  // filtered out
    const Row& r = row->second;
    if (!r.error.empty() || time == table.milliseconds.end()) {
      fmt::print("| {} | {} | failed: {} | | | | | |\n", r.model, to_string(r.integrator), r.error.substr(0, 60));
      continue;
    }
    const auto rigid = table.milliseconds.find(key_of({.kind = BoomKind::rigid}, r.integrator));
    const std::string ratio =
        rigid == table.milliseconds.end() ? std::string("—") : fmt::format("{:.1f}", time->second / rigid->second);
    const double factor = context.duration / (time->second * 1e-3);
    fmt::print("| {} | {} | {:.1f} | {:.0f} | {} | {} | {} | {} |\n", r.model, to_string(r.integrator), time->second,
               factor, ratio, r.stats.steps, r.stats.function_evaluations, r.stats.jacobian_evaluations);
  }
}

bool quick_from_environment() {
  const char* value = std::getenv("FFRF_BENCH_QUICK");
  return value != nullptr && *value != '\0' && std::string_view(value) != "0";
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = quick_from_environment();
  bool all = false;
  double duration = 0.0;  // 0: the default (kFullDuration, or kQuickDuration with --quick)
  std::string scene_path = FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml";
  // Take our own options out of argv before Google Benchmark parses the rest.
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument(argv[i]);
    if (argument == "--quick") {
      quick = true;
    } else if (argument == "--all") {
      all = true;
    } else if (argument.starts_with("--duration=")) {
      duration = std::stod(std::string(argument.substr(11)));
    } else if (argument.starts_with("--scene=")) {
      scene_path = std::string(argument.substr(8));
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;

  Context context;
  try {
    context.scene = ffrf::scene::load_scene(scene_path);
  } catch (const std::exception& error) {
    fmt::print(stderr, "bench_crane: {}\n", error.what());
    return 1;
  }
  context.duration = duration > 0.0 ? duration : quick ? kQuickDuration : kFullDuration;

  for (const Case& c : cases(all)) {
    context.order.push_back(key_of(c.choice, c.integrator));
    const std::string name = fmt::format("crane/{}/{}", to_string(c.integrator), benchmark_model_name(c.choice));
    benchmark::RegisterBenchmark(name.c_str(), run_crane, &context, c)
        ->Iterations(c.iterations)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  fmt::print("bench_crane: scene {}, {} s simulated\n", scene_path, context.duration);
  TableCollector table;
  benchmark::RunSpecifiedBenchmarks(&table);
  benchmark::Shutdown();
  if (!context.rows.empty()) print_table(context, table);  // nothing ran with --benchmark_list_tests
  return 0;
}
