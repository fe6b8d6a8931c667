// The comparison of boom models on one scene (`ffrf compare`): the converged reference first, then
// the models of compared_models() (rigid, nodal N = 1 as in the paper, nodal N = 16, modal k = 1,
// 2, 4 with and without static modes), each through the one pipeline from the scene's initial
// state, each measured against the reference over the error window on the judged outputs
// (study/error_measure.hpp), with a verdict against a tolerance.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "coupling/error_metrics.hpp"
#include "study/error_measure.hpp"
#include "study/reference.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {

// The compared models, in report order. All are in the tables; the `plotted` ones (and the
// reference) are drawn on the overlaid time-history charts, which stay readable with five curves.
struct ComparedModel {
  scene::BoomChoice choice;
  bool plotted = false;
};
std::vector<ComparedModel> compared_models();

struct CompareRequest {
  coupling::IntegratorSettings settings;  // of every compared model (study::integrator_settings)
  ReferenceOptions reference;
  // Geometric stiffening of every model and the reference; empty: what the physics needs at
  // `tolerance` together with the scene's (physics_stiffening: the same as recommend's reference).
  std::optional<scene::Stiffening> stiffening;
  double tolerance = 0.01;
};

struct Comparison {
  coupling::IntegratorSettings settings;
  scene::Stiffening stiffening = scene::Stiffening::none;  // of every model and the reference
  bool stiffening_from_physics = false;                    // decided by physics_stiffening (not given)
  ConvergedReference reference;
  double window_start = 0.0;                    // errors are measured for t >= window_start
  std::vector<coupling::OutputChannel> judged;  // the outputs the worst error is taken over
  std::vector<ModelRun> runs;                   // in compared_models() order
  std::vector<bool> plotted;                    // per run
  std::vector<coupling::RunErrors> errors;      // per run, against the reference
  std::vector<WorstError> worst;                // per run, over `judged`
};

// Throws scene::SceneError, coupling::SolverFailure; `progress` is told what runs next
// ("reference", or a model's label) — the name of what failed when one of them throws.
Comparison compare(const scene::Scene& scene, const CompareRequest& request,
                   const std::function<void(const std::string&)>& progress = {}, modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
