// Benchmark of one hull pressure integral (sea/hull_pressure.hpp) on the reference hull
// (90 m × 40 m × 8 m box floating at its loaded draft, slightly trimmed), closed form against the
// sampled-and-bisected Gauss–Legendre quadrature it replaced (tests/sea/hull_pressure_quadrature.hpp,
// 64 samples per edge), in calm water, in the reference scene's regular wave (H = 1 m, T = 10 s), and
// in irregular seas of 1 to 256 components (periods 4–25 s, amplitudes scaled so that Σ a_i = 1 m),
// deep water and 30 m depth. The time is per call, averaged over a sweep of 64 times through a wave
// period so every waterline position is visited. Cost per component = slope of the time against the
// component count (printed after Google Benchmark's table).
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <vector>

#include "../tests/sea/hull_pressure_quadrature.hpp"
#include "sea/hull_pressure.hpp"
#include "sea/wave_field.hpp"

namespace {

using ffrf::sea::BoxHullSection;
using ffrf::sea::ComponentSpec;
using ffrf::sea::WaveField;

constexpr double rho = 1025.0, g = 9.81;
const BoxHullSection hull{-32.0, 58.0, -6.0, 2.0, 40.0};
const Eigen::Vector2d g1(0.0, 1.91);  // G1 6 m above the keel, keel 4.09 m below still water (the loaded draft)
constexpr double pitch = 0.004;
constexpr int times = 64;

WaveField sea(int components, double depth) {
  std::vector<ComponentSpec> list;
  for (int i = 0; i < components; ++i) {
    const double period = 4.0 + 21.0 * (i + 0.5) / components;
    list.push_back({2.0 * std::numbers::pi / period, 1.0 / components, 2.399963 * i});  // golden-angle phases
  }
  return WaveField::from_components(list, 1.0, 0.0, depth, g);
}

double sample_time(int i) { return 10.0 * i / times + 40.0; }

void closed_form(benchmark::State& state, const WaveField* wave) {
  double sink = 0.0;
  for (auto _ : state) {
    for (int i = 0; i < times; ++i) {
      const auto load = ffrf::sea::hull_pressure_load(hull, wave, rho, g, g1, pitch, sample_time(i));
      sink += load.force.y();
    }
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations() * times);
}

void quadrature(benchmark::State& state, const WaveField* wave) {
  double sink = 0.0;
  for (auto _ : state) {
    for (int i = 0; i < times; ++i) {
      const ffrf::sea::testing::QuadratureHullPressure method(wave, rho, g, sample_time(i));
      sink += method.load(hull, g1, pitch).force.y();
    }
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations() * times);
}

struct Collector : benchmark::ConsoleReporter {
  std::map<std::string, double> nanoseconds;  // per call
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Iteration) nanoseconds[run.benchmark_name()] = run.GetAdjustedRealTime() / times;
    }
  }
};

}  // namespace

int main(int argc, char** argv) {
  static const WaveField regular = WaveField::regular(1.0, 10.0, 1.0, 2.0, std::numeric_limits<double>::infinity(), g);
  static std::map<std::pair<int, double>, WaveField> seas;
  const std::vector<int> counts = {1, 4, 16, 64, 256};
  const double deep = std::numeric_limits<double>::infinity();
  benchmark::RegisterBenchmark("hull/closed/calm", closed_form, nullptr)->Unit(benchmark::kNanosecond);
  benchmark::RegisterBenchmark("hull/quadrature/calm", quadrature, nullptr)->Unit(benchmark::kNanosecond);
  benchmark::RegisterBenchmark("hull/closed/regular", closed_form, &regular)->Unit(benchmark::kNanosecond);
  benchmark::RegisterBenchmark("hull/quadrature/regular", quadrature, &regular)->Unit(benchmark::kNanosecond);
  for (const double depth : {deep, 30.0}) {
    for (const int n : counts) {
      const auto& field = seas.emplace(std::pair{n, depth}, sea(n, depth)).first->second;
      const std::string tag = fmt::format("{}/{}", std::isinf(depth) ? "deep" : "d30", n);
      benchmark::RegisterBenchmark(("hull/closed/sea/" + tag).c_str(), closed_form, &field)->Unit(benchmark::kNanosecond);
      if (n <= 16) {
        benchmark::RegisterBenchmark(("hull/quadrature/sea/" + tag).c_str(), quadrature, &field)->Unit(benchmark::kNanosecond);
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();
  const auto& ns = collector.nanoseconds;
  const auto at = [&](const std::string& name) {
    const auto it = ns.find(name);
    return it == ns.end() ? std::nan("") : it->second;
  };
  fmt::print("\nOne hull pressure integral, per call [ns]\n\n| wave | closed form | quadrature | ratio |\n|---|---:|---:|---:|\n");
  for (const std::string wave : {"calm", "regular", "sea/deep/1", "sea/deep/4", "sea/deep/16", "sea/d30/1", "sea/d30/4", "sea/d30/16"}) {
    const double c = at("hull/closed/" + wave), q = at("hull/quadrature/" + wave);
    fmt::print("| {} | {:.0f} | {:.0f} | {:.1f} |\n", wave, c, q, q / c);
  }
  for (const std::string depth : {"deep", "d30"}) {
    const double first = at(fmt::format("hull/closed/sea/{}/{}", depth, counts.front()));
    const double last = at(fmt::format("hull/closed/sea/{}/{}", depth, counts.back()));
    fmt::print("\nclosed form, {}: {:.0f} ns per component ({} → {} components: {:.0f} → {:.0f} ns)\n", depth,
               (last - first) / (counts.back() - counts.front()), counts.front(), counts.back(), first, last);
  }
  return 0;
}
