// A converged reference for a scene: the nodal model refined until its outputs stop
// changing. Level i uses N = N0·2^i elements and rtol = atol = rtol0·10^(−i) (CVODE, minimal
// coordinates), each run through the one pipeline (study/run_pipeline.hpp: the scene's initial
// state, cargo lift included); the change between two levels is the worst normalized RMS
// difference over the output channels (multibody/error_metrics.hpp) in the error window
// (study/error_measure.hpp). The finest level is the reference once the change falls below the
// bound; every error ffrf reports is measured against it.
//
// One set of defaults for every command, so all judge against the same reference: N0 = 8, rtol0 = 1e-6, bound 1e-3, at most 3
// levels. The models compared by default run at rtol 1e-6, so the last level (N = 32, rtol 1e-8)
// is two decades tighter than they are; the bound is a tenth of the default 1 % verdict tolerance of
// compare and recommend, so a verdict is never decided by the reference's own error; three levels
// keep the reference within a few times the cost of the models (a fourth, N = 64 at rtol 1e-9,
// costs ~8× the third and is not needed on the shipped scenes: docs/validation.md).
#pragma once

#include <vector>

#include "modal/mode_cache.hpp"
#include "scene/crane_model_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {

struct ReferenceOptions {
  int start_elements = 8;
  double start_relative_tolerance = 1e-6;
  double bound = 1e-3;  // worst normalized RMS change between successive levels
  int max_levels = 3;
};
// Throws SettingError naming the first option out of range.
void validate(const ReferenceOptions& options);

struct ReferenceLevel {
  int elements = 0;
  double relative_tolerance = 0.0;
  double change = 0.0;  // vs the previous level (0 for the first)
  solve::SolverStats stats;
};

struct ConvergedReference {
  scene::BoomChoice choice;
  multibody::RunSettings settings;
  ModelRun run;               // the finest level's run, statistics included
  std::vector<ReferenceLevel> levels;
  double bound = 0.0;
  bool converged = false;
  double window_start = 0.0;  // errors (and the changes) are measured for t >= window_start [s]
};

// The reference for runs of `duration` seconds. A run that ends within the wave ramp has no window
// to check convergence on: then only the first level is run (reported as not converged). Throws
// scene::SceneError, solve::SolverFailure.
ConvergedReference converged_reference(const scene::Scene& scene, const ReferenceOptions& options, double duration,
                                       modal::ModeCache* modes = nullptr);
// The same on the cache's scene with the cache's models (scene/crane_model_cache.hpp): a study that
// also runs some of the levels' models (sweep, compare) builds each of them once.
ConvergedReference converged_reference(scene::CraneModelCache& models, const ReferenceOptions& options, double duration);

}  // namespace ffrf::study
