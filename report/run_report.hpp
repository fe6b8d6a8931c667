// What `ffrf run` reports about one model's run (study/run_pipeline.hpp): the static-equilibrium
// report, the human summary (stdout), the JSON summary (summary.json, and stdout with --json), the
// time-series CSV and the modelling warnings. The JSON blocks of one model are shared with compare.
#pragma once

#include <string>

#include "solve/failure.hpp"
#include "report/json.hpp"
#include "study/model_warnings.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::report {

// Where a run came from: the scene and the integrator settings, this program's version, the date.
struct RunContext {
  std::string scene_file;
  const scene::Scene* scene = nullptr;
  multibody::RunSettings settings;
  std::string date;  // ISO 8601, UTC
  study::ModelWarnings warnings;  // `ffrf run`: the model against what the scene needs
};
RunContext make_context(const std::string& scene_file, const scene::Scene& scene,
                        const multibody::RunSettings& settings);
std::string ffrf_version();
// Now, ISO 8601 in UTC ("2025-01-31T12:00:00Z").
std::string utc_date();

// The static equilibrium in a few lines (draft and trim, tip deflection, wire, joint reaction).
std::string static_report(const scene::Scene& scene, const study::ModelRun& run);
std::string static_report(const scene::Scene& scene, const scene::BoomChoice& choice, const multibody::StaticEquilibrium& statics);

// The settings' keys (scene, integrator, tolerances, duration, version, date).
Json settings_json(const RunContext& context);
// The static equilibrium's keys (summary.json's "static_equilibrium"; `ffrf statics --json`).
Json static_equilibrium_json(const scene::Scene& scene, const scene::BoomChoice& choice, const multibody::StaticEquilibrium& statics);
// One model's keys (model, static_equilibrium, outputs, wire, solver, ...).
Json model_json(const scene::Scene& scene, const study::ModelRun& run);
// One detection {kind, time_s, fatal, cause, remedy, value}.
Json detection_json(const solve::Detection& detection);

std::string run_json(const RunContext& context, const study::ModelRun& run);
// A failed run: {"command": "run", "status": "failed", "model", "provenance", "failure": {...}}.
std::string failure_json(const RunContext& context, const std::string& model, const solve::SolverFailure& failure);
// The human summary: the header (scene, model, integrator), then static_report(), then the
// dynamics (statistics table, wire, solver costs).
std::string run_header_text(const RunContext& context, const study::ModelRun& run);
std::string dynamics_text(const scene::Scene& scene, const study::ModelRun& run);

// time_s and every crane_series() column, one row per output time.
std::string timeseries_csv(const study::ModelRun& run);

// A warning with its remedy in `ffrf run` options ("...; add --static-modes").
std::string warning_line(const study::ModelWarning& warning);
// "ffrf run: warning: ..." lines for stderr (below) and "note: ..." lines (above).
std::string warnings_text(const study::ModelWarnings& warnings);

// "nodal N=16" → "nodal_N16": for file names.
std::string slug(const std::string& label);
// For the human reports: engineering number formatting ("-" when not finite).
std::string format_value(double value);

}  // namespace ffrf::report
