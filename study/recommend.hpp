// The candidate models of `ffrf recommend`, in order of expected solver work (study/expected_work.hpp),
// each pruned by the reasoning (recommend_reasoning.hpp) or verified against the converged reference
// at the model-choice rtol (study/verdict.hpp); the search stops at the first candidate whose worst
// normalized RMS error over the chosen outputs (multibody/error_metrics.hpp, the error of `ffrf
// compare` and `ffrf sweep`) is within the tolerance, then proves minimality by running the next
// cheaper candidate of the ladder even when the reasoning pruned it. The expected work is a
// prediction, the measured one scatters about it: the kept candidates whose expected work is within
// the scatter of the chosen one's (its integrator twins among them) are run too, and the recommendation
// is study::cheapest_passing of every candidate run — the rule and measure (solver work, RHS
// evaluations × state size) by which compare, sweep and operability name their cheapest model.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "multibody/crane_run.hpp"
#include "study/recommend_reasoning.hpp"
#include "study/reference.hpp"
#include "study/verdict.hpp"

namespace ffrf::study {

enum class CandidateStatus { pruned, not_run, passed, failed, solver_failure };
std::string_view to_string(CandidateStatus status);

struct Candidate {
  scene::BoomChoice choice;
  solve::Integrator integrator = solve::Integrator::cvode;
  int elastic_dof = 0;                  // predicted size of the elastic coordinates
  double expected_work = 0.0;           // the ladder's order: expected_solver_work (study/expected_work.hpp)
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
  double work() const { return solver_work(rhs_evaluations, state_size); }  // RHS evaluations × state size
  std::string label() const;  // "nodal N=1, cvode rtol 1e-04"
};

// The ladder of candidates for a scene, in order of predicted cost, each kept or pruned with the reason.
std::vector<Candidate> candidate_ladder(const scene::Scene& scene, const RecommendReasoning& reasoning,
                                        modal::ModeCache* modes = nullptr);

struct RecommendRequest {
  double tolerance = 0.01;                       // in (0, 1)
  std::vector<multibody::OutputChannel> outputs;  // judged; empty: judged_outputs(scene)
  double duration = 0.0;                         // of every run [s]; 0: simulation.duration of the scene
  ReferenceOptions reference;  // its first level's rtol is at most the candidates' (a one-level reference: a tenth)
};

struct Recommendation {
  RecommendReasoning reasoning;
  scene::Scene reference_scene;  // the scene with the stiffening the reference needs
  std::vector<multibody::OutputChannel> outputs;  // the judged outputs
  double duration = 0.0;                         // of every run [s]
  ConvergedReference reference;
  std::vector<Candidate> candidates;
  std::optional<std::size_t> chosen;      // index into candidates
  std::optional<std::size_t> next_cheaper;  // the candidate just below the first that passed, run and failed
  double work_speedup() const;            // reference steps × size over the chosen one's
  double wall_speedup() const;
};

// The verdict's view of the candidates that ran (label, error, work, wall time; all at the model-choice rtol).
std::vector<MeasuredModel> measured_candidates(const std::vector<Candidate>& candidates);
// study::cheapest_passing over the candidates (empty: none passed).
std::optional<std::size_t> cheapest_passing_candidate(const std::vector<Candidate>& candidates, double tolerance);
// Same kind, mesh, modes, static modes and stiffening (`scene_stiffening` stands for an unset one).
bool same_model(const Candidate& a, const Candidate& b, scene::Stiffening scene_stiffening);

// Throws scene::SceneError, solve::SolverFailure (the reference), modal::EigenSolverError,
// SettingError (a tolerance or duration out of range). `progress` is told what is being run.
Recommendation recommend(const scene::Scene& scene, const RecommendRequest& request,
                         const std::function<void(const std::string&)>& progress = {}, modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
