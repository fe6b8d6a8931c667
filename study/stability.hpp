// The stability map of `ffrf stability` (where each method fails, docs/stability.md) as studies: each experiment
// runs its models through the one pipeline (study/run_pipeline.hpp) and returns what happened — the
// runs, the failures named by kind with their time and number, and the hand results they are
// checked against. The report library (report/stability_*.cpp) turns each into a section with its
// cells, table, charts and finding. docs/stability.md explains each failure and its remedy.
//  1. explicit RK step limits (every scene)         4. slack wire and snap loads (a cargo)
//  2. constraint drift per formulation (every scene) 5. BDF order on undamped stiff modes (a hub, undamped boom)
//  3. spin with and without centrifugal stiffening   6. buckling margin (gravity and a cargo)
//     (a spinning hub)
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solve/failure.hpp"
#include "multibody/run_monitor.hpp"
#include "scene/scene.hpp"
#include "study/campbell.hpp"
#include "study/stability_explicit_map.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {

struct StabilityOptions {
  bool quick = false;  // fewer models, shorter horizons (< 20 s in all)
  std::function<void(const std::string&)> progress;  // one line per run (the command prints it on terminals)
};

// 1. The largest stable explicit RK step per boom model, measured against the theory.
struct ExplicitStepStudy {
  ExplicitStabilityMap map;
  solve::StableStepSearch search;
  bool quick = false;
};
ExplicitStepStudy explicit_step_study(const scene::Scene& scene, const StabilityOptions& options);

// 2. The clamp at B treated five ways on one model: |C(t)| per formulation against the drift bound.
struct DriftRun {
  solve::Integrator formulation;
  std::optional<ModelRun> run;                 // with |C| in its samples' constraint_residual
  std::optional<solve::Detection> failure;  // a solver failure (fatal)
  double max_residual = 0.0, final_residual = 0.0;  // [m]
  const solve::Detection* drift_detection() const;  // the run's constraint-drift detection, if any
};
struct DriftStudy {
  scene::BoomChoice choice;
  multibody::RunSettings settings;
  double cargo_lift = 0.0;  // [m] the scene's
  double limit = 0.0;       // simulation.constraint_drift_limit [m]
  std::vector<DriftRun> runs;
  double max_drift(solve::Integrator formulation) const;  // NaN when that run failed
};
DriftStudy constraint_drift_study(const scene::Scene& scene, const StabilityOptions& options);

// 3. Spin (a spinning hub): Ωs × stiffening × model, each over the scene's duration.
struct SpinRun {
  double spin = 0.0;  // Ωs [rad/s]
  scene::BoomChoice choice;
  bool stiffened = false;
  std::vector<double> time, deflection;  // tip transverse deflection [m] (up to the failure)
  std::optional<solve::Detection> failure;
  double max_deflection = 0.0;
  double spin_rate_at_failure = 0.0;  // Ω(t) at the detection [rad/s]
  std::string label() const;          // "nodal N=32, no stiffening"
};
struct SpinStudy {
  std::vector<double> spins;
  std::vector<scene::BoomChoice> models;
  double omega1 = 0.0;       // first clamped–free bending frequency at rest, analytic [rad/s]
  double chart_spin = 4.0;   // the spin of the time-history chart and the nodal–modal agreement [rad/s]
  multibody::RunSettings settings;
  std::vector<SpinRun> runs;  // model-major, then stiffening (off, on), then spin
  CampbellResult campbell;    // over [0, max spin]
  double agreement = 0.0;     // max|δ_nodal − δ_modal| / max|δ_nodal|, stiffened at chart_spin (NaN: not both ran)
};
SpinStudy spin_study(const scene::Scene& scene, const StabilityOptions& options);
// Ω(t) of the scene's hub motion driven to `spin` [rad/s].
double hub_spin_rate(const scene::Hub& hub, double spin, double t);

// 4. Slack wire and snap loads (a cargo): the cargo raised and dropped.
struct WireRun {
  scene::BoomChoice choice;
  std::optional<ModelRun> run;
  std::optional<solve::Detection> failure;
  std::vector<multibody::SlackInterval> slack;
  std::vector<multibody::SnapLoad> snaps;
};
struct WireStudy {
  double lift = 0.0;                // d [m]
  bool lift_from_scene = true;      // false: the scene had none, 1 m is used
  multibody::RunSettings settings;
  std::vector<WireRun> runs;        // rigid, then elastic (nodal)
  // The hand result (rigid boom, undamped wire): s = mg/k, ω = √(k/m), A = √(s² + 2g(d − s)/ω²).
  double mass = 0.0, stiffness = 0.0, gravity = 0.0;
  double static_stretch = 0.0, omega = 0.0, amplitude = 0.0, hand_peak = 0.0;  // k(s + A) [N]
};
WireStudy wire_study(const scene::Scene& scene, const StabilityOptions& options);

// 5. BDF order on undamped stiff modes: cvode with max_order 2 and 5 on the same run.
struct OrderRun {
  int order = 0;
  std::optional<solve::SolverStats> stats;
  std::optional<solve::Detection> failure;
};
struct BdfOrderStudy {
  scene::BoomChoice choice;
  double duration = 0.0, relative_tolerance = 0.0;
  std::vector<OrderRun> runs;  // order 2, then 5
  double step_ratio = 0.0;     // steps of order ≤ 5 over order ≤ 2 (NaN: one failed)
  // BDF 3–5 held to the stiff modes: more than 5× the steps of A-stable BDF 2.
  bool collapsed() const { return step_ratio > 5.0; }
};
BdfOrderStudy bdf_order_study(const scene::Scene& scene, const StabilityOptions& options);

// 6. Buckling margin: the root compression against the Euler load, and the softened first mode.
struct BucklingStudy {
  scene::BoomChoice choice;
  double axial_force = 0.0;        // root axial force from the static equilibrium, tension > 0 [N]
  double euler_load = 0.0;         // π²EI/(4L²) [N]
  double load_ratio = 0.0;         // compression / Euler load
  double warning_ratio = 0.0;      // the run monitor's warning threshold
  double omega1_unstressed = NAN, omega1_prestressed = NAN, omega1_series = NAN;  // [rad/s]
  std::string modes_failure;       // non-empty: the prestressed modes could not be computed (why)
  bool ample() const { return load_ratio < warning_ratio; }
};
BucklingStudy buckling_study(const scene::Scene& scene, const StabilityOptions& options);

// The experiments that apply to a scene, run in report order.
struct StabilityMap {
  std::optional<ExplicitStepStudy> explicit_steps;
  std::optional<DriftStudy> drift;
  std::optional<SpinStudy> spin;
  std::optional<WireStudy> wire;
  std::optional<BdfOrderStudy> bdf_order;
  std::optional<BucklingStudy> buckling;
  double wall_seconds = 0.0;
};
// Throws scene::SceneError (the scene cannot make the crane); solver failures are results.
StabilityMap stability_map(const scene::Scene& scene, const StabilityOptions& options);

}  // namespace ffrf::study
