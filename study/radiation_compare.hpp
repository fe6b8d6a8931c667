// The three radiation models of a [bem] scene compared like the boom models (`ffrf compare`,
// `ffrf recommend`; docs/hydrodynamics.md §6): one boom model, the same integrator settings, the
// Cummins convolution as the reference; each model's worst normalized RMS error over the judged
// outputs (study/error_measure.hpp) against it, its cost, and the verdict at the tolerance
// (study/verdict.hpp): the cheapest radiation model within it.
#pragma once

#include <string>
#include <vector>

#include "scene/bem_hull_model.hpp"
#include "study/error_measure.hpp"
#include "study/run_pipeline.hpp"
#include "study/verdict.hpp"

namespace ffrf::study {

struct RadiationComparison {
  scene::BoomChoice choice;                  // the boom model every run uses
  std::vector<hydro::RadiationKind> kinds;   // constant, state-space (convolution is the reference)
  std::vector<std::string> labels;           // "constant A, B at T = 8 s", "state-space r = 14 (e_r 1.9 %)"
  std::vector<ModelRun> runs;                // per kind
  std::vector<WorstError> worst;             // per kind, against the reference
  ModelRun reference;                        // convolution
  std::string reference_label;
  double window_start = 0.0;
  Verdict verdict;
};

// A copy of the scene whose [bem] uses `kind` (throws scene::SceneError when it has no [bem]).
using scene::with_radiation;  // scene/bem_hull_model.hpp
// The label of the scene's radiation model ("convolution T_c = 34.9 s (698 samples)").
std::string radiation_label(const scene::Scene& scene);

// Throws scene::SceneError, solve::SolverFailure, SettingError (the tolerance).
RadiationComparison compare_radiation(const scene::Scene& scene, const scene::BoomChoice& choice,
                                      const multibody::RunSettings& settings, double tolerance);

// The text table of the comparison (error, wall time, steps, the verdict).
std::string radiation_comparison_text(const RadiationComparison& comparison);

}  // namespace ffrf::study
