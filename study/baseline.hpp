// Regression baselines for users (docs/baselines.md): what `ffrf baseline record` keeps of one model's run
// so that a later run of the same scene and model can be checked against it (study/baseline_check.hpp).
//  * The boom's natural frequencies as `ffrf modes` computes them: clamped–free, unloaded, on the
//    model's mesh (N elements), ARPACK shift-invert at machine precision (study::solve_modes).
//  * The coupled crane's natural frequencies and damping ratios (crane scenes): the lowest
//    baseline_coupled_modes modes of the model linearised about its static equilibrium in calm
//    water, as `ffrf rao` computes them (study::coupled_natural_modes, study/rao.hpp).
//  * Per chosen output (a crane_series() column, default the judged outputs of study/error_measure.hpp):
//    its value at the static equilibrium and its min, max, mean, RMS about the static value and
//    standard deviation over the statistics window (study::stats_window: after the wave ramp), and
//    the wire tension's dynamic amplification (max over the run / static).
//  * Decimated time histories of the chosen outputs over the whole run: every k-th output sample,
//    k = max(1, ⌊T_short / (20 Δt)⌋) with Δt the output interval and T_short the shortest period of
//    the physics the outputs carry — the wave period, the hub's spin period, the boom's first
//    natural period and the cargo's bounce on the wire 2π√(m/k) — so that every such period keeps
//    at least 20 points (history_decimation); k = 1 when the output interval is already coarser.
//  * The model and settings that reproduce the run (boom choice with its stiffening resolved,
//    integrator, tolerances, BDF order, fixed step, duration, output interval) and its cost.
//  * The run's own integration error, measured when recording: the same run again with 1/100 of
//    the tolerances (a fixed-step run: a quarter of the step), and the largest deviation of any
//    recorded response from it in the units a check judges (study/baseline_check.hpp). A check's
//    default tolerance of the responses is derived from it.
// The run itself is study::run_model, the one pipeline. File provenance (program version, commit,
// scene file hash, date) and the file format belong to report/baseline_file.hpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "multibody/error_metrics.hpp"
#include "multibody/crane_run.hpp"
#include "modal/mode_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {

// How a baseline's run is reproduced: the boom model and the integrator settings, fully resolved
// (the scene's defaults written out, so that a later change of the scene does not change the model).
struct BaselineModel {
  scene::BoomChoice choice;  // stiffening always set
  solve::Integrator integrator = solve::Integrator::cvode;
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-6;
  double duration = 0.0;         // [s]
  double output_interval = 0.0;  // [s] (the scene's simulation.output_interval)
  double fixed_step = 0.0;       // [s] (0: adaptive)
  int max_order = 5;             // largest BDF order
};
// The model of a choice run with `settings` on `scene` (stiffening: the choice's or the scene's).
BaselineModel baseline_model(const scene::Scene& scene, const scene::BoomChoice& choice,
                             const multibody::RunSettings& settings);
// The integrator request that reproduces the model's settings on a scene (integrator_settings()
// adds the scene's output interval and detector bounds).
DynamicsRequest dynamics_request(const BaselineModel& model);

struct BoomFrequency {
  double hz = 0.0;
  std::string kind;  // "bending", "axial"
  int order = 0;     // 1-based within its kind
};

// One natural mode of the coupled, linearised crane.
struct CoupledFrequency {
  double hz = 0.0;
  double damping_ratio = 0.0;  // fraction of critical [-]
  std::string dominant;        // the coordinate with the largest share of the kinetic energy ("hull heave", "boom")
};

struct ChannelBaseline {
  std::string name;   // crane_series() column, unit in the name ("wire_tension_N")
  std::string unit;   // "N"
  bool about_static = false;  // the history and statistics are displacements from the static value
  double static_value = 0.0;  // the output at the static equilibrium (absolute, also for motions)
  double min = 0.0, max = 0.0, mean = 0.0;
  double rms = 0.0;           // about the static value (0 for motions), as `ffrf run`
  double standard_deviation = 0.0;  // about the mean
  std::vector<double> history;      // at Baseline::history_time
};

