// What sharing the crane model saves a sweep, per configuration: building the model of
// a boom choice (scene::build_crane_model with the modes already cached — what every sweep
// configuration paid before models were shared) against making equations from a shared model (what it pays now),
// beside the static equilibrium every configuration still solves. Reference scene, static
// stiffening (as the sweep models it), the medium grid's largest models. docs/performance.md.
#include <benchmark/benchmark.h>

#include "multibody/crane_statics.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"

namespace {

using namespace ffrf;

scene::Scene bench_scene() {
  scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  scene.boom.stiffening = scene::Stiffening::static_load;
  return scene;
}

scene::BoomChoice choice_of(std::int64_t index) {
  switch (index) {
    case 0: return {scene::BoomKind::rigid, 1};
    case 1: return {scene::BoomKind::nodal, 16};
    case 2: return {scene::BoomKind::nodal, 32};
    default: return {scene::BoomKind::modal, 16, 12, true};
  }
}

void BM_BuildModel(benchmark::State& state) {
  const scene::Scene scene = bench_scene();
  const scene::BoomChoice choice = choice_of(state.range(0));
  modal::ModeCache modes;
  (void)scene::build_crane_model(scene, choice, &modes);  // the eigen solve, outside the timing
  for (auto _ : state) benchmark::DoNotOptimize(scene::build_crane_model(scene, choice, &modes));
  state.SetLabel(choice.label());
}

void BM_EquationsFromSharedModel(benchmark::State& state) {
  const scene::Scene scene = bench_scene();
  const scene::BoomChoice choice = choice_of(state.range(0));
  const auto model = scene::build_crane_model(scene, choice);
  for (auto _ : state) benchmark::DoNotOptimize(model->equations());
  state.SetLabel(choice.label());
}

void BM_StaticEquilibrium(benchmark::State& state) {
  const scene::Scene scene = bench_scene();
  const scene::BoomChoice choice = choice_of(state.range(0));
  auto equations = scene::build_crane_equations(scene, choice);
  for (auto _ : state) benchmark::DoNotOptimize(multibody::solve_static_equilibrium(*equations, equations->initial_guess()));
  state.SetLabel(choice.label());
}

BENCHMARK(BM_BuildModel)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EquationsFromSharedModel)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticEquilibrium)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
