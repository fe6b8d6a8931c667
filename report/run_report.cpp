// Static report, human summary, JSON summary, time series and warnings of a crane run (see
// run_report.hpp).
#include "report/run_report.hpp"
#include "report/quantities.hpp"
#include "study/radiation_compare.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <chrono>
#include <cmath>
#include <ctime>
#include <numbers>
#include <optional>

#include "hydro/infinite_frequency.hpp"
#include "multibody/output_channels.hpp"
#include "report/boom_stress_report.hpp"
#include "report/irregular_report.hpp"

namespace ffrf::report {
namespace {


const char* initial_state_name(const study::ModelRun& run) {
  return run.from_static_equilibrium ? "static-equilibrium" : "as-built";
}

}  // namespace

Json detection_json(const solve::Detection& d) {
  return Json{{"kind", solve::to_string(d.kind)}, {"time_s", d.time},     {"fatal", d.fatal},
              {"cause", d.cause},                    {"remedy", d.remedy},   {"value", d.value}};
}

std::string failure_json(const RunContext& context, const std::string& model, const solve::SolverFailure& failure) {
  Json json;
  json["command"] = "run";
  json["status"] = "failed";
  json["model"] = model;
  json["provenance"] = settings_json(context);
  json["failure"] = detection_json(failure.detection());
  json["solver"] = failure.solver();
  return json_text(json);
}

std::string ffrf_version() {
#ifdef FFRF_VERSION
  return FFRF_VERSION;
#else
  return "unknown";
#endif
}

std::string utc_date() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return date;
}

RunContext make_context(const std::string& scene_file, const scene::Scene& scene,
                        const multibody::RunSettings& settings) {
  return {scene_file, &scene, settings, utc_date(), {}};
}

std::string static_report(const scene::Scene& scene, const study::ModelRun& run) {
  return static_report(scene, run.choice, run.statics);
}

std::string static_report(const scene::Scene& scene, const scene::BoomChoice& choice, const multibody::StaticEquilibrium& s) {
  const multibody::CraneOutputs& o = s.outputs;
  std::string text = fmt::format("static equilibrium ({}; KINSOL: {} Newton iterations, scaled residual {:.2g}, {:.3g} s)\n",
                                 choice.label(), s.newton_iterations, s.scaled_residual, s.wall_seconds);
  if (scene.hull) {
    text += fmt::format("  hull      draft {:.4f} m at mid-length, trim {:+.4f} deg (+ = bow up)\n",
                        study::draft_at_mid_length(scene, o), o.hull.z() * degrees);
  } else {
    text += fmt::format("  hub       angle {:+.4f} deg at t = 0\n", o.hull.z() * degrees);
  }
  text += fmt::format("  boom tip  deflection {:+.5f} m transverse, {:+.5f} m axial (boom frame)\n", o.tip_deflection.y(),
                      o.tip_deflection.x());
  if (scene.wire) {
    text += fmt::format("  wire      stretch {:.5f} m, tension {:.6g} N\n", o.wire_length - scene.wire->unstretched_length,
                        o.wire_tension);
  }
  if (scene.a_frame) {
    text += fmt::format("  A-frame   rotation {:+.6f} deg on its deck pin; luffing wires {:.6g} N, backstays {:.6g} N\n",
                        o.a_frame_rotation * degrees, o.luffing_tension, o.backstay_tension);
  }
  text += fmt::format("  joint B   Fx {:.6g} N, Fy {:.6g} N, M {:.6g} N m (on the boom)\n", o.joint_reaction.x(),
                      o.joint_reaction.y(), o.joint_reaction.z());
  const double euler = study::monitor_limits(scene).buckling_load;
  text += fmt::format("  boom      root axial force {:.6g} N, {:.3g} of the Euler buckling load {:.4g} N\n",
                      o.root_axial_force, std::max(0.0, -o.root_axial_force) / euler, euler);
  const scene::Stiffening stiffening = choice.stiffening.value_or(scene.boom.stiffening);
  text += stiffening == scene::Stiffening::none
              ? "  model     linear-elastic boom: geometric stiffening off (--stiffening static|centrifugal|both)\n"
              : fmt::format("  model     linear-elastic boom with {} geometric stiffening\n", scene::to_string(stiffening));
  text += boom_stress_static_line(scene, o);
  if (scene.simulation.cargo_lift > 0.0) {
    text += fmt::format("  start     cargo raised {:g} m above this posture and released at rest\n", scene.simulation.cargo_lift);
  }
  return text;
}

