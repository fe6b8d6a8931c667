// Text and JSON of `ffrf statics` (see statics_report.hpp).
#include "report/statics_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>

#include "report/json.hpp"
#include "report/quantities.hpp"
#include "report/run_report.hpp"

namespace ffrf::report {
std::string statics_text(const std::string& scene_file, const scene::Scene& scene, const study::StaticsResult& result) {
  const multibody::StaticEquilibrium& s = result.statics;
  const multibody::CraneOutputs& o = s.outputs;
  std::string text = fmt::format("scene       {}{}\nmodel       {} ({} elastic DOFs), calm water\n\n", scene_file,
                                 scene.name.empty() ? "" : " (" + scene.name + ")", result.choice.label(), result.elastic_dof);
  text += static_report(scene, result.choice, s);
  if (scene.is_crane()) {
    text += fmt::format("  offsets   from the even keel at the mean draft: surge {:+.4f} m, heave {:+.4f} m, pitch {:+.4f} deg\n",
                        result.hull_offset.x(), result.hull_offset.y(), result.hull_offset.z() * degrees);
  }
  if (scene.cargo) {
    text += fmt::format("  cargo     G2 at x {:.4f} m, y {:.4f} m (still water at y = 0), pitch {:+.4f} deg\n", o.cargo.x(),
                        o.cargo.y(), o.cargo.z() * degrees);
    text += fmt::format("  wire      tension {:.6g} N against the cargo's weight {:.6g} N (ratio {:.9f})\n", o.wire_tension,
                        result.cargo_weight, o.wire_tension / result.cargo_weight);
  }
  text += fmt::format("  boom      root moment {:.6g} N m, tip deflection {:.3f} % of the boom length\n", o.joint_reaction.z(),
                      100.0 * o.tip_deflection.norm() / scene.boom.mesh.length);
  const multibody::StaticSolvePath& path = result.path;
  text += fmt::format("  balance   largest out-of-balance force {:.3g} N, moment {:.3g} N m (rigid bodies and joints); scaled residual {:.2g}\n",
                      path.max_force_residual, path.max_moment_residual, s.scaled_residual);
  text += fmt::format("  solver    {}, {} residual evaluations\n",
                      path.by_continuation() ? fmt::format("Newton from the rest pose failed; reached by continuation in the load "
                                                           "({} steps)", path.continuation_steps)
                                             : std::string("Newton from the rest pose"),
                      s.function_evaluations);
  for (const solve::Detection& note : result.notes) {
    text += fmt::format("  note      {}: {} ({})\n", solve::to_string(note.kind), note.cause, note.remedy);
  }
  return text;
}

std::string statics_json(const std::string& scene_file, const scene::Scene& scene, const study::StaticsResult& result) {
  Json json;
  json["command"] = "statics";
  json["status"] = "ok";
  json["scene"] = scene_file;
  json["scene_name"] = scene.name;
  json["model"] = result.choice.label();
  json["boom"] = scene::to_string(result.choice.kind);
  json["elastic_dof"] = result.elastic_dof;
  json["static_equilibrium"] = static_equilibrium_json(scene, result.choice, result.statics);
  json["solve"] = Json{{"method", result.path.by_continuation() ? "continuation in the load" : "Newton"},
                       {"continuation_steps", result.path.continuation_steps},
                       {"max_force_residual_N", result.path.max_force_residual},
                       {"max_moment_residual_Nm", result.path.max_moment_residual}};
  json["rest_pose"] = Json{{"x_m", result.rest_pose.x()}, {"y_m", result.rest_pose.y()}, {"pitch_deg", result.rest_pose.z() * degrees}};
  json["hull_offset"] = Json{{"surge_m", result.hull_offset.x()},
                             {"heave_m", result.hull_offset.y()},
                             {"pitch_deg", result.hull_offset.z() * degrees}};
  json["cargo_weight_N"] = result.cargo_weight;
  json["buckling_load_ratio"] = result.buckling_ratio;
  json["notes"] = Json::array();
  for (const solve::Detection& note : result.notes) json["notes"].push_back(detection_json(note));
  json["ffrf_version"] = ffrf_version();
  json["date"] = utc_date();
  return json_text(json);
}

std::string statics_failure_json(const std::string& scene_file, const scene::Scene& scene, const std::string& model,
                                 const solve::SolverFailure& failure) {
  Json json;
  json["command"] = "statics";
  json["status"] = "failed";
  json["scene"] = scene_file;
  json["scene_name"] = scene.name;
  json["model"] = model;
  json["failure"] = detection_json(failure.detection());
  json["solver"] = failure.solver();
  json["ffrf_version"] = ffrf_version();
  json["date"] = utc_date();
  return json_text(json);
}

}  // namespace ffrf::report
