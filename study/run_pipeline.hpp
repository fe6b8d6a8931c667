// The one run pipeline (every command brings a model to its initial state here). prepare_run() builds the crane of a boom choice, solves its
// static equilibrium and brings it to the scene's initial state: the static equilibrium (or the
// as-built pose, simulation.initial_state), with the cargo raised by simulation.cargo_lift and
// released at rest; a hub's prescribed motion is part of the model. A study that runs one model
// many times (sweep, the converged reference, rao) takes it and its static equilibrium from a
// scene::CraneModelCache, built and solved once and shared by its threads. integrate_run() integrates a
// prepared model and gathers its statistics; run_model() is the two in a row. Every study — run,
// the converged reference, compare, sweep, recommend, the stability experiments — and the benches
// go through these functions: nothing else brings a model to its initial state.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "multibody/run_monitor.hpp"
#include "multibody/crane_run.hpp"
#include "multibody/crane_statics.hpp"
#include "modal/mode_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/crane_model_cache.hpp"
#include "scene/scene.hpp"
#include "sea/incident_wave_record_stats.hpp"
#include "study/irregular_statistics.hpp"
#include "study/output_series.hpp"
#include "study/verdict.hpp"

namespace ffrf::study {

// --- integrator settings: one set of defaults for every study ---

// A setting a study was given, in neutral words (the command line maps each to its option).
enum class Setting {
  relative_tolerance, absolute_tolerance, duration, fixed_step, max_order,
  reference_elements, reference_tolerance, reference_bound, reference_levels, tolerance, jobs, elements,
  boom_model, modes, stiffening, mode_set, stress_recovery,
  integrator, formulation, solver, step_limit, wall_clock_limit, step_floor,
  wave_periods, wave_frequencies, outputs, eigen_solver, boundary, grid, headings,
};
std::string_view to_string(Setting setting);  // "relative tolerance", ...

// A setting out of its valid range: which, the value as given, what is wrong (with the range).
class SettingError : public std::invalid_argument {
 public:
  SettingError(Setting setting, std::string value, std::string problem);
  Setting setting() const { return setting_; }
  const std::string& value() const { return value_; }
  const std::string& problem() const { return problem_; }

