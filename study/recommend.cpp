// The candidate ladder and the verification runs of `ffrf recommend` (see recommend.hpp).
#include "study/recommend.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "fem/mesh.hpp"
#include "study/error_measure.hpp"
#include "study/expected_work.hpp"
#include "study/run_pipeline.hpp"
#include "study/stability_theory.hpp"
#include "modal/static_modes.hpp"

namespace ffrf::study {
namespace {

constexpr double estimate_margin = 3.0;  // prune only what the estimates put 3× beyond τ
constexpr int max_plain_modes = 6;       // modal k without static modes: k = 1..6
constexpr int max_static_modes = 4;      // modal k+static: k = 1..4
constexpr std::array<int, 4> nodal_meshes{1, 2, 4, 8};
// The measured solver work of BDF models of one scene scatters about the expected (the state size
// times common steps) by up to ±20 % (reference scene, rtol 1e-4: 2 878–3 550 steps); candidates
// expected within that band of the first that passes are run too, so the cheapest is measured.
constexpr double work_scatter = 1.25;

int kind_rank(scene::BoomKind kind) { return kind == scene::BoomKind::rigid ? 0 : kind == scene::BoomKind::modal ? 1 : 2; }

double explicit_limit(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* modes) {
  const double boom = damped_boom_step_limit(boom_angular_frequencies(scene, choice, modes),
                                             scene::boom_stiffness_damping(scene));
  return std::min(boom, undamped_boom_step_limit(wire_cargo_frequency(scene)));
}

// Adds the model in each stiffening variant, and its explicit-RK twin where the stiffness does not bind.
void add_model(const scene::Scene& scene, const RecommendReasoning& r, const WorkForecast& forecast, scene::BoomChoice choice,
               int dof, double estimate, std::string reason, modal::ModeCache* modes, std::vector<Candidate>& ladder) {
  std::vector<std::optional<scene::Stiffening>> variants{std::nullopt};
  if (choice.kind != scene::BoomKind::rigid && r.reference_stiffening != scene::Stiffening::none) {
    variants = {scene::Stiffening::none, r.reference_stiffening};
  }
  for (const auto& variant : variants) {
    choice.stiffening = variant;
    Candidate c;
    c.choice = choice;
    c.elastic_dof = dof;
    c.expected_work = expected_solver_work(forecast, dof, solve::Integrator::cvode, 0.0);
    c.estimated_error = estimate;
    c.prune_reason = reason;
    if (c.prune_reason.empty() && variant == scene::Stiffening::none && r.required_stiffening != scene::Stiffening::none) {
      c.prune_reason = fmt::format("needs {} stiffening (buckling / spin figures above)", scene::to_string(r.required_stiffening));
    }
    const double limit = explicit_limit(scene, choice, modes);
    if (limit >= scene.simulation.output_interval) {
      Candidate e = c;
      e.integrator = solve::Integrator::arkode;
      e.explicit_step_limit = limit;
      e.expected_work = expected_solver_work(forecast, dof, e.integrator, limit);
      ladder.push_back(e);
    }
    ladder.push_back(c);
  }
}

}  // namespace

std::string_view to_string(CandidateStatus status) {
  switch (status) {
    case CandidateStatus::pruned: return "pruned";
    case CandidateStatus::not_run: return "not run";
    case CandidateStatus::passed: return "passed";
    case CandidateStatus::failed: return "failed";
    case CandidateStatus::solver_failure: return "solver failure";
  }
  return "?";
}

std::string Candidate::label() const {
  return fmt::format("{}, {}", choice.label(), solve::to_string(integrator));
}

std::vector<Candidate> candidate_ladder(const scene::Scene& scene, const RecommendReasoning& r, modal::ModeCache* modes) {
  std::vector<Candidate> ladder;
  scene::BoomChoice rigid;
  rigid.kind = scene::BoomKind::rigid;
  const WorkForecast forecast =
      work_forecast(scene, r, scene.simulation.duration, scene::build_crane_equations(scene, rigid, modes)->minimal_size());
  const double tau = r.tolerance;
  const auto too_large = [&](double estimate) { return std::isfinite(estimate) && estimate > estimate_margin * tau; };
  const auto estimate_reason = [&](double estimate) {
    return too_large(estimate) ? fmt::format("estimated error {:.2g} > {:g}·τ", estimate, estimate_margin) : std::string();
  };
  scene::BoomChoice choice;
  choice.elements = scene.boom.mesh.element_count;
  choice.kind = scene::BoomKind::rigid;
  add_model(scene, r, forecast, choice, 0, r.rigid_error, estimate_reason(r.rigid_error), modes, ladder);

  const int dof = fem::clamped_free_dof_count(scene.boom.mesh.element_count);
  const int static_count = static_cast<int>(modal::tip_and_body_unit_loads(scene.boom.mesh).size());
  choice.kind = scene::BoomKind::modal;
  for (int k = 1; k <= std::min(max_plain_modes, dof - 1); ++k) {
    choice.modes = k;
    choice.static_modes = false;
    const double estimate = r.rigid_error * missing_flexibility(scene, r.modes, k);
    std::string reason = k < r.dynamic_modes ? fmt::format("drops mode {}, which the excitation drives dynamically", r.dynamic_modes)
                                             : estimate_reason(estimate);
    add_model(scene, r, forecast, choice, k, estimate, reason, modes, ladder);
  }
  // The static-mode models of a mode set with `statics` static modes.
  const auto add_static_mode_models = [&](fem::Boundary set, int statics) {
    choice.mode_set = set;
    for (int k = 1; k <= std::min(max_static_modes, dof - 1); ++k) {
      choice.modes = k;
      choice.static_modes = true;
      const double next = k < static_cast<int>(r.modes.size())
                              ? quasi_static_error(r.excitation_top, r.modes[static_cast<std::size_t>(k)].angular_frequency)
                              : 0.0;
      const double estimate = r.rigid_error * missing_flexibility(scene, r.modes, k) * next;
      std::string reason = k < r.dynamic_modes ? fmt::format("drops mode {}, which the excitation drives dynamically", r.dynamic_modes)
                                               : estimate_reason(estimate);
      add_model(scene, r, forecast, choice, k + statics, estimate, reason, modes, ladder);
    }
    choice.mode_set = fem::Boundary::clamped_free;
  };
  add_static_mode_models(fem::Boundary::clamped_free, static_count);
  // The free-free set in the same frame, with the same static modes and estimates (their span holds
  // the same quasi-static response; only the verification run tells the sets apart).
  add_static_mode_models(fem::Boundary::free_free, static_count);
  // A pinned boom: the chord frame's set too (docs/validation.md, "The pinned boom: which mode set?"),
  // with one static mode fewer (the frame carries the tip's transverse load), the same estimates.
  if (scene.boom.mount && scene.boom.mount->pinned) add_static_mode_models(fem::Boundary::pinned_pinned, static_count - 1);
  choice.kind = scene::BoomKind::nodal;
  choice.static_modes = false;
  for (const int n : nodal_meshes) {
    choice.elements = n;
    std::string reason = 3 * n <= r.dynamic_modes
                             ? fmt::format("{} DOFs cannot carry the {} dynamic modes", 3 * n, r.dynamic_modes)
                             : std::string();
    add_model(scene, r, forecast, choice, 3 * n, std::numeric_limits<double>::quiet_NaN(), reason, modes, ladder);
  }
  // Expected work first; at equal work the smaller a-priori error (a static-mode model before the
  // vibration modes or mesh of its size; no estimate last), then rigid < modal < nodal, unstiffened first.
  std::stable_sort(ladder.begin(), ladder.end(), [](const Candidate& a, const Candidate& b) {
    const auto key = [](const Candidate& c) {
      const double estimate = std::isfinite(c.estimated_error) ? c.estimated_error : std::numeric_limits<double>::infinity();
      return std::tuple(c.expected_work, estimate, kind_rank(c.choice.kind),
                        c.choice.stiffening.value_or(scene::Stiffening::none) != scene::Stiffening::none);
    };
    return key(a) < key(b);
  });
  for (Candidate& c : ladder) {
    if (!c.prune_reason.empty()) c.status = CandidateStatus::pruned;
  }
  return ladder;
}

namespace {

void verify(const scene::Scene& scene, const Recommendation& rec, modal::ModeCache& modes, Candidate& c) {
  DynamicsRequest request;
  request.integrator = c.integrator;
  request.relative_tolerance = request.absolute_tolerance = rec.reasoning.relative_tolerance;
  request.duration = rec.duration;
  const multibody::RunSettings settings = integrator_settings(scene, request);
  try {
    const ModelRun run = run_model(scene, c.choice, settings, &modes);
    c.state_size = run.state_size;
    c.steps = run.result.stats.steps;
    c.rhs_evaluations = run.result.stats.function_evaluations;
    c.wall_seconds = run.result.stats.wall_seconds;
    const WorstError worst =
        worst_error(multibody::compare_runs(run.result, rec.reference.run.result, rec.reference.window_start), rec.outputs);
    c.error = worst.error;
    c.worst_output = std::string(multibody::channel_name(worst.channel));
    c.status = std::isfinite(c.error) && c.error <= rec.reasoning.tolerance ? CandidateStatus::passed : CandidateStatus::failed;
  } catch (const solve::SolverFailure& failure) {
    c.status = CandidateStatus::solver_failure;
    c.failure = fmt::format("{} ({}) at t = {:.3g} s: {}", solve::to_string(failure.kind()), failure.solver(),
                            failure.time(), failure.cause());
  }
}

}  // namespace

bool same_model(const Candidate& a, const Candidate& b, scene::Stiffening scene_stiffening) {
  return a.choice.kind == b.choice.kind && a.choice.elements == b.choice.elements && a.choice.modes == b.choice.modes &&
         a.choice.static_modes == b.choice.static_modes && a.choice.mode_set == b.choice.mode_set &&
         a.choice.stiffening.value_or(scene_stiffening) == b.choice.stiffening.value_or(scene_stiffening);
}

std::vector<MeasuredModel> measured_candidates(const std::vector<Candidate>& candidates) {
  std::vector<MeasuredModel> measured;
  for (const Candidate& c : candidates) {
    MeasuredModel m;
    m.label = c.label();
    m.ran = c.status == CandidateStatus::passed || c.status == CandidateStatus::failed;
    m.reason = c.failure;
    m.error = c.error;
    m.worst_output = c.worst_output;
    m.wall_seconds = c.wall_seconds;
    m.work = c.work();
    measured.push_back(std::move(m));
  }
  return measured;
}

std::optional<std::size_t> cheapest_passing_candidate(const std::vector<Candidate>& candidates, double tolerance) {
  // A candidate recommend judged failed (its error, or a check beyond it such as the minimality of
  // the named model) never passes here, whatever its error alone says.
  std::vector<MeasuredModel> measured = measured_candidates(candidates);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].status != CandidateStatus::passed) measured[i].ran = false;
  }
  return cheapest_passing(measured, tolerance);
}

