// What `ffrf run` and `ffrf compare` share: the dynamics options and their validation, loading a
// crane scene with its problems reported, one model's run (build → static equilibrium →
// integration → statistics) and its time-series CSV.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/crane_series.hpp"
#include "cases/crane_builder.hpp"
#include "cases/scene.hpp"
#include "coupling/simulation.hpp"
#include "coupling/static_equilibrium.hpp"

namespace ffrf::app {

// Integrator options as typed on the command line (validated by integrator_settings()).
struct DynamicsOptions {
  std::string integrator = "cvode";
  double rtol = 1e-6;
  double atol = 1e-6;
  std::optional<double> duration;
  double step = 0.0;  // fixed step [s] (generalized-alpha: required; arkode: 0 = adaptive)
  int max_order = 0;  // largest BDF order of cvode/ida; 0 = from the physics (see integrator_settings)
};
void add_dynamics_options(CLI::App& sub, DynamicsOptions& options);

// The settings for a scene, or the message naming the bad option, its value and the valid range.
// The BDF order limit defaults to 2 (A-stable) when the boom is undamped and elastic, where BDF 3–5
// would be held to tiny steps by undamped stiff modes on the imaginary axis; 5 otherwise.
struct SettingsOrError {
  std::optional<coupling::IntegratorSettings> settings;
  std::string error;
};
SettingsOrError integrator_settings(const DynamicsOptions& options, const cases::Scene& scene);

// Loads the scene and checks that it is a crane scene; prints every problem on stderr and returns
// nothing on failure (bad input: exit 2).
std::optional<cases::Scene> load_crane_scene(const std::string& path, const std::string& command);

// One model's complete run.
struct ModelRun {
  cases::BoomChoice choice;
  int elastic_dof = 0;
  bool from_static_equilibrium = true;  // false: the scene's initial_state is as-built
  coupling::StaticEquilibrium statics;
  coupling::RunResult result;
  StatsWindow window;
  std::vector<SeriesStats> stats;  // per crane_series() entry
  double amplification = 0.0;      // max wire tension over the run / static tension
  double max_constraint_residual = 0.0;
  double real_time_factor = 0.0;   // simulated seconds per wall second (integration)

  const coupling::CraneOutputs& static_outputs() const { return statics.outputs; }
  long slack_events() const;       // the wire went slack
};

// Fills a finished run's statistics window, per-output statistics, wire amplification factor, max
// constraint residual and real-time factor (`duration` simulated seconds) from its samples.
void summarize_run(const cases::Scene& scene, double duration, ModelRun& run);

// Builds, solves the static equilibrium, integrates. Throws cases::SceneError (the scene cannot
// make this crane) and coupling::SolverFailure. `on_static` sees the run once its static
// equilibrium is known, before the integration.
ModelRun run_model(const cases::Scene& scene, const cases::BoomChoice& choice,
                   const coupling::IntegratorSettings& settings,
                   const std::function<void(const ModelRun&)>& on_static = {});

// time_s and every crane_series() column, one row per output time.
std::string timeseries_csv(const ModelRun& run);

// The failure detectors' bounds for a scene (deflection and drift limits, the boom's Euler load,
// the wire); run_model adds the static wire tension.
coupling::MonitorLimits monitor_limits(const cases::Scene& scene);

// Hull draft at mid-length [m] (keel depth below still water) of a static or sampled pose; NaN
// without a hull (hub scenes).
double draft_at_mid_length(const cases::Scene& scene, const coupling::CraneOutputs& outputs);

// "nodal N=16" → "nodal_N16": for file names.
std::string slug(const std::string& label);

// For the human reports: engineering number formatting.
std::string format_value(double value);

}  // namespace ffrf::app