Json settings_json(const RunContext& c) {
  Json json{{"scene", c.scene_file},
              {"scene_name", c.scene->name},
              {"integrator", solve::to_string(c.settings.kind)},
              {"max_bdf_order", c.settings.max_order},
              {"rtol", c.settings.relative_tolerance},
              {"atol", c.settings.absolute_tolerance},
              {"duration_s", c.settings.duration},
              {"output_interval_s", c.settings.output_interval},
              {"ffrf_version", ffrf_version()},
              {"date", c.date}};
  if (!c.scene->overrides.empty()) json["scene_overrides"] = c.scene->overrides;  // --set / with_values, in order
  if (c.scene->bem) {
    const scene::BemHull& bem = *c.scene->bem;
    json["radiation"] = study::radiation_label(*c.scene);
    json["excitation"] = bem.excitation == scene::ExcitationModel::bem ? "bem" : "froude-krylov";
    json["bem_file"] = bem.radiation_file;
    json["bem_format"] = bem.format == scene::BemFormat::capytaine ? "capytaine" : "wamit";
    // A∞ of the radiation models: the file's, or estimated (a Capytaine dataset without ω = ∞).
    json["infinite_frequency_added_mass"] =
        bem.infinite_frequency_estimate ? "estimated: " + hydro::to_string(bem.infinite_frequency_estimate->method) : "file";
  }
  return json;
}

Json static_equilibrium_json(const scene::Scene& scene, const scene::BoomChoice& choice, const multibody::StaticEquilibrium& s) {
  const multibody::CraneOutputs& o = s.outputs;
  // Every output channel at rest by its column (display unit in the name), then what follows from
  // them and the scene, and how KINSOL got there.
  Json json;
  for (const multibody::OutputChannelSpec& channel : multibody::output_channels()) {
    json[std::string(channel.column)] = channel.value(o);
  }
  json.update(Json{
      {"hull_draft_mid_length_m", study::draft_at_mid_length(scene, o)},
      {"hull_trim_deg", o.hull.z() * degrees},
      {"wire_stretch_m", scene.wire ? o.wire_length - scene.wire->unstretched_length : NAN},
      {"newton_iterations", s.newton_iterations},
      {"function_evaluations", s.function_evaluations},
      {"scaled_residual", s.scaled_residual},
      {"wall_time_s", s.wall_seconds},
      {"root_axial_force_N", o.root_axial_force},
      {"geometric_stiffening", scene::to_string(choice.stiffening.value_or(scene.boom.stiffening))}});
  return json;
}

Json wave_kinematics_json(const study::WaveKinematicsUse& use) {
  Json json{{"method", use.method},
            {"hull_loads_recorded", use.hull_loads.recorded},
            {"hull_loads_exact", use.hull_loads.exact}};
  if (!use.reason.empty()) json["reason"] = use.reason;
  if (use.record) {
    const sea::IncidentWaveRecordStats& r = *use.record;
    json["record"] = Json{{"components", r.components},
                          {"patches", r.patches},
                          {"taylor_degree", r.degree},
                          {"line_degree", r.line_degree},
                          {"channels", r.channels},
                          {"samples", r.samples},
                          {"time_step_s", r.time_step},
                          {"truncation_bound_m", r.truncation_bound},
                          {"interpolation_error_m", r.interpolation_error},
                          {"elevation_bound_m", r.elevation_bound},
                          {"slope_bound", r.slope_bound},
                          {"memory_MB", r.memory_bytes / 1e6},
                          {"build_time_s", r.build_seconds}};
  }
  return json;
}

std::string wave_kinematics_text(const study::WaveKinematicsUse& use) {
  if (use.method.empty()) return {};
  if (!use.record) return fmt::format("sea         exact component sums ({})\n", use.reason);
  const sea::IncidentWaveRecordStats& r = *use.record;
  return fmt::format("sea         precomputed: {} components recorded in {} patches (Taylor degree {}), {} samples every "
                     "{:.3g} s, {:.1f} MB, built in {:.2f} s; error <= {:.2g} m\n",
                     r.components, r.patches, r.degree, r.samples, r.time_step, r.memory_bytes / 1e6, r.build_seconds,
                     r.truncation_bound + r.interpolation_error);
}

