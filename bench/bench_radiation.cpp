// Cost of the three radiation models (constant A, B; the fitted state-space model for a 2 % and a
// 0.5 % impulse-response error; the Cummins convolution) on the WAMIT fixture's barge (surge, heave,
// pitch; tests/hydro/data), measured side by side in one run:
//  * radiation_force/KIND: one evaluation of the memory force μ(t, ẋ) at a trial time between the
//    recorded samples (what a right-hand side or residual of the crane costs more), with the history
//    recorded every 0.05 s;
//  * crane_run/KIND: the whole crane of cases/bem_barge_crane.toml (nodal N = 12 boom, CVODE,
//    rtol 1e-6, BEM excitation) over 30 s: wall time per integrator step, and the steps taken.
// After Google Benchmark's output, a table of the costs and their ratios to the constant model.
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <map>
#include <memory>
#include <string>
#include <unistd.h>

#include "hydro/radiation_memory.hpp"
#include "hydro/wamit_reader.hpp"
#include "scene/scene_loader.hpp"
#include "study/radiation_compare.hpp"

namespace {

using namespace ffrf::hydro;

struct Fixture {
  PlanarRadiation radiation;
  RetardationFunction kernel;
  Fixture() {
    const std::string data = std::string(FFRF_SOURCE_DIR) + "/tests/hydro/data/";
    radiation = read_wamit_radiation(data + "barge.1", {1.0, 1000.0, 9.81});
    kernel = retardation_function(radiation, {.time_step = 0.05});
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

std::shared_ptr<const RadiationMemoryModel> make_model(const std::string& kind) {
  const auto& f = fixture();
  if (kind == "constant") return std::make_shared<const RadiationMemoryModel>(constant_memory(radiation_at(f.radiation, 1.05)));
  if (kind == "convolution") return std::make_shared<const RadiationMemoryModel>(convolution_memory(f.kernel));
  const double tolerance = kind == "state_space_2pct" ? 0.02 : 0.005;
  return std::make_shared<const RadiationMemoryModel>(
      state_space_memory(fit_state_space(f.kernel, {.tolerance = tolerance}), f.kernel.infinite_frequency_added_mass));
}

void radiation_force(benchmark::State& state, const std::string& kind) {
  const auto model = make_model(kind);
  RadiationMemory memory(model);
  const double h = 0.05;
  for (int n = 0; n <= 1000; ++n) {  // 50 s of history, longer than T_c
    memory.record(n * h, PlanarVector(0.1 * std::sin(0.05 * n), 0.2 * std::cos(0.05 * n), 0.01));
  }
  double t = 1000 * h + 0.37 * h;
  const PlanarVector velocity(0.1, 0.2, 0.01);
  for (auto _ : state) {
    const PlanarVector force = memory.force(t, velocity);
    benchmark::DoNotOptimize(force.data());
    t += 1e-9;
  }
  state.SetLabel(kind);
  state.counters["order"] = model->order;
  state.counters["kernel_samples"] = static_cast<double>(model->kernel.kernel.size());
}

std::map<std::string, long> crane_steps;

void crane_run(benchmark::State& state, const std::string& kind) {
  ffrf::scene::Scene scene = ffrf::scene::load_scene(std::string(FFRF_SOURCE_DIR) + "/cases/bem_barge_crane.toml");
  if (kind != "constant" && kind != "convolution") scene.bem->state_space_tolerance = kind == "state_space_2pct" ? 0.02 : 0.005;
  RadiationKind radiation = RadiationKind::constant;
  parse_radiation_kind(kind == "constant" || kind == "convolution" ? kind : "state-space", radiation);
  const ffrf::scene::Scene modelled = ffrf::study::with_radiation(scene, radiation);
  ffrf::multibody::RunSettings settings;
  settings.duration = 30.0;
  settings.output_interval = 0.05;
  long steps = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto prepared = ffrf::study::prepare_run(modelled, {ffrf::scene::BoomKind::nodal, 12});  // fit cached, outside the timing
    state.ResumeTiming();
    const auto result = ffrf::multibody::simulate(*prepared.equations, prepared.initial_state, settings);
    steps = result.stats.steps;
    benchmark::DoNotOptimize(result.time.data());
  }
  crane_steps["crane_" + kind] = steps;
  state.SetLabel("crane_" + kind);
  state.counters["steps"] = static_cast<double>(steps);
}

class Collector : public benchmark::ConsoleReporter {
 public:
  Collector() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}
  std::map<std::string, double> nanoseconds;
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred || run.run_type != Run::RT_Iteration) continue;
      nanoseconds[run.report_label] = run.GetAdjustedRealTime();  // in run.time_unit (ns or ms)
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  const std::string kinds[] = {"constant", "state_space_2pct", "state_space_0.5pct", "convolution"};
  for (const auto& kind : kinds) {
    benchmark::RegisterBenchmark(("radiation_force/" + kind).c_str(), radiation_force, kind)->Unit(benchmark::kNanosecond);
  }
  for (const auto& kind : kinds) {
    benchmark::RegisterBenchmark(("crane_run/" + kind).c_str(), crane_run, kind)->Unit(benchmark::kMillisecond)->Iterations(3);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Collector table;
  benchmark::RunSpecifiedBenchmarks(&table);
  benchmark::Shutdown();
  const auto& f = fixture();
  fmt::print("\nRadiation models, barge fixture (3 DOF), kernel dt = 0.05 s, T_c = {:.2f} s ({} samples); crane: "
             "cases/bem_barge_crane.toml, nodal N = 12, CVODE rtol 1e-6, 30 s\n\n",
             f.kernel.truncation_time, f.kernel.kernel.size());
  fmt::print("| model | memory force [ns/evaluation] | ratio | crane steps | crane [µs/step] | ratio |\n|---|---:|---:|---:|---:|---:|\n");
  const auto per_step = [&](const std::string& kind) {
    const auto ms = table.nanoseconds.find("crane_" + kind);
    const auto steps = crane_steps.find("crane_" + kind);
    return ms == table.nanoseconds.end() || steps == crane_steps.end() || steps->second == 0
               ? 0.0
               : ms->second * 1e3 / static_cast<double>(steps->second);
  };
  const double base = table.nanoseconds.count("constant") ? table.nanoseconds.at("constant") : 0.0;
  const double base_step = per_step("constant");
  for (const auto& kind : kinds) {
    const auto force = table.nanoseconds.find(kind);
    if (force == table.nanoseconds.end()) continue;
    const double step = per_step(kind);
    fmt::print("| {} | {:.1f} | {:.1f} | {} | {:.1f} | {:.2f} |\n", kind, force->second, base > 0 ? force->second / base : 0.0,
               crane_steps.count("crane_" + kind) ? crane_steps.at("crane_" + kind) : 0L, step,
               base_step > 0 ? step / base_step : 0.0);
  }
  return 0;
}
