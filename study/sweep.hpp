// The accuracy–speed sweep (`ffrf sweep`): the converged reference, then every configuration of a
// grid (study/sweep_grid.hpp), or one shard of it, in parallel. Each configuration is one run of
// the one pipeline (study/run_pipeline.hpp) measured against the reference over the error window;
// a solver failure is a result with status `failed` and the reason, never an exception. The
// reference and the workers share one mode cache (each mesh's eigenproblem is solved once) and one
// model cache (each distinct crane model — radiation model included — is built once, its static
// equilibrium solved once, and shared read-only, scene/crane_model_cache.hpp); each run
// owns only its equations' workspace and run state. ARPACK guards itself (modal/), so nothing here
// is serialized but the caches' own look-ups and the first build of each model.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "multibody/error_metrics.hpp"
#include "distributed/farm.hpp"
#include "scene/crane_model_cache.hpp"
#include "scene/scene.hpp"
#include "study/error_measure.hpp"
#include "study/reference.hpp"
#include "study/sweep_grid.hpp"
#include "study/verdict.hpp"

namespace ffrf::study {

enum class RunStatus { ok, failed, skipped };
std::string_view to_string(RunStatus status);

struct SweepResult {
  SweepConfig config;
  RunStatus status = RunStatus::ok;
  std::string reason;           // failed/skipped: why
  double step = 0.0;            // fixed step actually taken [s] (0: adaptive)
  double stable_step = 0.0;     // ARKODE rows: the explicit stability limit [s] (0: not computed)
  multibody::RunErrors errors;   // ok rows
  WorstError worst;             // ok rows: over the judged outputs
  solve::SolverStats stats;  // ok rows
  int state_size = 0;           // ok rows: 2 × minimal coordinates (work = RHS evaluations × state size)
};

struct SweepRequest {
  SweepGrid grid = SweepGrid::quick;
  distributed::Shard shard;  // the whole grid by default
  double duration = 0.0;                // simulated time of every run [s]
  ReferenceOptions reference;
  int jobs = 1;                         // worker threads
  // Geometric stiffening of every run and the reference; empty: physics_stiffening at `tolerance`
  // (as compare and recommend).
  std::optional<scene::Stiffening> stiffening;
  double tolerance = 0.01;              // of the verdict (and of the physics deciding the stiffening)
  long max_explicit_steps = 2'000'000;  // ARKODE runs needing more steps are skipped (with the reason)
  // A scene with [bem]: the grid crossed with the radiation models, the reference with
  // the Cummins convolution. Throws scene::SceneError when the scene has no [bem].
  bool radiation_axis = false;
  // A boom pinned at its heel: the modal models also with the chord frame's pinned-pinned mode set
  // (appended: the other configurations keep their ids).
  bool mode_set_axis = false;
};

// The duration of every run when none is given: quick_sweep_duration for the quick grid (a first look
// past the wave ramp), the scene's simulation.duration for the others.
inline constexpr double quick_sweep_duration = 40.0;  // [s]
double default_sweep_duration(const scene::Scene& scene, SweepGrid grid);
// Worker threads of a sweep: `jobs`, or one per core for 0 (the front ends' default).
int worker_threads(int jobs);
// The axes a scene adds to the grid: the radiation models of a [bem] hull (unless its radiation model
// is kept as given: `radiation_fixed`), the pinned-pinned mode set of a boom pinned at its heel.
void add_scene_axes(SweepRequest& request, const scene::Scene& scene, bool radiation_fixed);

struct SweepStudy {
  double tolerance = 0.01;  // of the verdict
  scene::Scene scene;       // the scene as every run models it (the stiffening decided)
  scene::Stiffening stiffening = scene::Stiffening::none;
  bool stiffening_from_physics = false;
  ConvergedReference reference;
  double window_start = 0.0;
  std::vector<multibody::OutputChannel> judged;
  std::vector<SweepResult> results;  // in grid order (the shard's configurations only)
  // How the runs got their models (this process), all from one scene::CraneModelCache: crane models
  // built for the reference's levels, then for the configurations (one per distinct model and
  // radiation model; a model a reference level built is not built again), and eigen solves (one per
  // distinct mesh of a modal boom).
  int reference_models_built = 0;
  int models_built = 0;
  int eigen_solves = 0;
};

// What a configuration runs against (shared, read-only, by the workers).
struct SweepSetup {
  const scene::Scene* scene = nullptr;
  const ConvergedReference* reference = nullptr;
  double window_start = 0.0;
  std::vector<multibody::OutputChannel> judged;
  double duration = 0.0;
  long max_explicit_steps = 2'000'000;
  // The shared models of *scene (its scene() equal to *scene; a configuration's radiation model is
  // its scene(radiation)); null: every run builds its own and solves its static equilibrium.
  scene::CraneModelCache* models = nullptr;
};

// One configuration (thread-safe).
SweepResult run_configuration(const SweepSetup& setup, const SweepConfig& config);

// The study's scene as every run models it (the stiffening decided; with the radiation axis the
// reference's convolution), tolerance and stiffening: no reference, no results. Throws SettingError,
// scene::SceneError (the radiation axis on a scene without [bem]).
SweepStudy sweep_scene(const scene::Scene& scene, const SweepRequest& request);
// The converged reference, on `models` (whose scene is study.scene), and what the runs are measured
// over; sets study.reference_models_built. Throws as converged_reference().
void measure_reference(SweepStudy& study, const SweepRequest& request, scene::CraneModelCache& models);
// sweep_scene then measure_reference on models of its own (everything but the results). Throws as sweep().
SweepStudy sweep_reference(const scene::Scene& scene, const SweepRequest& request, modal::ModeCache* modes);
// The shard's configurations, in grid order.
std::vector<SweepConfig> sweep_configurations(const SweepRequest& request);

// The reference, then the shard's configurations over request.jobs threads (in this process). `on_reference` is
// called once the reference is known; `progress` (serialized) after each configuration with the
// number done and the total. Throws scene::SceneError, solve::SolverFailure (the reference),
// SettingError.
SweepStudy sweep(const scene::Scene& scene, const SweepRequest& request,
                 const std::function<void(const ConvergedReference&)>& on_reference = {},
                 const std::function<void(const SweepResult&, std::size_t done, std::size_t total)>& progress = {});

// The sweep on the distributed engine (study/sweep_farm.cpp): the reference on every process, then the
// shard's configurations as farm tasks (threads: farm_options.threads; request.jobs is not used),
// journaled in farm_options.output_directory and resumed on a rerun. Every process calls it; on ranks
// > 0 farm.root is false and records is empty. records: record_of(result) of the shard's
// configurations in grid order (a work function that threw becomes a failed result with its message).
struct SweepOnEngine {
  SweepStudy study;                   // reference, window, judged outputs (results empty)
  std::vector<std::string> records;   // the shard's rows, grid order
  distributed::FarmResult farm;       // engine, counts, journal (outcomes dropped)
};
SweepOnEngine sweep_on_engine(distributed::Session& session, const scene::Scene& scene, const SweepRequest& request,
                              distributed::FarmOptions farm_options,
                              const std::function<std::string(const SweepResult&)>& record_of);

}  // namespace ffrf::study