Json model_json(const scene::Scene& scene, const study::ModelRun& run) {
  Json json;
  json["model"] = run.choice.label();
  json["boom"] = scene::to_string(run.choice.kind);
  json["elastic_dof"] = run.elastic_dof;
  json["initial_state"] = initial_state_name(run);
  json["static_equilibrium"] = static_equilibrium_json(scene, run.choice, run.statics);
  json["statistics_window"] = Json{
      {"start_s", run.window.start_s},
      {"after_ramp", run.window.after_ramp},
      {"ramp_end_s", run.window.ramp_end_s},
      {"note", run.window.after_ramp ? "min, max and RMS over t > ramp_periods x period; RMS about the static value"
                                     : "min, max and RMS over the whole run (calm water, or the run ends within the ramp)"}};
  Json outputs = Json::object();
  const auto series = study::crane_series();
  for (std::size_t i = 0; i < series.size(); ++i) {
    outputs[std::string(series[i].column)] = Json{{"static", run.stats[i].static_value},
                                                  {"min", run.stats[i].min},
                                                  {"max", run.stats[i].max},
                                                  {"rms_about_static", run.stats[i].rms},
                                                  {"displacement_from_static", series[i].about_static}};
  }
  json["outputs"] = std::move(outputs);
  json["boom_stress"] = boom_stress_json(scene, run);
  Json wire{{"static_tension_N", run.statics.outputs.wire_tension},
            {"dynamic_amplification_factor", run.amplification},
            {"slack_events", run.slack_events()},
            {"taut_events", static_cast<long>(run.result.wire_events.size()) - run.slack_events()}};
  wire["slack_intervals_s"] = Json::array();
  for (const multibody::SlackInterval& slack : run.slack_intervals) {
    wire["slack_intervals_s"].push_back(Json::array({slack.start, std::isfinite(slack.end) ? Json(slack.end) : Json(nullptr)}));
  }
  wire["snap_loads"] = Json::array();
  for (const multibody::SnapLoad& snap : run.snap_loads) {
    wire["snap_loads"].push_back(Json{{"taut_at_s", snap.time},
                                      {"peak_tension_N", snap.peak_tension},
                                      {"peak_at_s", snap.peak_time},
                                      {"peak_over_static", snap.ratio}});
  }
  json["wire"] = std::move(wire);
  if (run.irregular) json["irregular_sea"] = irregular_json(*run.irregular);
  if (!run.wave_kinematics.method.empty()) json["wave_kinematics"] = wave_kinematics_json(run.wave_kinematics);
  json["max_constraint_residual_m"] = run.max_constraint_residual;
  json["max_buckling_load_ratio"] = run.max_buckling_load_ratio;
  json["detections"] = Json::array();
  for (const solve::Detection& d : run.result.detections) json["detections"].push_back(detection_json(d));
  const solve::SolverStats& st = run.result.stats;
  Json solver{{"steps", st.steps},
              {"function_evaluations", st.function_evaluations},
              {"jacobian_evaluations", st.jacobian_evaluations},
              {"newton_iterations", st.newton_iterations},
              {"error_test_failures", st.error_test_failures},
              {"convergence_failures", st.convergence_failures},
              {"wall_time_s", st.wall_seconds},
              {"real_time_factor", run.real_time_factor}};
  if (st.step > 0.0) solver["fixed_step_s"] = st.step;
  if (st.projections > 0) solver["projections"] = st.projections;
  json["solver"] = std::move(solver);
  return json;
}

std::string run_json(const RunContext& context, const study::ModelRun& run) {
  Json json;
  json["command"] = "run";
  json["provenance"] = settings_json(context);
  json.update(model_json(*context.scene, run));
  Json warnings{{"tolerance", context.warnings.tolerance}, {"below", Json::array()}, {"above", Json::array()}};
  for (const study::ModelWarning& w : context.warnings.below) warnings["below"].push_back(warning_line(w));
  for (const study::ModelWarning& w : context.warnings.above) warnings["above"].push_back(warning_line(w));
  json["model_warnings"] = std::move(warnings);
  return json_text(json);
}

std::string run_header_text(const RunContext& c, const study::ModelRun& run) {
  std::string text = fmt::format("scene       {}{}\n", c.scene_file, c.scene->name.empty() ? "" : " (" + c.scene->name + ")");
  text += fmt::format("model       {} ({} elastic DOFs), start from {}\n", run.choice.label(), run.elastic_dof,
                      initial_state_name(run));
  text += fmt::format("integrator  {}, rtol {:g}, atol {:g}, {:g} s, output every {:g} s{}\n\n",
                      solve::to_string(c.settings.kind), c.settings.relative_tolerance, c.settings.absolute_tolerance,
                      c.settings.duration, c.settings.output_interval,
                      c.settings.kind == solve::Integrator::cvode || c.settings.kind == solve::Integrator::ida
                          ? fmt::format(", BDF order <= {}", c.settings.max_order)
                          : std::string());
  text.insert(text.size() - 1, wave_kinematics_text(run.wave_kinematics));
  if (c.scene->bem) {  // hull hydrodynamics from BEM files: which model owns which force
    const scene::BemHull& bem = *c.scene->bem;
    text.insert(text.size() - 1, fmt::format("hydro       radiation {}; excitation {}{}\n", study::radiation_label(*c.scene),
                                             bem.excitation == scene::ExcitationModel::bem
                                                 ? "BEM (Froude-Krylov + diffraction), pressure hydrostatic only"
                                                 : "Froude-Krylov (wave pressure on the wetted box)",
                                             bem.infinite_frequency_estimate
                                                 ? "; A∞ estimated (" + hydro::to_string(bem.infinite_frequency_estimate->method) + ")"
                                                 : std::string()));
  }
  return text;
}

