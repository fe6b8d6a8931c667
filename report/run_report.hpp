// What `ffrf run` reports about one model's run: the static-equilibrium report, the human summary
// (stdout) and the JSON summary (summary.json, and stdout with --json). The JSON blocks of one
// model are shared with `ffrf compare`.
#pragma once

#include <string>

#include "app/crane_run.hpp"
#include "app/json_writer.hpp"
#include "app/run_warnings.hpp"

namespace ffrf::app {

// Where a run came from: the scene and the integrator settings, this program's version, the date.
struct RunContext {
  std::string scene_file;
  const cases::Scene* scene = nullptr;
  coupling::IntegratorSettings settings;
  std::string date;  // ISO 8601, UTC
  ModelWarnings warnings;  // `ffrf run`: the model against what the scene needs
};
RunContext make_context(const std::string& scene_file, const cases::Scene& scene,
                        const coupling::IntegratorSettings& settings);
std::string ffrf_version();

// The static equilibrium in a few lines (draft and trim, tip deflection, wire, joint reaction).
std::string static_report(const cases::Scene& scene, const ModelRun& run);

// Writes the keys common to the settings (scene, integrator, tolerances, duration, version, date)
// into an open JSON object.
void write_settings_json(JsonWriter& json, const RunContext& context);
// Writes one model's keys (model, static_equilibrium, outputs, wire, solver, ...) into an open object.
void write_model_json(JsonWriter& json, const cases::Scene& scene, const ModelRun& run);

std::string run_json(const RunContext& context, const ModelRun& run);
// The detectors' bounds of a finished run (the scene's, with its static wire tension).
coupling::MonitorLimits run_limits(const cases::Scene& scene, const ModelRun& run);
// One detection as a JSON object {kind, time_s, fatal, cause, remedy, value}.
void write_detection_json(JsonWriter& json, const coupling::Detection& detection);
// A failed run: {"command": "run", "status": "failed", "model", "provenance", "failure": {...}}.
std::string failure_json(const RunContext& context, const std::string& model, const coupling::SolverFailure& failure);
// The human summary: the header (scene, model, integrator), then static_report(), then the
// dynamics (statistics table, wire, solver costs).
std::string run_header_text(const RunContext& context, const ModelRun& run);
std::string dynamics_text(const ModelRun& run);

}  // namespace ffrf::app