double Recommendation::work_speedup() const {
  if (!chosen) return std::numeric_limits<double>::quiet_NaN();
  return reference.run.work() / candidates[*chosen].work();
}

double Recommendation::wall_speedup() const {
  if (!chosen) return std::numeric_limits<double>::quiet_NaN();
  return reference.run.result.stats.wall_seconds / candidates[*chosen].wall_seconds;
}

Recommendation recommend(const scene::Scene& scene, const RecommendRequest& request,
                         const std::function<void(const std::string&)>& progress, modal::ModeCache* modes) {
  const auto tell = [&](const std::string& what) {
    if (progress) progress(what);
  };
  if (!(request.tolerance > 0.0 && request.tolerance < 1.0)) {
    throw SettingError(Setting::tolerance, fmt::format("{}", request.tolerance), "not a tolerance (valid range (0, 1))");
  }
  modal::ModeCache own;
  modal::ModeCache& cache = modes != nullptr ? *modes : own;
  Recommendation rec;
  rec.outputs = request.outputs.empty() ? judged_outputs(scene) : request.outputs;
  rec.duration = request.duration > 0.0 ? request.duration : scene.simulation.duration;
  tell("reasoning (boom modes, excitation, loads) ...");
  rec.reasoning = reason_about(scene, request.tolerance, rec.outputs);
  rec.reference_scene = scene;
  rec.reference_scene.boom.stiffening = rec.reasoning.reference_stiffening;
  const scene::Scene& s = rec.reference_scene;
  tell("converged reference (nodal, refined level by level) ...");
  ReferenceOptions options = request.reference;
  // The reference's levels tighten rtol tenfold each: starting at the candidates' rtol its last level
  // is at least ten times tighter than they are (and the same reference as compare's and sweep's).
  options.start_relative_tolerance = std::min(options.start_relative_tolerance,
                                              rec.reasoning.relative_tolerance / (options.max_levels > 1 ? 1.0 : 10.0));
  rec.reference = converged_reference(s, options, rec.duration, &cache);
  rec.candidates = candidate_ladder(s, rec.reasoning, &cache);
  for (std::size_t i = 0; i < rec.candidates.size(); ++i) {
    Candidate& c = rec.candidates[i];
    if (c.status == CandidateStatus::pruned) continue;
    tell(c.label() + " ...");
    verify(s, rec, cache, c);
    if (c.status == CandidateStatus::passed) {
      rec.chosen = i;
      break;
    }
  }
  // Minimality: the next cheaper *model* must fail its run (an integrator twin of the chosen model,
  // e.g. its explicit variant, proves nothing about the model); run it even when pruned, and should it
  // pass (the reasoning was too cautious), move down and check again.
  const auto twins = [&](const Candidate& a, const Candidate& b) { return same_model(a, b, s.boom.stiffening); };
  while (rec.chosen && *rec.chosen > 0) {
    std::size_t j = *rec.chosen - 1;
    while (j > 0 && twins(rec.candidates[j], rec.candidates[*rec.chosen])) --j;
    if (twins(rec.candidates[j], rec.candidates[*rec.chosen])) break;  // nothing cheaper
    Candidate& c = rec.candidates[j];
    if (c.status == CandidateStatus::pruned) {
      tell(c.label() + " (minimality check) ...");
      c.minimality_check = true;
      verify(s, rec, cache, c);
    }
    if (c.status != CandidateStatus::passed) {
      rec.next_cheaper = j;
      break;
    }
    rec.chosen = j;
  }
  // The kept candidates expected to cost about as much as the one that passed (within the scatter of
  // measured about expected work): run them too, and recommend the cheapest that passes by measured
  // solver work (study::cheapest_passing, the rule of compare and sweep).
  if (rec.chosen) {
    const double band = work_scatter * rec.candidates[*rec.chosen].expected_work;
    for (Candidate& c : rec.candidates) {
      if (c.status != CandidateStatus::not_run || c.expected_work > band) continue;
      tell(c.label() + " (about as cheap) ...");
      verify(s, rec, cache, c);
    }
    rec.chosen = cheapest_passing_candidate(rec.candidates, rec.reasoning.tolerance);
  }
  return rec;
}

}  // namespace ffrf::study
