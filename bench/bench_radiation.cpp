// Cost per time step of the three radiation models of the Cummins equation on the WAMIT fixture's
// barge (surge, heave, pitch; tests/hydro/data): constant A, B; the fitted state-space model (order
// chosen for a 2 % and a 0.5 % impulse-response error); the convolution with the retardation
// function (trapezoid over T_c / h samples). One step = the memory force at the new velocity plus
// pushing that velocity into the model's history or state. Also a whole Newmark step of the hull
// (bench "cummins_step"). After Google Benchmark's output, a table of ns per step and the ratio to
// the constant model, all measured in this one run.
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <map>
#include <memory>
#include <string>
#include <unistd.h>

#include "hydro/cummins_solver.hpp"
#include "hydro/wamit_reader.hpp"

namespace {

using namespace ffrf::hydro;

struct Fixture {
  PlanarRadiation radiation;
  RetardationFunction kernel;
  PlanarMatrix stiffness;
  Fixture() {
    const std::string data = std::string(FFRF_SOURCE_DIR) + "/tests/hydro/data/";
    radiation = read_wamit_radiation(data + "barge.1", {1.0, 1000.0, 9.81});
    stiffness = read_wamit_hydrostatics(data + "barge.hst", {1.0, 1000.0, 9.81});
    kernel = retardation_function(radiation, {.time_step = 0.05});
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

std::unique_ptr<RadiationModel> make_model(const std::string& kind) {
  const auto& f = fixture();
  if (kind == "constant") return std::make_unique<ConstantRadiationModel>(radiation_at(f.radiation, 1.05));
  if (kind == "convolution") return std::make_unique<ConvolutionRadiationModel>(f.kernel);
  const double tolerance = kind == "state_space_2pct" ? 0.02 : 0.005;
  return std::make_unique<StateSpaceRadiationModel>(fit_state_space(f.kernel, {.tolerance = tolerance}),
                                                    f.kernel.infinite_frequency_added_mass, f.kernel.time_step);
}

void radiation_step(benchmark::State& state, const std::string& kind) {
  auto model = make_model(kind);
  PlanarVector velocity(0.1, 0.2, 0.01);
  const double c = std::cos(0.05), s = std::sin(0.05);
  for (auto _ : state) {
    const PlanarVector force = model->memory_force(velocity);
    benchmark::DoNotOptimize(force.data());
    model->push(velocity);
    velocity = PlanarVector(c * velocity(0) - s * velocity(1), s * velocity(0) + c * velocity(1), velocity(2));
  }
  state.SetLabel(kind);
  if (const auto* ss = dynamic_cast<const StateSpaceRadiationModel*>(model.get())) state.counters["order"] = ss->order();
  if (const auto* cv = dynamic_cast<const ConvolutionRadiationModel*>(model.get()))
    state.counters["history"] = static_cast<double>(cv->history_length());
}

void cummins_steps(benchmark::State& state, const std::string& kind) {
  auto model = make_model(kind);
  const auto& f = fixture();
  PlanarMatrix mass = PlanarMatrix::Zero();
  mass.diagonal() << 4.0e6, 4.0e6, 2.166667e9;
  constexpr std::size_t steps = 2000;  // 100 s
  for (auto _ : state) {
    const auto rec = integrate_cummins(mass, f.stiffness, *model, PlanarVector(0, 1, 0.01), PlanarVector::Zero(), 0.05, steps);
    benchmark::DoNotOptimize(rec.position.back().data());
  }
  state.SetLabel("cummins_" + kind);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps));
}

class Collector : public benchmark::ConsoleReporter {
 public:
  Collector() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}
  std::map<std::string, double> nanoseconds;
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred || run.run_type != Run::RT_Iteration) continue;
      double ns = run.GetAdjustedRealTime();  // in run.time_unit
      if (run.report_label.rfind("cummins_", 0) == 0) ns = ns * 1e6 / 2000.0;  // ms per 2000 steps → ns per step
      nanoseconds[run.report_label] = ns;
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  const std::string kinds[] = {"constant", "state_space_2pct", "state_space_0.5pct", "convolution"};
  for (const auto& kind : kinds) {
    benchmark::RegisterBenchmark(("radiation_step/" + kind).c_str(), radiation_step, kind)->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark(("cummins_step/" + kind).c_str(), cummins_steps, kind)->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Collector table;
  benchmark::RunSpecifiedBenchmarks(&table);
  benchmark::Shutdown();
  const auto& f = fixture();
  fmt::print("\nRadiation models, barge fixture (3 DOF), step h = 0.05 s, kernel T_c = {:.2f} s ({} samples)\n\n",
             f.kernel.truncation_time, f.kernel.kernel.size() - 1);
  fmt::print("| model | memory force + push [ns/step] | ratio | Newmark hull step [ns/step] | ratio |\n|---|---:|---:|---:|---:|\n");
  const double base = table.nanoseconds.count("constant") ? table.nanoseconds.at("constant") : 0.0;
  const double base_step = table.nanoseconds.count("cummins_constant") ? table.nanoseconds.at("cummins_constant") : 0.0;
  for (const auto& kind : kinds) {
    const auto force = table.nanoseconds.find(kind), step = table.nanoseconds.find("cummins_" + kind);
    if (force == table.nanoseconds.end() || step == table.nanoseconds.end()) continue;
    fmt::print("| {} | {:.1f} | {:.1f} | {:.1f} | {:.1f} |\n", kind, force->second, base > 0 ? force->second / base : 0.0,
               step->second, base_step > 0 ? step->second / base_step : 0.0);
  }
  return 0;
}
