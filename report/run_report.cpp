// Static report, human summary and JSON summary of a crane run (see run_report.hpp).
#include "app/run_report.hpp"

#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <numbers>
#include <optional>

namespace ffrf::app {
namespace {

constexpr double degrees = 180.0 / std::numbers::pi;

// JSON integers from the solvers' long counters.
double count(long n) { return static_cast<double>(n); }

const char* initial_state_name(const ModelRun& run) {
  return run.from_static_equilibrium ? "static-equilibrium" : "as-built";
}

}  // namespace

coupling::MonitorLimits run_limits(const cases::Scene& scene, const ModelRun& run) {
  coupling::MonitorLimits limits = monitor_limits(scene);
  limits.static_tension = run.statics.outputs.wire_tension;
  return limits;
}

void write_detection_json(JsonWriter& json, const coupling::Detection& d) {
  json.begin_object().field("kind", coupling::to_string(d.kind)).field("time_s", d.time).field("fatal", d.fatal);
  json.field("cause", d.cause).field("remedy", d.remedy).field("value", d.value).end_object();
}

std::string failure_json(const RunContext& context, const std::string& model, const coupling::SolverFailure& failure) {
  JsonWriter json;
  json.begin_object();
  json.field("command", "run").field("status", "failed").field("model", model);
  json.key("provenance").begin_object();
  write_settings_json(json, context);
  json.end_object();
  json.key("failure");
  write_detection_json(json, failure.detection());
  json.field("solver", failure.solver());
  json.end_object();
  return json.str();
}

std::string ffrf_version() {
#ifdef FFRF_VERSION
  return FFRF_VERSION;
#else
  return "unknown";
#endif
}

RunContext make_context(const std::string& scene_file, const cases::Scene& scene,
                        const coupling::IntegratorSettings& settings) {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return {scene_file, &scene, settings, date, {}};
}

std::string static_report(const cases::Scene& scene, const ModelRun& run) {
  const coupling::StaticEquilibrium& s = run.statics;
  const coupling::CraneOutputs& o = s.outputs;
  std::string text = fmt::format("static equilibrium ({}; KINSOL: {} Newton iterations, scaled residual {:.2g}, {:.3g} s)\n",
                                 run.choice.label(), s.newton_iterations, s.scaled_residual, s.wall_seconds);
  if (scene.hull) {
    text += fmt::format("  hull      draft {:.4f} m at mid-length, trim {:+.4f} deg (+ = bow up)\n",
                        draft_at_mid_length(scene, o), o.hull.z() * degrees);
  } else {
    text += fmt::format("  hub       angle {:+.4f} deg at t = 0\n", o.hull.z() * degrees);
  }
  text += fmt::format("  boom tip  deflection {:+.5f} m transverse, {:+.5f} m axial (boom frame)\n", o.tip_deflection.y(),
                      o.tip_deflection.x());
  if (scene.wire) {
    text += fmt::format("  wire      stretch {:.5f} m, tension {:.6g} N\n", o.wire_length - scene.wire->unstretched_length,
                        o.wire_tension);
  }
  text += fmt::format("  joint B   Fx {:.6g} N, Fy {:.6g} N, M {:.6g} N m (on the boom)\n", o.joint_reaction.x(),
                      o.joint_reaction.y(), o.joint_reaction.z());
  const double euler = monitor_limits(scene).buckling_load;
  text += fmt::format("  boom      root axial force {:.6g} N, {:.3g} of the Euler buckling load {:.4g} N\n",
                      o.root_axial_force, std::max(0.0, -o.root_axial_force) / euler, euler);
  const cases::Stiffening stiffening = run.choice.stiffening.value_or(scene.boom.stiffening);
  text += stiffening == cases::Stiffening::none
              ? "  model     linear-elastic boom: geometric stiffening off (--stiffening static|centrifugal|both)\n"
              : fmt::format("  model     linear-elastic boom with {} geometric stiffening\n", cases::to_string(stiffening));
  if (scene.simulation.cargo_lift > 0.0) {
    text += fmt::format("  start     cargo raised {:g} m above this posture and released at rest\n", scene.simulation.cargo_lift);
  }
  return text;
}

void write_settings_json(JsonWriter& json, const RunContext& c) {
  json.field("scene", c.scene_file).field("scene_name", c.scene->name);
  json.field("integrator", coupling::to_string(c.settings.kind)).field("max_bdf_order", c.settings.max_order);
  json.field("rtol", c.settings.relative_tolerance).field("atol", c.settings.absolute_tolerance);
  json.field("duration_s", c.settings.duration).field("output_interval_s", c.settings.output_interval);
  json.field("ffrf_version", ffrf_version()).field("date", c.date);
}

void write_model_json(JsonWriter& json, const cases::Scene& scene, const ModelRun& run) {
  const coupling::StaticEquilibrium& s = run.statics;
  const coupling::CraneOutputs& o = s.outputs;
  json.field("model", run.choice.label()).field("boom", cases::to_string(run.choice.kind));
  json.field("elastic_dof", run.elastic_dof).field("initial_state", initial_state_name(run));

  json.key("static_equilibrium").begin_object();
  json.field("hull_draft_mid_length_m", draft_at_mid_length(scene, o)).field("hull_trim_deg", o.hull.z() * degrees);
  json.field("hull_x_m", o.hull.x()).field("hull_y_m", o.hull.y());
  json.field("cargo_x_m", o.cargo.x()).field("cargo_y_m", o.cargo.y()).field("cargo_pitch_deg", o.cargo.z() * degrees);
  json.field("tip_axial_m", o.tip_deflection.x()).field("tip_transverse_m", o.tip_deflection.y());
  json.field("wire_stretch_m", o.wire_length - scene.wire->unstretched_length).field("wire_tension_N", o.wire_tension);
  json.field("joint_force_x_N", o.joint_reaction.x()).field("joint_force_y_N", o.joint_reaction.y());
  json.field("joint_moment_Nm", o.joint_reaction.z());
  json.field("newton_iterations", count(s.newton_iterations)).field("function_evaluations", count(s.function_evaluations));
  json.field("scaled_residual", s.scaled_residual).field("wall_time_s", s.wall_seconds);
  json.field("root_axial_force_N", o.root_axial_force);
  json.field("geometric_stiffening", cases::to_string(run.choice.stiffening.value_or(scene.boom.stiffening)));
  json.end_object();

  json.key("statistics_window").begin_object();
  json.field("start_s", run.window.start_s).field("after_ramp", run.window.after_ramp);
  json.field("note", run.window.after_ramp
                         ? "min, max and RMS over t > ramp_periods x period; RMS about the static value"
                         : "min, max and RMS over the whole run (calm water, or the run ends within the ramp)");
  json.end_object();

  json.key("outputs").begin_object();
  const auto series = crane_series();
  for (std::size_t i = 0; i < series.size(); ++i) {
    json.key(series[i].column).begin_object();
    json.field("static", run.stats[i].static_value).field("min", run.stats[i].min).field("max", run.stats[i].max);
    json.field("rms_about_static", run.stats[i].rms).field("displacement_from_static", series[i].about_static);
    json.end_object();
  }
  json.end_object();

  json.key("wire").begin_object();
  json.field("static_tension_N", o.wire_tension).field("dynamic_amplification_factor", run.amplification);
  json.field("slack_events", count(run.slack_events()));
  json.field("taut_events", count(static_cast<long>(run.result.wire_events.size()) - run.slack_events()));
  const coupling::MonitorLimits limits = run_limits(scene, run);
  json.key("slack_intervals_s").begin_array();
  for (const coupling::SlackInterval& slack : coupling::slack_intervals(run.result, limits)) {
    json.begin_array().value(slack.start);
    json.value(std::isfinite(slack.end) ? std::optional<double>(slack.end) : std::nullopt).end_array();
  }
  json.end_array();
  json.key("snap_loads").begin_array();
  for (const coupling::SnapLoad& snap : coupling::snap_loads(run.result, limits)) {
    json.begin_object().field("taut_at_s", snap.time).field("peak_tension_N", snap.peak_tension);
    json.field("peak_at_s", snap.peak_time).field("peak_over_static", snap.ratio).end_object();
  }
  json.end_array();
  json.end_object();
  json.field("max_constraint_residual_m", run.max_constraint_residual);
  json.field("max_buckling_load_ratio", coupling::max_buckling_load_ratio(run.result, limits));
  json.key("detections").begin_array();
  for (const coupling::Detection& d : run.result.detections) write_detection_json(json, d);
  json.end_array();

  const coupling::SolverStats& st = run.result.stats;
  json.key("solver").begin_object();
  json.field("steps", count(st.steps)).field("function_evaluations", count(st.function_evaluations));
  json.field("jacobian_evaluations", count(st.jacobian_evaluations)).field("newton_iterations", count(st.newton_iterations));
  json.field("error_test_failures", count(st.error_test_failures));
  json.field("convergence_failures", count(st.convergence_failures));
  json.field("wall_time_s", st.wall_seconds).field("real_time_factor", run.real_time_factor);
  if (st.step > 0.0) json.field("fixed_step_s", st.step);
  if (st.projections > 0) json.field("projections", count(st.projections));
  json.end_object();
}

std::string run_json(const RunContext& context, const ModelRun& run) {
  JsonWriter json;
  json.begin_object();
  json.field("command", "run");
  json.key("provenance").begin_object();
  write_settings_json(json, context);
  json.end_object();
  write_model_json(json, *context.scene, run);
  json.key("model_warnings");
  write_warnings_json(json, context.warnings);
  json.end_object();
  return json.str();
}

std::string run_header_text(const RunContext& c, const ModelRun& run) {
  std::string text = fmt::format("scene       {}{}\n", c.scene_file, c.scene->name.empty() ? "" : " (" + c.scene->name + ")");
  text += fmt::format("model       {} ({} elastic DOFs), start from {}\n", run.choice.label(), run.elastic_dof,
                      initial_state_name(run));
  text += fmt::format("integrator  {}, rtol {:g}, atol {:g}, {:g} s, output every {:g} s{}\n\n",
                      coupling::to_string(c.settings.kind), c.settings.relative_tolerance, c.settings.absolute_tolerance,
                      c.settings.duration, c.settings.output_interval,
                      c.settings.kind == coupling::Integrator::cvode || c.settings.kind == coupling::Integrator::ida
                          ? fmt::format(", BDF order <= {}", c.settings.max_order)
                          : std::string());
  return text;
}

std::string dynamics_text(const ModelRun& run) {
  std::string text = fmt::format("\ndynamics ({}; motions are displacements from static equilibrium; RMS about the static value)\n",
                      run.window.after_ramp ? fmt::format("statistics over t > {:g} s, after the wave ramp", run.window.start_s)
                                            : std::string("statistics over the whole run"));
  text += fmt::format("  {:<24} {:>13} {:>13} {:>13} {:>13}\n", "output", "static", "min", "max", "RMS");
  const auto series = crane_series();
  for (std::size_t i = 0; i < series.size(); ++i) {
    const SeriesStats& s = run.stats[i];
    text += fmt::format("  {:<24} {:>13} {:>13} {:>13} {:>13}\n", series[i].column, format_value(s.static_value),
                        format_value(s.min), format_value(s.max), format_value(s.rms));
  }
  if (std::isfinite(run.amplification)) {
    text += fmt::format("  wire tension: dynamic amplification factor {:.4f} (max / static over the run), {} slack events\n",
                        run.amplification, run.slack_events());
  }
  text += fmt::format("  max constraint residual {:.3g} m\n", run.max_constraint_residual);
  if (!run.result.detections.empty()) {
    text += "\ndetected\n";
    for (const coupling::Detection& d : run.result.detections) {
      text += fmt::format("  {:<20} t = {:<9.4g} {}\n  {:<20} {:<13} remedy: {}\n", coupling::to_string(d.kind), d.time,
                          d.cause, "", "", d.remedy);
    }
  }
  const coupling::SolverStats& st = run.result.stats;
  text += fmt::format("\nsolver      {} steps, {} function and {} Jacobian evaluations, {} Newton iterations,\n"
                      "            {} error-test and {} convergence failures\n",
                      st.steps, st.function_evaluations, st.jacobian_evaluations, st.newton_iterations,
                      st.error_test_failures, st.convergence_failures);
  if (st.projections > 0) text += fmt::format("            {} constraint projections\n", st.projections);
  text += fmt::format("wall time   {:.3g} s ({:.4g}x real time)\n", st.wall_seconds, run.real_time_factor);
  return text;
}

}  // namespace ffrf::app
