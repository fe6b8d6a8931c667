// Benchmark of what `ffrf recommend` saves: the wall time of the model `ffrf recommend` chooses on the reference
// scene at 1 % against its converged reference, measured side by side in one run. The choice is made
// here by the real recommend study (study::recommend: reasoning, reference, verification runs) — no
// model is hard-coded — and both runs go through the one pipeline (study/run_pipeline.hpp): model
// construction, the KINSOL static equilibrium and the initial state outside the timed region, the
// integration inside. After Google Benchmark's output it prints the ratio and the solver work
// (RHS evaluations × state size). Options (before Google Benchmark's own): --duration=SECONDS another
// simulated time (default: the scene's 120 s), --tolerance=FRACTION another tolerance (default 0.01).
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <exception>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unistd.h>

#include "scene/scene_loader.hpp"
#include "study/recommend.hpp"
#include "study/run_pipeline.hpp"

namespace {

using namespace ffrf;

struct Model {
  std::string name;
  scene::BoomChoice choice;
  multibody::RunSettings settings;
};

struct Measured {
  double milliseconds = 0.0;
  double work = 0.0;  // RHS evaluations × state size (study::solver_work)
  long steps = 0;
};

struct Comparison {
  scene::Scene scene;  // with the stiffening the reference needs (recommend's reference scene)
  std::map<std::string, Measured> measured;
};

void integrate_model(benchmark::State& state, Comparison* context, const Model& model) {
  state.SetLabel(model.name);
  study::PreparedRun prepared = study::prepare_run(context->scene, model.choice);
  long steps = 0;
  double work = 0.0;
  for (auto _ : state) {
    try {
      const study::ModelRun run = study::integrate_run(context->scene, prepared, model.settings);
      benchmark::DoNotOptimize(run.result.samples.data());
      steps = run.result.stats.steps;
      work = run.work();
    } catch (const std::exception& error) {
      state.SkipWithError(error.what());
      return;
    }
  }
  context->measured[model.name].steps = steps;
  context->measured[model.name].work = work;
  state.counters["steps"] = static_cast<double>(steps);
}

class Collector : public benchmark::ConsoleReporter {
 public:
  explicit Collector(Comparison* context)
      : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular), comparison_(context) {}
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
  study::RecommendRequest request;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument(argv[i]);
    if (argument.starts_with("--duration=")) {
      request.duration = std::stod(std::string(argument.substr(11)));
    } else if (argument.starts_with("--tolerance=")) {
      request.tolerance = std::stod(std::string(argument.substr(12)));
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  const scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  fmt::print("recommend at {:g} on {} (the choice is made by study::recommend) ...\n", request.tolerance, scene.file);
  const study::Recommendation rec = study::recommend(scene, request);
  if (!rec.chosen) {
    fmt::print("recommend found no model within {:g}: nothing to benchmark\n", request.tolerance);
    return 1;
  }
  const study::Candidate& chosen = rec.candidates[*rec.chosen];
  Comparison context{rec.reference_scene, {}};
  study::DynamicsRequest dynamics;
  dynamics.integrator = chosen.integrator;
  dynamics.relative_tolerance = dynamics.absolute_tolerance = rec.reasoning.relative_tolerance;
  dynamics.duration = rec.duration;
  const std::vector<Model> models{{"reference", rec.reference.choice, rec.reference.settings},
                                  {"recommended", chosen.choice, study::integrator_settings(rec.reference_scene, dynamics)}};
  for (const Model& model : models) {
    benchmark::RegisterBenchmark(fmt::format("recommend/{}", model.name).c_str(), integrate_model, &context, model)
        ->Iterations(model.name == "reference" ? 2 : 10)
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
    fmt::print("\nreference scene, {:g} s simulated: reference {} at rtol {:g}: {:.1f} ms ({} steps); recommended {}, {} at "
               "rtol {:g}: {:.1f} ms ({} steps)\nwall-time ratio {:.1f}x, solver-work ratio {:.1f}x (RHS evaluations x state size)\n",
               rec.duration, rec.reference.choice.label(), rec.reference.settings.relative_tolerance, reference.milliseconds,
               reference.steps, chosen.choice.label(), solve::to_string(chosen.integrator), rec.reasoning.relative_tolerance,
               recommended.milliseconds, recommended.steps, reference.milliseconds / recommended.milliseconds,
               reference.work / recommended.work);
  }
  return 0;
}
