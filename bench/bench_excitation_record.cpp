// The first-order BEM wave excitation per call: the exact sum BemExcitation::at (a sine and cosine per
// component) against the record of it (sea/excitation_record.hpp: one segment lookup and a quintic
// Hermite interpolation per channel), in the sea of cases/irregular_bem_barge_crane.toml (the WAMIT
// barge, JONSWAP Hs 2 m, Tp 8 s over 3 hours: 3 376 components), and the exact sum of a regular wave
// (one component) as the cost to match. Times march through the record by 13.7 ms per call, as an
// integrator's right-hand sides do; the record is also read at random times (every call a cache miss
// in a record larger than the cache). After the table: the ratio per call, and the record's time
// step, samples, memory, build time and measured midpoint error at three tolerances.
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "sea/bem_excitation.hpp"
#include "sea/excitation_record.hpp"
#include "scene/bem_hull_model.hpp"
#include "scene/irregular_sea.hpp"
#include "scene/scene_loader.hpp"

namespace {

using namespace ffrf;

constexpr double march_step = 0.0137;  // [s] between calls
constexpr int random_times = 4096;

struct Sea {
  sea::WaveField wave;
  sea::BemExcitation excitation;
};

// The scene's sea and its BEM excitation, as scene/bem_hull_model.cpp builds them (G1 at x = 0).
Sea scene_sea(const scene::Scene& scene) {
  const std::optional<sea::WaveField> wave = scene::scene_wave_field(scene);
  if (!wave || !scene.bem || !scene.bem->excitation_table) throw std::runtime_error("the scene has no sea or no BEM excitation");
  const Eigen::Vector2d origin = scene::bem_origin_offset(scene);
  return {*wave, sea::bem_excitation(*scene.bem->excitation_table, *wave, origin.x(), origin)};
}

template <class Excitation>
void marching(benchmark::State& state, const Excitation* excitation, double duration) {
  double t = 0.0, sink = 0.0;
  for (auto _ : state) {
    sink += excitation->at(t).sum();
    t += march_step;
    if (t > duration) t -= duration;
  }
  benchmark::DoNotOptimize(sink);
}

void random_access(benchmark::State& state, const sea::ExcitationRecord* record) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> time(0.0, record->duration());
  std::vector<double> times(random_times);
  for (double& t : times) t = time(random);
  std::size_t k = 0;
  double sink = 0.0;
  for (auto _ : state) {
    sink += record->at(times[k]).sum();
    k = (k + 1) % times.size();
  }
  benchmark::DoNotOptimize(sink);
}

struct Collector : benchmark::ConsoleReporter {
  std::map<std::string, double> nanoseconds;  // per call
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Iteration) nanoseconds[run.benchmark_name()] = run.GetAdjustedRealTime();
    }
  }
};

sea::ExcitationRecord record_at(const Sea& sea, double duration, double fraction) {
  sea::ExcitationRecordOptions options;
  options.duration = duration;
  options.tolerance = sea::excitation_tolerance(sea.excitation, fraction);
  auto outcome = sea::ExcitationRecord::build(sea.excitation, sea.wave, options);
  if (!outcome.record) throw std::runtime_error("no excitation record: " + outcome.refusal);
  return std::move(*outcome.record);
}

}  // namespace

int main(int argc, char** argv) {
  const scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/irregular_bem_barge_crane.toml");
  const double duration = scene.simulation.duration;
  static const Sea sea = scene_sea(scene);
  // The regular wave of the sea's significant height and peak period: the cost to match.
  static const sea::BemExcitation regular = sea::bem_excitation(
      *scene.bem->excitation_table, sea::WaveField::regular(2.0, 8.0, 1.0, 0.0, sea.wave.depth(), sea.wave.gravity()),
      scene::bem_origin_offset(scene).x(), scene::bem_origin_offset(scene));
  static const sea::ExcitationRecord record = record_at(sea, duration, sea::kDefaultExcitationFraction);

  const auto unit = benchmark::kNanosecond;
  benchmark::RegisterBenchmark("excitation/exact/sea", marching<sea::BemExcitation>, &sea.excitation, duration)->Unit(unit);
  benchmark::RegisterBenchmark("excitation/record/sea", marching<sea::ExcitationRecord>, &record, duration)->Unit(unit);
  benchmark::RegisterBenchmark("excitation/record/sea/random", random_access, &record)->Unit(unit);
  benchmark::RegisterBenchmark("excitation/exact/regular", marching<sea::BemExcitation>, &regular, duration)->Unit(unit);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();

  const auto at = [&](const std::string& name) {
    const auto it = collector.nanoseconds.find(name);
    return it == collector.nanoseconds.end() ? std::nan("") : it->second;
  };
  const double exact = at("excitation/exact/sea"), recorded = at("excitation/record/sea");
  const double random = at("excitation/record/sea/random"), one = at("excitation/exact/regular");
  fmt::print("\nBEM excitation per call, {} ({} components, {:.0f} s) [ns]\n\n", scene.name, sea.excitation.force.size(),
             duration);
  fmt::print("| exact sum | record, marching | record, random t | exact, regular wave | exact / record |\n");
  fmt::print("|---:|---:|---:|---:|---:|\n| {:.0f} | {:.1f} | {:.1f} | {:.1f} | {:.0f} |\n", exact, recorded, random, one,
             exact / recorded);

  const Eigen::Vector3d sigma = sea::excitation_standard_deviation(sea.excitation);
  fmt::print("\nThe record over {:.0f} s; sigma = {:.4g} N, {:.4g} N, {:.4g} N m (surge, heave, pitch)\n\n", duration,
             sigma(0), sigma(1), sigma(2));
  fmt::print("| tolerance [sigma] | time step [s] | samples | memory [MB] | build [s] | midpoint error [tolerance] |\n");
  fmt::print("|---:|---:|---:|---:|---:|---:|\n");
  const auto row = [](const sea::ExcitationRecord& r, double fraction, const char* note) {
    fmt::print("| {:.0e}{} | {:.4f} | {} | {:.1f} | {:.3f} | {:.3f} |\n", fraction, note, r.time_step(), r.samples(),
               static_cast<double>(r.memory_bytes()) / 1e6, r.build_seconds(), r.midpoint_error_fraction());
  };
  for (const double fraction : {1e-6, 1e-7}) row(record_at(sea, duration, fraction), fraction, "");
  row(record, sea::kDefaultExcitationFraction, " (default)");
  row(record_at(sea, duration, 1e-9), 1e-9, "");
  return 0;
}
