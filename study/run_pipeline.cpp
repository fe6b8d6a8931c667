// One crane model's run for `ffrf run` and `ffrf compare` (see crane_run.hpp).
#include "app/crane_run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>

#include "cases/scene_loader.hpp"
#include "fem/analytic_beam.hpp"
#include "coupling/planar.hpp"

namespace ffrf::app {

void add_dynamics_options(CLI::App& sub, DynamicsOptions& options) {
  sub.add_option("--integrator", options.integrator,
                 "Integrator " + coupling::integrator_choices() +
                     ": cvode = minimal coordinates (BDF ODE), ida = Lagrange multipliers (stabilized index-2 DAE), "
                     "arkode = minimal coordinates (explicit Runge-Kutta), generalized-alpha = index-3, fixed step (needs --step); "
                     "index1, baumgarte, projection = full coordinates as an index-1 ODE (BDF): unstabilized (the constraint "
                     "drifts), with Baumgarte feedback (omega_b = 10 rad/s), or projected onto the constraint after every step")
      ->capture_default_str();
  sub.add_option("--rtol", options.rtol, "Relative tolerance, in (0, 1)")->capture_default_str();
  sub.add_option("--atol", options.atol, "Absolute tolerance (scaled by each coordinate's typical size), in (0, 1)")
      ->capture_default_str();
  sub.add_option("--duration", options.duration, "Simulated time [s] (default: simulation.duration of the scene)");
  sub.add_option("--max-order", options.max_order,
                 "Largest BDF order of cvode and ida, 1-5 (default: 2 for an undamped boom, where BDF 3-5 are not "
                 "stable on its undamped stiff modes; 5 otherwise)");
  sub.add_option("--step", options.step,
                 "Fixed time step [s] of generalized-alpha (required) and arkode (0: adaptive), at most the output interval")
      ->capture_default_str();
}

SettingsOrError integrator_settings(const DynamicsOptions& options, const cases::Scene& scene) {
  const auto kind = coupling::parse_integrator(options.integrator);
  if (!kind) {
    return {std::nullopt, fmt::format("--integrator {}: unknown integrator; choose one of {}", options.integrator,
                                      coupling::integrator_choices())};
  }
  for (const auto& [name, value] : {std::pair{"--rtol", options.rtol}, std::pair{"--atol", options.atol}}) {
    if (!(value > 0.0 && value < 1.0)) {
      return {std::nullopt, fmt::format("{} {}: not a valid tolerance (valid range (0, 1))", name, value)};
    }
  }
  coupling::IntegratorSettings settings;
  settings.kind = *kind;
  settings.relative_tolerance = options.rtol;
  settings.absolute_tolerance = options.atol;
  settings.output_interval = scene.simulation.output_interval;
  settings.duration = options.duration.value_or(scene.simulation.duration);
  if (!(settings.duration >= settings.output_interval) || !std::isfinite(settings.duration)) {
    return {std::nullopt,
            fmt::format("--duration {}: shorter than one output interval of the scene ({} s) (valid range [{}, inf) s)",
                        settings.duration, settings.output_interval, settings.output_interval)};
  }
  if (!(options.step >= 0.0 && options.step <= settings.output_interval)) {
    return {std::nullopt, fmt::format("--step {}: not a valid fixed step (valid range [0, {}] s, the output interval)",
                                      options.step, settings.output_interval)};
  }
  if (settings.kind == coupling::Integrator::generalized_alpha && options.step == 0.0) {
    return {std::nullopt, fmt::format("--integrator generalized-alpha is a fixed-step method: give --step in (0, {}] s, "
                                      "e.g. --step 0.01", settings.output_interval)};
  }
  settings.fixed_step = options.step;
  if (options.max_order != 0 && (options.max_order < 1 || options.max_order > 5)) {
    return {std::nullopt, fmt::format("--max-order {}: not a BDF order (valid range [1, 5])", options.max_order)};
  }
  settings.max_order = options.max_order != 0 ? options.max_order : (scene.boom.damping_ratio > 0.0 ? 5 : 2);
  settings.progress = ::isatty(STDERR_FILENO) != 0;
  settings.monitor = monitor_limits(scene);
  return {settings, {}};
}

std::optional<cases::Scene> load_crane_scene(const std::string& path, const std::string& command) {
  try {
    cases::Scene scene = cases::load_scene(path);
    if (!scene.has_base()) {
      fmt::print(stderr, "ffrf {}: error: {}: not a crane scene: it has neither a [hull] section (a crane "
                 "needs [hull], [cargo], [wire] and boom.angle/root_x/root_y) nor a [hub]; `ffrf modes` analyses a "
                 "single beam\n", command, path);
      return std::nullopt;
    }
    return scene;
  } catch (const cases::SceneError& error) {
    for (const auto& problem : error.problems()) fmt::print(stderr, "{}\n", cases::format_problem(problem));
    fmt::print(stderr, "ffrf {}: error: {}: {} problem{} in the scene\n", command, path, error.problems().size(),
               error.problems().size() == 1 ? "" : "s");
    return std::nullopt;
  }
}

long ModelRun::slack_events() const {
  return std::count_if(result.wire_events.begin(), result.wire_events.end(),
                       [](const coupling::WireEvent& event) { return event.slack; });
}

ModelRun run_model(const cases::Scene& scene, const cases::BoomChoice& choice,
                   const coupling::IntegratorSettings& settings, const std::function<void(const ModelRun&)>& on_static) {
  ModelRun run;
  run.choice = choice;
  const auto equations = cases::build_crane(scene, choice);
  run.elastic_dof = equations->elastic_size();
  run.statics = coupling::solve_static_equilibrium(*equations, equations->initial_guess());
  run.from_static_equilibrium = scene.simulation.initial_state == cases::InitialState::static_equilibrium;
  if (on_static) on_static(run);
  Eigen::VectorXd z0 = run.from_static_equilibrium ? run.statics.z : equations->initial_guess();
  if (scene.simulation.cargo_lift > 0.0 && equations->cargo_offset() >= 0) {
    z0(equations->cargo_offset() + 1) += scene.simulation.cargo_lift;  // raised, released at rest
  }
  coupling::IntegratorSettings run_settings = settings;
  run_settings.monitor.static_tension = run.statics.outputs.wire_tension;
  run.result = coupling::integrate(*equations, z0, run_settings);
  summarize_run(scene, settings.duration, run);
  return run;
}

void summarize_run(const cases::Scene& scene, double duration, ModelRun& run) {
  run.window = stats_window(scene, run.result.time);
  run.stats = series_stats(run.result.samples, run.statics.outputs, run.window);
  double max_tension = 0.0;
  run.max_constraint_residual = 0.0;
  for (const coupling::CraneOutputs& sample : run.result.samples) {
    max_tension = std::max(max_tension, sample.wire_tension);
    run.max_constraint_residual = std::max(run.max_constraint_residual, std::abs(sample.constraint_residual));
  }
  run.amplification = run.statics.outputs.wire_tension > 0.0 ? max_tension / run.statics.outputs.wire_tension
                                                               : std::numeric_limits<double>::quiet_NaN();
  run.real_time_factor = duration / run.result.stats.wall_seconds;
}

std::string timeseries_csv(const ModelRun& run) {
  std::string csv = "time_s";
  for (const SeriesSpec& spec : crane_series()) csv += fmt::format(",{}", spec.column);
  csv += '\n';
  for (std::size_t i = 0; i < run.result.samples.size(); ++i) {
    csv += fmt::format("{:.10g}", run.result.time[i]);
    for (const SeriesSpec& spec : crane_series()) {
      csv += fmt::format(",{:.10g}", series_value(spec, run.result.samples[i], run.statics.outputs));
    }
    csv += '\n';
  }
  return csv;
}

coupling::MonitorLimits monitor_limits(const cases::Scene& scene) {
  coupling::MonitorLimits limits;
  const fem::BeamMesh& mesh = scene.boom.mesh;
  limits.boom_length = mesh.length;
  limits.deflection_limit = scene.simulation.deflection_limit;
  limits.constraint_drift_limit = scene.simulation.constraint_drift_limit;
  limits.buckling_load = *fem::euler_buckling_load(mesh, fem::Boundary::clamped_free);  // the root is clamped
  limits.wire_unstretched_length = scene.wire ? scene.wire->unstretched_length : 0.0;
  return limits;
}

double draft_at_mid_length(const cases::Scene& scene, const coupling::CraneOutputs& outputs) {
  if (!scene.hull) return std::numeric_limits<double>::quiet_NaN();
  const cases::Hull& hull = *scene.hull;
  const Eigen::Vector2d keel_mid =
      outputs.hull.head<2>() +
      coupling::rotation(outputs.hull.z()) * Eigen::Vector2d(hull.g1_aft_of_mid_length, -hull.g1_above_keel);
  return -keel_mid.y();
}

std::string slug(const std::string& label) {
  std::string out;
  for (char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c)) != 0) {
      out += c;
    } else if (c != '=' && !out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

std::string format_value(double value) { return std::isfinite(value) ? fmt::format("{:.6g}", value) : "-"; }

}  // namespace ffrf::app
