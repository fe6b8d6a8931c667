// Benchmark of the coupled floating crane: wall time of one dynamic run of the reference scene
// (cases/paper_floating_crane.toml, 120 s simulated, outputs every 0.05 s, from static equilibrium)
// with CVODE (BDF on the minimal-coordinate ODE) for the rigid boom, the nodal boom with N = 1, 4,
// 16, 32, 64, 128 elements, the modal boom k = 2 + static modes and k = 8 (N = 16 mesh); IDA
// (stabilized index-2 DAE in full coordinates) for the rigid boom and N = 16, 64; generalized-α
// (fixed step 0.02 s) for N = 16, 64; and the spin-up benchmark (cases/spin_up_beam.toml, nodal
// N = 10, centrifugal stiffening, 30 s, outputs every 0.02 s, BDF order ≤ 2 as `ffrf run` chooses for
// an undamped boom). rtol = 1e-6, atol = 1e-6 (× each coordinate's typical size). Model construction
// and the KINSOL static equilibrium are outside the timed region; the timed call is
// `multibody::simulate`, including the output samples.
// After Google Benchmark's own output it prints a Markdown table (crane_bench_table.hpp): wall,
// steps, RHS evaluations (those of the Jacobians included), Jacobian evaluations, µs per step,
// real-time factor and the local cost exponent in N, and checks the real-time-factor targets (crane_bench_table.hpp); for a missed
// target it measures what one RHS, one Jacobian, one Newton factorization and solve and one output
// sample cost and splits the run's wall time accordingly (the rest is CVODE's own vector work);
// --breakdown prints that split for every target row.
// Options (before Google Benchmark's own): --quick (or FFRF_BENCH_QUICK=1) simulates 20 s instead of
// 120 s; --duration=SECONDS; --repetitions=R (best of R, default 1); --csv=FILE writes the rows;
// --before=A.csv[,B.csv…] --after=C.csv[,…] prints the side-by-side table of two builds' CSV files
// (best of each) without running anything (bench/before_after.sh builds the old commit and does this).
// The file also builds in older source trees (the breakdown needs the structured Newton API).
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

#if __has_include("scene/crane_builder.hpp")
#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"
namespace scene_library = ffrf::scene;
#else  // an older source tree (bench/before_after.sh), where the scene library was cases/
#include "cases/crane_builder.hpp"
#include "cases/scene_loader.hpp"
namespace scene_library = ffrf::cases;
#endif
#include "multibody/crane_run.hpp"
#include "multibody/crane_statics.hpp"
#include "crane_bench_table.hpp"
#if __has_include("solve/second_order_newton.hpp")
#include "solve/bordered_band_matrix.hpp"
#include "sea/hull_pressure.hpp"
#define FFRF_BENCH_BREAKDOWN 1
#endif

