// The comparison of boom models on one scene (`ffrf compare`): the converged reference first, then
// the models of compared_models() (rigid, nodal N = 1 as in the paper, nodal N = 16, modal k = 1,
// 2, 4 with and without static modes, in the clamped-free and free-free mode sets and, for a pinned
// boom, the pinned-pinned set too), each through the one pipeline from the scene's initial
// state, each measured against the reference over the error window on the judged outputs
// (study/error_measure.hpp): the total error per output split into its static and dynamic parts
// (study/error_split.hpp), and the verdict against a tolerance (study/verdict.hpp). The reference's
// levels and the compared models come from one scene::CraneModelCache (nodal N = 16 is built once).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "multibody/error_metrics.hpp"
#include "study/error_measure.hpp"
#include "study/error_split.hpp"
#include "study/reference.hpp"
#include "study/run_pipeline.hpp"
#include "study/stress_recovery_errors.hpp"
#include "study/verdict.hpp"

namespace ffrf::study {

// The compared models, in report order. All are in the tables; the `plotted` ones (and the
// reference) are drawn on the overlaid time-history charts, which stay readable with five curves.
struct ComparedModel {
  scene::BoomChoice choice;
  bool plotted = false;
};
std::vector<ComparedModel> compared_models(const scene::Scene& scene);

struct CompareRequest {
  multibody::RunSettings settings;  // of every compared model (study::integrator_settings)
  ReferenceOptions reference;
  // Geometric stiffening of every model and the reference; empty: what the physics needs at
  // `tolerance` together with the scene's (physics_stiffening: the same as recommend's reference).
  std::optional<scene::Stiffening> stiffening;
  double tolerance = 0.01;  // of the verdict, in (0, 1)
};

struct Comparison {
  multibody::RunSettings settings;
  scene::Stiffening stiffening = scene::Stiffening::none;  // of every model and the reference
  bool stiffening_from_physics = false;                    // decided by physics_stiffening (not given)
  ConvergedReference reference;
  double window_start = 0.0;                    // errors are measured for t >= window_start
  std::vector<multibody::OutputChannel> judged;  // the outputs the worst error is taken over
  std::vector<ModelRun> runs;                   // in compared_models() order
  std::vector<bool> plotted;                    // per run
  std::vector<multibody::RunErrors> errors;      // per run, against the reference (total errors)
  std::vector<SplitErrors> split;               // per run: the static and dynamic parts per channel
  std::vector<WorstError> worst;                // per run, over `judged`
  // Per run, its peak boom stress by mode displacement and by mode acceleration against the reference's.
  std::vector<StressRecoveryErrors> stress;
  // Per run, an irregular sea: its statistics and spectra against the reference's (study/irregular_statistics.hpp).
  std::vector<std::optional<IrregularErrors>> irregular;
  Verdict verdict;                              // per run, against the request's tolerance
};

// The verdict's view of the compared runs (label, worst error, wall time, work).
std::vector<MeasuredModel> measured_models(const Comparison& comparison);

// Throws scene::SceneError, solve::SolverFailure, SettingError (the tolerance); `progress` is told what runs next
// ("reference", or a model's label) — the name of what failed when one of them throws.
Comparison compare(const scene::Scene& scene, const CompareRequest& request,
                   const std::function<void(const std::string&)>& progress = {}, modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
