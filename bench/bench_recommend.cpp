// Benchmark of issue 6's claim: the wall time of the model `ffrf recommend` chooses on the reference
// scene at 1 % (nodal N = 1 with static stiffening, CVODE rtol = atol = 1e-4; docs/recommend.md)
// against its converged reference (nodal N = 16 with static stiffening, rtol = atol = 1e-7), both
// 120 s simulated from static equilibrium (cases/paper_floating_crane.toml), measured side by side
// in one run. Model construction and the KINSOL static equilibrium are outside the timed region.
// After Google Benchmark's output it prints the ratio and the solver work (steps × state size).
// Options (before Google Benchmark's own): --duration=SECONDS another simulated time.
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <exception>
#include <map>
#include <string>
#include <string_view>
#include <unistd.h>

#include "cases/crane_builder.hpp"
#include "cases/scene_loader.hpp"
#include "coupling/simulation.hpp"
#include "coupling/static_equilibrium.hpp"

namespace {

using ffrf::cases::BoomChoice;
using ffrf::cases::BoomKind;
using ffrf::cases::Stiffening;

struct Model {
  const char* name;
  BoomChoice choice;
  double tolerance;
};

struct Measured {
  double milliseconds = 0.0;
  double work = 0.0;  // steps × state size (2 × minimal coordinates)
  long steps = 0;
};

struct Comparison {
  ffrf::cases::Scene scene;
  double duration = 120.0;
  std::map<std::string, Measured> measured;
};

const Model kReference{"reference", {BoomKind::nodal, 16, 0, false, ffrf::modal::EigenSolverKind::arpack, Stiffening::static_load}, 1e-7};
const Model kRecommended{"recommended", {BoomKind::nodal, 1, 0, false, ffrf::modal::EigenSolverKind::arpack, Stiffening::static_load}, 1e-4};

void run_model(benchmark::State& state, Comparison* context, Model model) {
  state.SetLabel(model.name);
  const auto equations = ffrf::cases::build_crane(context->scene, model.choice);
  const Eigen::VectorXd z0 = ffrf::coupling::solve_static_equilibrium(*equations, equations->initial_guess()).z;
  ffrf::coupling::IntegratorSettings settings;
  settings.kind = ffrf::coupling::Integrator::cvode;
  settings.relative_tolerance = model.tolerance;
  settings.absolute_tolerance = model.tolerance;
  settings.duration = context->duration;
  settings.output_interval = context->scene.simulation.output_interval;
  long steps = 0;
  for (auto _ : state) {
    try {
      const auto result = ffrf::coupling::integrate(*equations, z0, settings);
      benchmark::DoNotOptimize(result.samples.data());
      steps = result.stats.steps;
    } catch (const std::exception& error) {
      state.SkipWithError(error.what());
      return;
    }
  }
  context->measured[model.name].steps = steps;
  context->measured[model.name].work = static_cast<double>(steps) * 2.0 * equations->minimal_size();
  state.counters["steps"] = static_cast<double>(steps);
}

class Collector : public benchmark::ConsoleReporter {
 public:
  Collector(Comparison* context) : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular), comparison_(context) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (!run.error_occurred && run.run_type == Run::RT_Iteration) comparison_->measured[run.report_label].milliseconds = run.GetAdjustedRealTime();
    }
  }

 private:
  Comparison* comparison_;
};

}  // namespace

int main(int argc, char** argv) {
  Comparison context;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument(argv[i]);
    if (argument.starts_with("--duration=")) {
      context.duration = std::stod(std::string(argument.substr(11)));
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  context.scene = ffrf::cases::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  for (const Model& model : {kReference, kRecommended}) {
    benchmark::RegisterBenchmark(fmt::format("recommend/{}", model.name).c_str(), run_model, &context, model)
        ->Iterations(model.tolerance < 1e-6 ? 2 : 10)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Collector collector(&context);
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();
  const Measured& reference = context.measured["reference"];
  const Measured& recommended = context.measured["recommended"];
  if (reference.milliseconds > 0.0 && recommended.milliseconds > 0.0) {
    fmt::print("\nreference scene, {} s simulated: reference {:.1f} ms ({} steps), recommended {:.1f} ms ({} steps)\n"
               "wall-time ratio {:.1f}x, solver-work ratio {:.1f}x (steps x state size)\n",
               context.duration, reference.milliseconds, reference.steps, recommended.milliseconds, recommended.steps,
               reference.milliseconds / recommended.milliseconds, reference.work / recommended.work);
  }
  return 0;
}
