// The candidate models of `ffrf recommend` (docs/recommend.md), cheapest first, each pruned by the reasoning
// (recommend_reasoning.hpp) or verified against the converged reference; the search stops at the
// first candidate whose worst normalized RMS error over the chosen outputs (coupling/error_metrics.hpp,
// the error of `ffrf compare` and `ffrf sweep`) is within the tolerance, then proves minimality by
// running the next cheaper candidate of the ladder even when the reasoning pruned it.
// Cost is solver work: steps × state size (and the RHS evaluations), never seconds. Integrator twins
// of one model (explicit RK and BDF) do the same work per right-hand-side evaluation, but an explicit
// step costs several evaluations and a stiff wire can make it take many more steps: when a model
// passes, every twin of it that the reasoning kept is run too, and the one with the fewest RHS
// evaluations among those that pass is recommended (cheapest_passing_twin).
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "coupling/simulation.hpp"
#include "study/recommend_reasoning.hpp"
#include "study/reference.hpp"

namespace ffrf::study {

enum class CandidateStatus { pruned, not_run, passed, failed, solver_failure };
std::string_view to_string(CandidateStatus status);

struct Candidate {
  scene::BoomChoice choice;
  coupling::Integrator integrator = coupling::Integrator::cvode;
  int elastic_dof = 0;                  // predicted size of the elastic coordinates (the ladder's order)
  double estimated_error = std::numeric_limits<double>::quiet_NaN();  // a priori (NaN: none)
  double explicit_step_limit = 0.0;     // arkode candidates: β_I/ω_max of the boom and wire [s]
  std::string prune_reason;             // empty: kept
  bool minimality_check = false;        // run only to prove the chosen one minimal
  CandidateStatus status = CandidateStatus::not_run;
  std::string failure;                  // solver_failure: the named failure
  double error = std::numeric_limits<double>::quiet_NaN();  // worst normalized RMS over the outputs
  std::string worst_output;
  long steps = 0, rhs_evaluations = 0;
  int state_size = 0;
  double wall_seconds = 0.0;
  double work() const { return static_cast<double>(steps) * state_size; }
  std::string label() const;  // "nodal N=1, cvode rtol 1e-04"
};

// The ladder of candidates for a scene, in order of predicted cost, each kept or pruned with the reason.
std::vector<Candidate> candidate_ladder(const scene::Scene& scene, const RecommendReasoning& reasoning,
                                        modal::ModeCache* modes = nullptr);

struct RecommendRequest {
  double tolerance = 0.01;                       // in (0, 1)
  std::vector<coupling::OutputChannel> outputs;  // judged; empty: judged_outputs(scene)
  double duration = 0.0;                         // of every run [s]; 0: simulation.duration of the scene
  ReferenceOptions reference;  // its first level's rtol is tightened to a tenth of the candidates'
};

struct Recommendation {
  RecommendReasoning reasoning;
  scene::Scene reference_scene;  // the scene with the stiffening the reference needs
  std::vector<coupling::OutputChannel> outputs;  // the judged outputs
  double duration = 0.0;                         // of every run [s]
  ConvergedReference reference;
  std::vector<Candidate> candidates;
  std::optional<std::size_t> chosen;      // index into candidates
  std::optional<std::size_t> next_cheaper;  // the candidate just below the chosen one, run and failed
  double work_speedup() const;            // reference steps × size over the chosen one's
  double wall_speedup() const;
};

// Among the candidates that are the same model as candidates[chosen] (kind, mesh, modes, static
// modes, stiffening) and passed, the index of the one with the fewest RHS evaluations (ties: the
// earlier one); `scene_stiffening` stands for an unset stiffening.
std::size_t cheapest_passing_twin(const std::vector<Candidate>& candidates, std::size_t chosen,
                                  scene::Stiffening scene_stiffening);
bool same_model(const Candidate& a, const Candidate& b, scene::Stiffening scene_stiffening);

// Throws scene::SceneError, coupling::SolverFailure (the reference), modal::EigenSolverError,
// SettingError (a tolerance or duration out of range). `progress` is told what is being run.
Recommendation recommend(const scene::Scene& scene, const RecommendRequest& request,
                         const std::function<void(const std::string&)>& progress = {}, modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
