// The one run pipeline and the integrator settings of a scene (see run_pipeline.hpp).
#include "study/run_pipeline.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "sea/incident_wave_record.hpp"
#include "multibody/planar.hpp"
#include "fem/analytic_beam.hpp"
#include "scene/irregular_sea.hpp"
#include "scene/scene_checks.hpp"
#include "study/work_limits.hpp"

namespace ffrf::study {

std::string_view to_string(Setting setting) {
  switch (setting) {
    case Setting::relative_tolerance: return "relative tolerance";
    case Setting::absolute_tolerance: return "absolute tolerance";
    case Setting::duration: return "duration";
    case Setting::fixed_step: return "fixed step";
    case Setting::max_order: return "largest BDF order";
    case Setting::reference_elements: return "reference elements";
    case Setting::reference_tolerance: return "reference tolerance";
    case Setting::reference_bound: return "reference convergence bound";
    case Setting::reference_levels: return "reference levels";
    case Setting::tolerance: return "error tolerance";
    case Setting::jobs: return "worker threads";
    case Setting::elements: return "boom elements";
    case Setting::boom_model: return "boom model";
    case Setting::modes: return "mode count";
    case Setting::stiffening: return "geometric stiffening";
    case Setting::mode_set: return "mode set";
    case Setting::stress_recovery: return "stress recovery";
    case Setting::integrator: return "integrator";
    case Setting::formulation: return "constraint formulation";
    case Setting::solver: return "solver";
    case Setting::step_limit: return "step limit";
    case Setting::wall_clock_limit: return "wall-clock limit";
    case Setting::step_floor: return "step-size floor";
    case Setting::wave_periods: return "wave periods";
    case Setting::wave_frequencies: return "wave frequencies";
    case Setting::outputs: return "outputs";
    case Setting::eigen_solver: return "eigen solver";
    case Setting::boundary: return "boundary condition";
    case Setting::grid: return "sweep grid";
    case Setting::headings: return "wave headings";
  }
  return "?";
}

SettingError::SettingError(Setting setting, std::string value, std::string problem)
    : std::invalid_argument(fmt::format("{} {}: {}", to_string(setting), value, problem)),
      setting_(setting),
      value_(std::move(value)),
      problem_(std::move(problem)) {}

multibody::MonitorLimits monitor_limits(const scene::Scene& scene) {
  multibody::MonitorLimits limits;
  const fem::BeamMesh& mesh = scene.boom.mesh;
  limits.boom_length = mesh.length;
  limits.deflection_limit = scene.simulation.deflection_limit;
  limits.constraint_drift_limit = scene.simulation.constraint_drift_limit;
  // The clamped root's Euler load π²EI/(4L²); a pinned heel's with the luffing wires holding the tip: π²EI/L².
  const bool pinned = scene.boom.mount && scene.boom.mount->pinned;
  limits.buckling_load = *fem::euler_buckling_load(mesh, pinned ? fem::Boundary::pinned_pinned : fem::Boundary::clamped_free);
  limits.wire_unstretched_length = scene.wire ? scene.wire->unstretched_length : 0.0;
  if (scene.is_crane()) {  // a floating hull: capsize, deck and cargo-in-water watch
    const scene::Hull& hull = *scene.hull;
    limits.water.floating = true;
    limits.water.hull_stern_x = hull.g1_aft_of_mid_length - 0.5 * hull.length;
    limits.water.hull_bow_x = hull.g1_aft_of_mid_length + 0.5 * hull.length;
    limits.water.hull_deck_y = hull.depth - hull.g1_above_keel;
    if (scene.cargo) {
      limits.water.cargo_half_length = 0.5 * scene.cargo->length;
      limits.water.cargo_half_height = 0.5 * scene.cargo->height;
    }
    limits.water.wave_amplitude = scene::wave_amplitude_bound(scene);
  }
  return limits;
}

solve::Integrator integrator_choice(const std::string& integrator, const std::string& formulation,
                                    const std::string& solver) {
  if (!integrator.empty() && (!formulation.empty() || !solver.empty())) {
    throw SettingError(Setting::integrator, integrator,
                       "names a formulation and a solver: give either the integrator or the formulation and the solver");
  }
  if (formulation.empty() && solver.empty()) {
    const std::string name = integrator.empty() ? "cvode" : integrator;
    const auto kind = solve::parse_integrator(name);
    if (!kind) throw SettingError(Setting::integrator, name, "unknown integrator; choose one of " + solve::integrator_choices());
    return *kind;
  }
  solve::Integrator choice = solve::Integrator::cvode;
  if (!formulation.empty()) {
    const auto parsed = solve::parse_formulation(formulation);
    if (!parsed) throw SettingError(Setting::formulation, formulation, "unknown formulation; choose one of " + solve::formulation_choices());
    choice.formulation = *parsed;
  }
  if (!solver.empty()) {
    const auto parsed = solve::parse_solver(solver);
    if (!parsed) throw SettingError(Setting::solver, solver, "unknown solver; choose one of " + solve::solver_choices());
    choice.solver = *parsed;
  }
  if (!solve::is_valid(choice)) {
    throw SettingError(Setting::solver, std::string(solve::to_string(choice.solver)),
                       fmt::format("not an implemented integrator with the formulation {}; valid pairs: {}",
                                   solve::to_string(choice.formulation), solve::valid_integrators()));
  }
  return choice;
}

void validate(const solve::WorkLimits& work) {
  if (work.max_steps < 1 || work.max_steps > max_step_limit) {
    throw SettingError(Setting::step_limit, fmt::format("{}", work.max_steps),
                       fmt::format("not a step limit (valid range [1, {}])", max_step_limit));
  }
  if (!(work.max_wall_seconds > 0.0 && (work.max_wall_seconds <= max_wall_clock || std::isinf(work.max_wall_seconds)))) {
    throw SettingError(Setting::wall_clock_limit, fmt::format("{}", work.max_wall_seconds),
                       fmt::format("not a wall-clock limit (valid range (0, {:g}] s, or none)", max_wall_clock));
  }
  if (!(work.min_step >= 0.0 && work.min_step <= max_step_floor)) {
    throw SettingError(Setting::step_floor, fmt::format("{}", work.min_step),
                       fmt::format("not a step-size floor (valid range [0, {:g}] s; 0: none)", max_step_floor));
  }
}

multibody::RunSettings integrator_settings(const scene::Scene& scene, const DynamicsRequest& request) {
  validate(request.work);
  for (const auto& [setting, value] : {std::pair{Setting::relative_tolerance, request.relative_tolerance},
                                       std::pair{Setting::absolute_tolerance, request.absolute_tolerance}}) {
    if (!(value >= min_tolerance && value <= max_tolerance)) {
      throw SettingError(setting, fmt::format("{}", value),
                         fmt::format("not a valid tolerance (valid range [{:g}, {:g}])", min_tolerance, max_tolerance));
    }
  }
  multibody::RunSettings settings;
  settings.kind = request.integrator;
  settings.relative_tolerance = request.relative_tolerance;
  settings.absolute_tolerance = request.absolute_tolerance;
  settings.output_interval = scene.simulation.output_interval;
  settings.duration = request.duration.value_or(scene.simulation.duration);
  if (!(settings.duration >= settings.output_interval) || !std::isfinite(settings.duration)) {
    throw SettingError(Setting::duration, fmt::format("{}", settings.duration),
                       fmt::format("shorter than one output interval of the scene ({} s) (valid range [{}, inf) s)",
                                   settings.output_interval, settings.output_interval));
  }
  if (settings.duration / settings.output_interval > scene::max_output_samples) {
    throw SettingError(Setting::duration, fmt::format("{}", settings.duration),
                       fmt::format("{:.4g} output samples at the scene's output interval {} s, more than the limit of "
                                   "{:g} (valid range [{}, {:g}] s)",
                                   settings.duration / settings.output_interval, settings.output_interval,
                                   scene::max_output_samples, settings.output_interval,
                                   scene::max_output_samples * settings.output_interval));
  }
  if (!(request.fixed_step >= 0.0 && request.fixed_step <= settings.output_interval)) {
    throw SettingError(Setting::fixed_step, fmt::format("{}", request.fixed_step),
                       fmt::format("not a valid fixed step (valid range [0, {}] s, the output interval)",
                                   settings.output_interval));
  }
  if (settings.kind == solve::Integrator::generalized_alpha && request.fixed_step == 0.0) {
    throw SettingError(Setting::fixed_step, "0",
                       fmt::format("generalized-alpha is a fixed-step method: give a fixed step in (0, {}] s, e.g. 0.01",
                                   settings.output_interval));
  }
  if (request.fixed_step > 0.0 && settings.duration / request.fixed_step > max_fixed_steps) {
    throw SettingError(Setting::fixed_step, fmt::format("{}", request.fixed_step),
                       fmt::format("{:.3g} steps for {} s, more than the limit of {:g} (valid range [{:.3g}, {}] s)",
                                   settings.duration / request.fixed_step, settings.duration, max_fixed_steps,
                                   settings.duration / max_fixed_steps, settings.output_interval));
  }
  settings.fixed_step = request.fixed_step;
  if (request.max_order != 0 && (request.max_order < 1 || request.max_order > 5)) {
    throw SettingError(Setting::max_order, fmt::format("{}", request.max_order), "not a BDF order (valid range [1, 5])");
  }
  settings.max_order = request.max_order != 0 ? request.max_order : (scene.boom.damping_ratio > 0.0 ? 5 : 2);
  settings.monitor = monitor_limits(scene);
  settings.work = request.work;
  return settings;
}

long ModelRun::slack_events() const {
  return std::count_if(result.wire_events.begin(), result.wire_events.end(),
                       [](const multibody::WireEvent& event) { return event.slack; });
}

namespace {

// The initial state of freshly made equations at their static equilibrium.
PreparedRun prepare_equations(const scene::Scene& scene, const scene::BoomChoice& choice,
                              std::unique_ptr<multibody::CraneEquations> made, multibody::StaticEquilibrium statics) {
  PreparedRun prepared;
  prepared.choice = choice;
  prepared.equations = std::move(made);
  multibody::CraneEquations& equations = *prepared.equations;
  prepared.statics = std::move(statics);
  prepared.from_static_equilibrium = scene.simulation.initial_state == scene::InitialState::static_equilibrium;
  prepared.initial_state = prepared.from_static_equilibrium ? prepared.statics.z : equations.initial_guess();
  if (scene.simulation.cargo_lift > 0.0 && equations.cargo_offset() >= 0) {
    prepared.initial_state(equations.cargo_offset() + 1) += scene.simulation.cargo_lift;  // raised, released at rest
  }
  return prepared;
}

}  // namespace

PreparedRun prepare_run(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* modes) {
  check_run_memory(choice);
  std::unique_ptr<multibody::CraneEquations> equations = scene::build_crane_equations(scene, choice, modes);
  multibody::StaticEquilibrium statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
  return prepare_equations(scene, choice, std::move(equations), std::move(statics));
}

PreparedRun prepare_run(scene::CraneModelCache& models, const scene::BoomChoice& choice,
                        std::optional<hydro::RadiationKind> radiation) {
  check_run_memory(choice);
  multibody::StaticEquilibrium statics = models.static_equilibrium(choice, radiation);
  return prepare_equations(models.scene(radiation), choice, models.model(choice, radiation)->equations(), std::move(statics));
}

namespace {

// The statistics window, per-output statistics, wire amplification, constraint residual and
// real-time factor of a finished run.
void summarize(const scene::Scene& scene, double duration, ModelRun& run) {
  run.window = stats_window(scene, run.result.time);
  run.stats = series_stats(run.result.samples, run.statics.outputs, run.window);
  double max_tension = 0.0;
  run.max_constraint_residual = 0.0;
  for (const multibody::CraneOutputs& sample : run.result.samples) {
    max_tension = std::max(max_tension, sample.wire_tension);
    run.max_constraint_residual = std::max(run.max_constraint_residual, std::abs(sample.constraint_residual));
  }
  run.amplification = run.statics.outputs.wire_tension > 0.0 ? max_tension / run.statics.outputs.wire_tension
                                                               : std::numeric_limits<double>::quiet_NaN();
  run.real_time_factor = duration / run.result.stats.wall_seconds;
  run.irregular = irregular_statistics(scene, run.result.time, run.result.samples, run.statics.outputs, run.window.first,
                                       scene.simulation.output_interval);
  run.slack_intervals = multibody::slack_intervals(run.result, run.monitor);
  run.snap_loads = multibody::snap_loads(run.result, run.monitor);
  run.max_buckling_load_ratio = multibody::max_buckling_load_ratio(run.result, run.monitor);
}

ModelRun prepared_model(const PreparedRun& prepared) {
  ModelRun run;
  run.choice = prepared.choice;
  run.elastic_dof = prepared.equations->elastic_size();
  run.state_size = prepared.state_size();
  run.from_static_equilibrium = prepared.from_static_equilibrium;
  run.statics = prepared.statics;
  if (const sea::IncidentWaveRecord* record = prepared.equations->wave_record()) {
    run.wave_kinematics = {"precomputed", "", record->stats(), {}};
  } else if (const std::string reason = prepared.equations->exact_kinematics_reason(); !reason.empty()) {
    run.wave_kinematics = {"exact", reason, std::nullopt, {}};
  }
  return run;
}

}  // namespace

ModelRun integrate_run(const scene::Scene& scene, PreparedRun& prepared, const multibody::RunSettings& settings) {
  ModelRun run = prepared_model(prepared);
  multibody::RunSettings run_settings = settings;
  run_settings.monitor.static_tension = prepared.statics.outputs.wire_tension;
  run.monitor = run_settings.monitor;
  const multibody::HullLoadCounts before = prepared.equations->hull_load_counts();
  run.result = multibody::simulate(*prepared.equations, prepared.initial_state, run_settings);
  const multibody::HullLoadCounts after = prepared.equations->hull_load_counts();
  run.wave_kinematics.hull_loads = {after.recorded - before.recorded, after.exact - before.exact};
  summarize(scene, settings.duration, run);
  return run;
}

ModelRun run_model(const scene::Scene& scene, const scene::BoomChoice& choice, const multibody::RunSettings& settings,
                   modal::ModeCache* modes, const std::function<void(const ModelRun&)>& on_prepared) {
  PreparedRun prepared = prepare_run(scene, choice, modes);
  if (on_prepared) on_prepared(prepared_model(prepared));
  return integrate_run(scene, prepared, settings);
}

double draft_at_mid_length(const scene::Scene& scene, const multibody::CraneOutputs& outputs) {
  if (!scene.hull) return std::numeric_limits<double>::quiet_NaN();
  const scene::Hull& hull = *scene.hull;
  const Eigen::Vector2d keel_mid =
      outputs.hull.head<2>() +
      multibody::rotation(outputs.hull.z()) * Eigen::Vector2d(hull.g1_aft_of_mid_length, -hull.g1_above_keel);
  return -keel_mid.y();
}

}  // namespace ffrf::study