// The recorded run's integration error, estimated against a tighter run of the same model.
struct IntegrationError {
  double relative_tolerance = 0.0;  // of the tighter run
  double absolute_tolerance = 0.0;
  double fixed_step = 0.0;          // [s] (0: adaptive)
  long steps = 0;                   // of the tighter run
  double largest = 0.0;             // largest deviation of a response (deviation as a check judges it)
  std::string channel, quantity;    // where
  std::string problem;              // not empty: not measured, and why (the tighter runs failed)
  bool measured() const { return problem.empty(); }
};

struct Baseline {
  BaselineModel model;
  solve::SolverStats cost;  // steps, evaluations, wall time of the recorded run
  int boom_elements = 0;       // the mesh of the frequencies
  std::vector<BoomFrequency> boom_frequencies;
  // Lowest natural modes of the coupled crane, lowest first; empty for a hub scene and in a
  // baseline recorded before they were (file format 1).
  std::vector<CoupledFrequency> coupled_modes;
  double window_start = 0.0;   // statistics window start [s]
  bool window_after_ramp = false;
  std::optional<double> wire_amplification;  // none without a wire
  int decimation = 1;          // history keeps every decimation-th output sample
  std::vector<double> history_time;  // [s]
  std::vector<ChannelBaseline> channels;
  std::optional<IntegrationError> integration_error;  // none: not measured (check runs)

  const ChannelBaseline* channel(const std::string& name) const;  // nullptr when not recorded
};

struct BaselineRequest {
  scene::BoomChoice choice;
  multibody::RunSettings settings;
  std::vector<std::string> outputs;  // crane_series() columns; empty: the scene's judged outputs
  std::optional<int> decimation;     // of the histories; default: history_decimation() (a check
                                     // uses its baseline's, so that both sample the same times)
};

// The boom modes recorded per baseline (as `ffrf modes`' default), fewer on a coarse mesh.
inline constexpr int baseline_boom_modes = 6;
// The coupled crane's natural modes recorded per baseline (the lowest; all when fewer).
inline constexpr int baseline_coupled_modes = 8;
// Samples kept per shortest period of the physics in a decimated history.
inline constexpr int history_points_per_period = 20;

// The crane_series() column of a judged output channel ("wire_tension" → "wire_tension_N").
std::string series_column(multibody::OutputChannel channel);
// The column for a name: a column itself ("wire_tension_N") or a channel ("wire_tension");
// nothing when neither.
std::optional<std::string> output_column(const std::string& name);
// "crane_surge_m, crane_heave_m, ..." (for messages).
std::string output_columns();

// The decimation k of the histories (see the header comment) for a boom whose first natural
// frequency is `first_boom_hz` (0: none).
int history_decimation(const scene::Scene& scene, double output_interval, double first_boom_hz);

// The boom's frequencies as `ffrf modes SCENE -N elements` (up to baseline_boom_modes).
// Throws modal::EigenSolverError.
std::vector<BoomFrequency> boom_frequencies(const scene::Scene& scene, int elements);

// The lowest baseline_coupled_modes natural modes of the crane of `choice` linearised about its
// static equilibrium (study::coupled_natural_modes); empty for a scene without a hull.
std::vector<CoupledFrequency> coupled_frequencies(const scene::Scene& scene, const scene::BoomChoice& choice,
                                                  modal::ModeCache* modes = nullptr);

// Runs the model once (study::run_model) and keeps what a baseline holds, without the integration
// error. Throws std::invalid_argument for an unknown output, scene::SceneError,
// solve::SolverFailure and modal::EigenSolverError.
Baseline record_run(const scene::Scene& scene, const BaselineRequest& request, modal::ModeCache* modes = nullptr);

// record_run(), then the same run with tighter settings (1/100 of the tolerances; a fixed-step
// run: a quarter of the step) that measures its integration error (baseline_record.cpp); when the
// tighter runs fail, the error says why it was not measured. Throws as record_run().
Baseline record_baseline(const scene::Scene& scene, const BaselineRequest& request, modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