 private:
  Setting setting_;
  std::string value_, problem_;
};

// What a run is asked for; the rest of multibody::RunSettings follows from the scene.
struct DynamicsRequest {
  solve::Integrator integrator = solve::Integrator::cvode;
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-6;
  std::optional<double> duration;  // default: simulation.duration of the scene
  double fixed_step = 0.0;         // generalized-α: required; arkode: 0 = adaptive [s]
  int max_order = 0;               // largest BDF order of cvode/ida; 0: from the physics
  solve::WorkLimits work = {};  // steps, wall clock and step-size floor of the run
};

// The integrator a front end names: a valid pair by its name (`integrator`: "cvode", "ida", ...), or
// the `formulation` and the `solver` apart (the one not given from cvode = minimal × bdf); all three
// empty: cvode. Throws SettingError (Setting::integrator, formulation or solver) for an unknown name,
// for both ways at once and for a pair that is not implemented, with the valid names or pairs.
solve::Integrator integrator_choice(const std::string& integrator, const std::string& formulation,
                                    const std::string& solver);

// The work limits a run accepts: steps over the run [1, max_step_limit], wall clock (0, max_wall_clock]
// s (infinite: none), the adaptive solvers' step floor [0, max_step_floor] s.
inline constexpr long max_step_limit = 1'000'000'000;
inline constexpr double max_wall_clock = 1e6, max_step_floor = 3600.0;
// Throws SettingError (step_limit, wall_clock_limit, step_floor) for a limit out of its range.
void validate(const solve::WorkLimits& work);

// The tolerances every run accepts: tighter than 1e-12 is at the edge of what the integrators
// resolve in double precision (IDA at 1e-14 crawls for minutes over 2 s of the reference crane),
// looser than 0.1 resolves nothing.
inline constexpr double min_tolerance = 1e-12, max_tolerance = 0.1;

// The settings for a scene: its output interval, the duration, the failure detectors' bounds of
// the scene (monitor_limits), and the BDF order limit from the physics when not given: 2 for an
// undamped boom (BDF 3–5 are held to tiny steps by its undamped stiff modes on the imaginary
// axis; 2 is A-stable), 5 otherwise. Throws SettingError for a value out of range, for more output
// samples than scene::max_output_samples and for more fixed steps than max_fixed_steps
// (study/work_limits.hpp), and for work limits out of range (validate above).
multibody::RunSettings integrator_settings(const scene::Scene& scene, const DynamicsRequest& request);

// The failure detectors' bounds for a scene (deflection and drift limits, the boom's Euler load,
// the wire); integrate_run() adds the static wire tension.
multibody::MonitorLimits monitor_limits(const scene::Scene& scene);

// --- the pipeline ---

// A model in its initial state, ready to integrate (possibly more than once: benches).
struct PreparedRun {
  scene::BoomChoice choice;
  std::unique_ptr<multibody::CraneEquations> equations;
  multibody::StaticEquilibrium statics;
  Eigen::VectorXd initial_state;        // minimal coordinates at t = 0 (at rest)
  bool from_static_equilibrium = true;  // false: simulation.initial_state = as-built
  int state_size() const { return static_cast<int>(2 * initial_state.size()); }  // ODE state (z, ż)
};

// How the run's hull loads read the incident wave: method, why exact, the record's size and cost
// (sea/incident_wave_record.hpp), and how many loads took each path.
struct WaveKinematicsUse {
  std::string method;  // "precomputed" | "exact"; empty: no wave on a floating hull
  std::string reason;  // why exact
  std::optional<sea::IncidentWaveRecordStats> record;
  multibody::HullLoadCounts hull_loads;  // of this run's integration
};

// One model's complete run.
struct ModelRun {
  scene::BoomChoice choice;
  int elastic_dof = 0;
  int state_size = 0;                   // 2 × minimal coordinates
  bool from_static_equilibrium = true;
  multibody::StaticEquilibrium statics;
  multibody::RunResult result;
  StatsWindow window;
  std::vector<SeriesStats> stats;  // per crane_series() entry
  double amplification = 0.0;      // max wire tension over the run / static tension
  double max_constraint_residual = 0.0;
  double real_time_factor = 0.0;   // simulated seconds per wall second (integration)
  std::optional<IrregularStatistics> irregular;  // an irregular sea: statistics after the ramp
  WaveKinematicsUse wave_kinematics;
  // The failure detectors' bounds the run was judged by (the scene's, its static wire tension
  // added), and what they found over the run: the wire's slack intervals and snap loads, the largest
  // boom compression over its Euler load.
  multibody::MonitorLimits monitor;
  std::vector<multibody::SlackInterval> slack_intervals;
  std::vector<multibody::SnapLoad> snap_loads;
  double max_buckling_load_ratio = 0.0;

  const multibody::CraneOutputs& static_outputs() const { return statics.outputs; }
  long slack_events() const;       // the wire went slack
  // Solver work, RHS evaluations × state size (study/verdict.hpp: the measure every verdict decides by).
  double work() const { return solver_work(result.stats.function_evaluations, state_size); }
};

// Builds the crane (modes from `modes`, or solved here), solves its static equilibrium, applies
// the scene's initial state. Throws SettingError when the model is beyond the memory limit
// (study/work_limits.hpp), scene::SceneError (the scene cannot make this crane) and
// solve::SolverFailure (KINSOL).
PreparedRun prepare_run(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* modes = nullptr);
// The same on the cache's scene with `radiation` as its [bem] radiation model (empty: the scene's
// own) and the cache's shared model of `choice` and its static equilibrium (each built and solved
// once per distinct model, scene/crane_model_cache.hpp): the run gets its own equations (workspace
// and run state).
PreparedRun prepare_run(scene::CraneModelCache& models, const scene::BoomChoice& choice,
                        std::optional<hydro::RadiationKind> radiation = std::nullopt);

// Integrates a prepared model with `settings` (the static wire tension added to its monitor) and
// gathers the statistics. Throws solve::SolverFailure.
ModelRun integrate_run(const scene::Scene& scene, PreparedRun& prepared, const multibody::RunSettings& settings);

// prepare_run then integrate_run. `on_prepared` sees the run once its static equilibrium is known,
// before the integration (the command line prints the static report there).
ModelRun run_model(const scene::Scene& scene, const scene::BoomChoice& choice, const multibody::RunSettings& settings,
                   modal::ModeCache* modes = nullptr, const std::function<void(const ModelRun&)>& on_prepared = {});

// Hull draft at mid-length [m] (keel depth below still water) of a static or sampled pose; NaN
// without a hull (hub scenes).
double draft_at_mid_length(const scene::Scene& scene, const multibody::CraneOutputs& outputs);

}  // namespace ffrf::study