std::string dynamics_text(const scene::Scene& scene, const study::ModelRun& run) {
  std::string text = fmt::format("\ndynamics ({}; motions are displacements from static equilibrium; RMS about the static value)\n",
                      run.window.after_ramp ? fmt::format("statistics over t > {:g} s, after the wave ramp", run.window.start_s)
                      : run.window.ramp_end_s > 0.0
                          ? fmt::format("statistics over the whole run, which ends within the wave ramp (t < {:g} s)",
                                        run.window.ramp_end_s)
                          : std::string("statistics over the whole run"));
  text += fmt::format("  {:<24} {:>13} {:>13} {:>13} {:>13}\n", "output", "static", "min", "max", "RMS");
  const auto series = study::crane_series();
  for (std::size_t i = 0; i < series.size(); ++i) {
    const study::SeriesStats& s = run.stats[i];
    text += fmt::format("  {:<24} {:>13} {:>13} {:>13} {:>13}\n", series[i].column, format_value(s.static_value),
                        format_value(s.min), format_value(s.max), format_value(s.rms));
  }
  if (std::isfinite(run.amplification)) {
    text += fmt::format("  wire tension: dynamic amplification factor {:.4f} (max / static over the run), {} slack events\n",
                        run.amplification, run.slack_events());
  }
  text += fmt::format("  max constraint residual {:.3g} m\n", run.max_constraint_residual);
  if (!run.result.boom_stress.empty()) text += "  " + boom_stress_text(scene, run);
  if (run.irregular) text += irregular_text(*run.irregular);
  if (!run.result.detections.empty()) {
    text += "\ndetected\n";
    for (const solve::Detection& d : run.result.detections) {
      text += fmt::format("  {:<20} t = {:<9.4g} {}\n  {:<20} {:<13} remedy: {}\n", solve::to_string(d.kind), d.time,
                          d.cause, "", "", d.remedy);
    }
  }
  const solve::SolverStats& st = run.result.stats;
  text += fmt::format("\nsolver      {} steps, {} function and {} Jacobian evaluations, {} Newton iterations,\n"
                      "            {} error-test and {} convergence failures\n",
                      st.steps, st.function_evaluations, st.jacobian_evaluations, st.newton_iterations,
                      st.error_test_failures, st.convergence_failures);
  if (st.projections > 0) text += fmt::format("            {} constraint projections\n", st.projections);
  text += fmt::format("wall time   {:.3g} s ({:.4g}x real time)\n", st.wall_seconds, run.real_time_factor);
  if (run.wave_kinematics.hull_loads.recorded + run.wave_kinematics.hull_loads.exact > 0) {
    text += fmt::format("hull loads  {} from the recorded sea, {} by the exact sums{}\n", run.wave_kinematics.hull_loads.recorded,
                        run.wave_kinematics.hull_loads.exact,
                        run.wave_kinematics.record ? " (outside the record's patches or bounds)" : "");
  }
  return text;
}

std::string timeseries_csv(const study::ModelRun& run) {
  std::string csv = "time_s";
  for (const study::SeriesSpec& spec : study::crane_series()) csv += fmt::format(",{}", spec.column);
  csv += '\n';
  for (std::size_t i = 0; i < run.result.samples.size(); ++i) {
    csv += fmt::format("{:.10g}", run.result.time[i]);
    for (const study::SeriesSpec& spec : study::crane_series()) {
      csv += fmt::format(",{:.10g}", study::series_value(spec, run.result.samples[i], run.statics.outputs));
    }
    csv += '\n';
  }
  return csv;
}

std::string warning_line(const study::ModelWarning& w) {
  switch (w.remedy) {
    case study::Remedy::modal_with_static_modes: return w.finding + "; use --boom modal --static-modes";
    case study::Remedy::keep_vibration_modes: return fmt::format("{}; keep k >= {}", w.finding, w.modes);
    case study::Remedy::add_static_modes: return w.finding + "; add --static-modes";
    case study::Remedy::static_stiffening: return w.finding + "; use --stiffening static";
    case study::Remedy::centrifugal_stiffening: return w.finding + "; use --stiffening centrifugal";
    case study::Remedy::cheaper_model: return w.finding + ": `ffrf recommend` finds the cheapest adequate model";
  }
  return w.finding;
}

std::string warnings_text(const study::ModelWarnings& warnings) {
  std::string text;
  for (const study::ModelWarning& w : warnings.below) text += "ffrf run: warning: modelled below need: " + warning_line(w) + "\n";
  for (const study::ModelWarning& w : warnings.above) text += "ffrf run: note: modelled above need: " + warning_line(w) + "\n";
  return text;
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

}  // namespace ffrf::report