namespace {

using ffrf::bench::CraneRow;
using scene_library::BoomChoice;
using scene_library::BoomKind;
using ffrf::solve::Integrator;

constexpr double kTolerance = 1e-6;  // rtol and atol
constexpr double kFullDuration = 120.0, kQuickDuration = 20.0;
constexpr double kGeneralizedAlphaStep = 0.02;  // [s]

struct Case {
  std::string scene;  // file under cases/
  BoomChoice choice;
  Integrator integrator;
  bool spin_up = false;  // the scene's own duration, output interval and BDF order limit
};

struct Context {
  double duration = kFullDuration;
  std::map<std::string, scene_library::Scene> scenes;
  std::vector<std::string> order;
  std::map<std::string, CraneRow> rows;
  std::map<std::string, std::string> errors;
};

std::string key_of(const Case& c) {
  return fmt::format("{}{} | {}", c.spin_up ? "spin-up " : "", c.choice.label(), to_string(c.integrator));
}

std::vector<Case> cases() {
  const std::string crane = "paper_floating_crane.toml";
  std::vector<Case> list;
  list.push_back({crane, {.kind = BoomKind::rigid}, Integrator::cvode});
  for (const int n : {1, 4, 16, 32, 64, 128}) list.push_back({crane, {.kind = BoomKind::nodal, .elements = n}, Integrator::cvode});
  list.push_back({crane, {.kind = BoomKind::modal, .elements = 16, .modes = 2, .static_modes = true}, Integrator::cvode});
  list.push_back({crane, {.kind = BoomKind::modal, .elements = 16, .modes = 8, .static_modes = false}, Integrator::cvode});
  list.push_back({"spin_up_beam.toml", {.kind = BoomKind::nodal, .elements = 10}, Integrator::cvode, true});
  list.push_back({crane, {.kind = BoomKind::rigid}, Integrator::ida});
  for (const int n : {16, 64}) list.push_back({crane, {.kind = BoomKind::nodal, .elements = n}, Integrator::ida});
  for (const int n : {16, 64}) list.push_back({crane, {.kind = BoomKind::nodal, .elements = n}, Integrator::generalized_alpha});
  return list;
}

ffrf::multibody::RunSettings settings_for(const Context& context, const Case& c, const scene_library::Scene& scene) {
  ffrf::multibody::RunSettings s;
  s.kind = c.integrator;
  s.relative_tolerance = s.absolute_tolerance = kTolerance;
  s.duration = c.spin_up ? std::min(context.duration, scene.simulation.duration) : context.duration;
  s.output_interval = c.spin_up ? scene.simulation.output_interval : 0.05;
  if (c.spin_up && !(scene.boom.damping_ratio > 0.0)) s.max_order = 2;
  if (c.integrator == Integrator::generalized_alpha) s.fixed_step = kGeneralizedAlphaStep;
  return s;
}

#ifdef FFRF_BENCH_BREAKDOWN
// What the parts of one step cost for this model, and the run's wall time split by the counts.
void print_breakdown(ffrf::multibody::CraneEquations& eq, const Eigen::VectorXd& z0, const ffrf::multibody::RunSettings& s,
                     const ffrf::solve::SolverStats& stats, double wall_ms) {
  using clock = std::chrono::steady_clock;
  const int n = eq.minimal_size();
  Eigen::VectorXd z = z0, z_dot = Eigen::VectorXd::Constant(n, 1e-3), z_ddot(n);
  const double t = 30.0;
  const auto time_us = [](int repeats, auto&& f) {
    const auto start = clock::now();
    for (int i = 0; i < repeats; ++i) f();
    return std::chrono::duration<double, std::micro>(clock::now() - start).count() / repeats;
  };
  const double rhs = time_us(2000, [&] { eq.minimal_accelerations(t, z, z_dot, z_ddot); });
  ffrf::solve::SecondOrderJacobian blocks(eq.minimal_structure());
  const double jacobian = time_us(100, [&] { eq.minimal_jacobian(t, z, z_dot, z_ddot, blocks); });
  ffrf::solve::BorderedBandMatrix effective(eq.minimal_structure());
  ffrf::solve::BorderedBandLU lu(eq.minimal_structure());
  const double gamma = 0.01;
  const double factor = time_us(200, [&] {
    effective.assign_combination(1.0, blocks.mass, gamma, blocks.damping, gamma * gamma, blocks.stiffness);
    lu.factorize(effective);
  });
  Eigen::VectorXd b = Eigen::VectorXd::Ones(n), work(n);
  const double solve = time_us(2000, [&] {
    blocks.mass.multiply(b, work);
    blocks.stiffness.multiply(b, work);
    lu.solve(work);
  });
  const double output = time_us(2000, [&] { (void)eq.minimal_outputs_with_accelerations(t, z, z_dot, z_ddot); });
  const long outputs = std::lround(s.duration / s.output_interval) + 1;
  const long own_rhs = stats.function_evaluations - stats.jacobian_evaluations * eq.minimal_jacobian_evaluations();
  struct Part {
    const char* name;
    double unit_us;
    long count;
  };
  const std::vector<Part> parts = {{"right-hand sides", rhs, own_rhs},
                                   {"Jacobians (blocks)", jacobian, stats.jacobian_evaluations},
                                   {"Newton matrix S = M + γD + γ²K, factorization", factor, stats.linear_setups},
                                   {"Newton solves (reduction + back-substitution)", solve, stats.newton_iterations},
                                   {"output samples", output, outputs}};
  double accounted = 0.0;
  fmt::print("    | part | µs each | count | ms | share |\n    |---|--:|--:|--:|--:|\n");
  for (const Part& p : parts) {
    const double ms = 1e-3 * p.unit_us * static_cast<double>(p.count);
    accounted += ms;
    fmt::print("    | {} | {:.2f} | {} | {:.1f} | {:.0f} % |\n", p.name, p.unit_us, p.count, ms, 100.0 * ms / wall_ms);
  }
  fmt::print("    | CVODE's own work (vectors, error test, interpolation), the remainder | | | {:.1f} | {:.0f} % |\n",
             wall_ms - accounted, 100.0 * (wall_ms - accounted) / wall_ms);
}
#endif

void run_case(benchmark::State& state, Context* context, Case c) {
  const std::string key = key_of(c);
  state.SetLabel(key);
  const scene_library::Scene& scene = context->scenes.at(c.scene);
  std::unique_ptr<ffrf::multibody::CraneEquations> equations;
  Eigen::VectorXd z0;
  try {
    equations = scene_library::build_crane_equations(scene, c.choice);
    const auto statics = ffrf::multibody::solve_static_equilibrium(*equations, equations->initial_guess());
    z0 = scene.simulation.initial_state == scene_library::InitialState::static_equilibrium ? statics.z : equations->initial_guess();
  } catch (const std::exception& error) {
    context->errors[key] = error.what();
    state.SkipWithError(error.what());
    return;
  }
  const auto settings = settings_for(*context, c, scene);
  ffrf::solve::SolverStats stats;
  for (auto _ : state) {
    try {
      const auto result = ffrf::multibody::simulate(*equations, z0, settings);
      benchmark::DoNotOptimize(result.samples.data());
      stats = result.stats;
    } catch (const std::exception& error) {
      context->errors[key] = error.what();
      state.SkipWithError(error.what());
      break;
    }
  }
  if (state.error_occurred()) return;
  CraneRow& row = context->rows[key];
  row.key = key;
  row.model = (c.spin_up ? "spin-up " : "") + c.choice.label();
  row.integrator = std::string(to_string(c.integrator));
  row.elements = c.choice.kind == BoomKind::nodal && !c.spin_up ? c.choice.elements : 0;
  row.duration = settings.duration;
  row.steps = stats.steps;
  row.rhs = stats.function_evaluations;
  row.jacobians = stats.jacobian_evaluations;
  row.newton = stats.newton_iterations;
  state.counters["steps"] = static_cast<double>(stats.steps);
  state.counters["f_evals"] = static_cast<double>(stats.function_evaluations);
  state.counters["jac_evals"] = static_cast<double>(stats.jacobian_evaluations);
}

// Collects the best wall time per case [ms] while the console reporter prints.
class TableCollector : public benchmark::ConsoleReporter {
 public:
  TableCollector() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}
  std::map<std::string, double> best_ms;
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred || run.run_type != Run::RT_Iteration) continue;
      const double ms = run.GetAdjustedRealTime();
      const auto it = best_ms.find(run.report_label);
      if (it == best_ms.end() || ms < it->second) best_ms[run.report_label] = ms;
    }
  }
};

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::string::size_type start = 0;
  while (start <= list.size()) {
    const auto end = list.find(',', start);
    out.push_back(list.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const char* quick_env = std::getenv("FFRF_BENCH_QUICK");
  bool quick = quick_env != nullptr && *quick_env != '\0' && std::string_view(quick_env) != "0";
  double duration = 0.0;
  int repetitions = 1;
  std::string csv, before, after;
  bool breakdown_all = false;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a(argv[i]);
    if (a == "--quick") quick = true;
    else if (a == "--all") continue;  // accepted for compatibility: every case runs
    else if (a.starts_with("--duration=")) duration = std::stod(std::string(a.substr(11)));
    else if (a.starts_with("--repetitions=")) repetitions = std::stoi(std::string(a.substr(14)));
    else if (a.starts_with("--csv=")) csv = std::string(a.substr(6));
    else if (a.starts_with("--before=")) before = std::string(a.substr(9));
    else if (a.starts_with("--after=")) after = std::string(a.substr(8));
    else if (a == "--breakdown") breakdown_all = true;
    else argv[kept++] = argv[i];
  }
  argc = kept;
  if (!after.empty()) {  // report mode: merge CSV files of two builds
    try {
      const auto before_rows = before.empty() ? std::vector<CraneRow>{} : ffrf::bench::read_best_rows(split(before));
      const auto after_rows = ffrf::bench::read_best_rows(split(after));
      fmt::print("Coupled crane, reference scene ({} s simulated; spin-up: its scene's 30 s), rtol = atol = {:g}, best of "
                 "each build's runs\n\n",
                 after_rows.empty() ? 0.0 : after_rows.front().duration, kTolerance);
      ffrf::bench::print_table(before_rows, after_rows);
      fmt::print("\nreal-time-factor targets (after; 120 s runs only):\n");
      for (const auto& target : ffrf::bench::targets()) {
        const CraneRow* r = ffrf::bench::find_row(after_rows, target.key);
        if (!r || r->duration != kFullDuration) continue;
        fmt::print("  {:<34} {:>7.0f}× real time, target ≥ {:g}×: {}\n", target.key, r->real_time_factor(),
                   target.real_time_factor, r->real_time_factor() >= target.real_time_factor ? "met" : "MISSED");
      }
    } catch (const std::exception& error) {
      fmt::print(stderr, "{}\n", error.what());
      return 1;
    }
    return 0;
  }

  Context context;
  context.duration = duration > 0.0 ? duration : quick ? kQuickDuration : kFullDuration;
  try {
    for (const Case& c : cases()) {
      if (!context.scenes.count(c.scene)) context.scenes[c.scene] = scene_library::load_scene(FFRF_SOURCE_DIR "/cases/" + c.scene);
    }
  } catch (const std::exception& error) {
    fmt::print(stderr, "bench_crane: {}\n", error.what());
    return 1;
  }
  for (const Case& c : cases()) {
    context.order.push_back(key_of(c));
    const std::string name = fmt::format("crane/{}/{}{}", to_string(c.integrator), c.spin_up ? "spin-up/" : "",
                                         c.choice.kind == BoomKind::rigid   ? std::string("rigid")
                                         : c.choice.kind == BoomKind::nodal ? fmt::format("nodal/N:{}", c.choice.elements)
                                                                            : fmt::format("modal/k:{}{}", c.choice.modes, c.choice.static_modes ? "+static" : ""));
    benchmark::RegisterBenchmark(name.c_str(), run_case, &context, c)
        ->Iterations(1)
        ->Repetitions(repetitions)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  TableCollector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();

  std::vector<CraneRow> rows;
  for (const std::string& key : context.order) {
    const auto row = context.rows.find(key);
    const auto time = collector.best_ms.find(key);
    if (row == context.rows.end() || time == collector.best_ms.end()) {
      if (context.errors.count(key)) fmt::print("{}: failed: {}\n", key, context.errors[key]);
      continue;
    }
    row->second.wall_ms = time->second;
    rows.push_back(row->second);
  }
  if (rows.empty()) return 0;  // --benchmark_list_tests or a filter that matched nothing
  if (!csv.empty()) ffrf::bench::write_rows(csv, rows);
  fmt::print("\nCoupled crane, {} s simulated (spin-up: its scene's 30 s), rtol = atol = {:g}, best of {}\n\n", context.duration,
             kTolerance, repetitions);
  ffrf::bench::print_table({}, rows);
#ifdef FFRF_BENCH_BREAKDOWN
  for (const auto& target : ffrf::bench::targets()) {
    const CraneRow* r = ffrf::bench::find_row(rows, target.key);
    if (!r || context.duration != kFullDuration) continue;
    const bool met = r->real_time_factor() >= target.real_time_factor;
    fmt::print("\n{}: {:.0f}× real time, target ≥ {:g}×: {}\n", target.key, r->real_time_factor(), target.real_time_factor,
               met ? "met" : "MISSED — where the time goes:");
    if (met && !breakdown_all) continue;
    if (met) fmt::print("  where the time goes:\n");
    for (const Case& c : cases()) {
      if (key_of(c) != target.key) continue;
      const auto& scene = context.scenes.at(c.scene);
      auto eq = scene_library::build_crane_equations(scene, c.choice);
      const Eigen::VectorXd z0 = ffrf::multibody::solve_static_equilibrium(*eq, eq->initial_guess()).z;
      const auto settings = settings_for(context, c, scene);
      const auto result = ffrf::multibody::simulate(*eq, z0, settings);
      print_breakdown(*eq, z0, settings, result.stats, r->wall_ms);
    }
  }
#endif
  return 0;
}
