// What the commands share on the command line: the dynamics options (integrator, tolerances,
// duration, step, BDF order) and the reference options, each mapped to the study's request; the
// option name of each study setting (so the study's neutral messages name the flag); loading a
// scene with every problem printed; and the error, failure and progress lines on stderr.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "solve/failure.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"
#include "study/reference.hpp"
#include "study/boom_choice.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::app {

// Integrator options as typed on the command line.
// The integrator is a formulation × solver pair (solve/integrator_choice.hpp): --integrator names a
// valid pair (the names before the split: cvode, ida, ...); --formulation and --solver choose the two
// apart (the one not given from the default cvode = minimal × bdf). The two ways exclude each other.
struct DynamicsOptions {
  std::string integrator;   // empty: cvode
  std::string formulation;  // empty: from --integrator
  std::string solver;       // empty: from --integrator
  long max_steps = solve::WorkLimits{}.max_steps;  // steps over the run
  std::optional<double> max_wall_time;                // [s]
  double min_step = 0.0;                              // step-size floor [s]; 0: none
  double rtol = 1e-6;
  double atol = 1e-6;
  std::optional<double> duration;
  double step = 0.0;  // fixed step [s] (generalized-alpha: required; arkode: 0 = adaptive)
  int max_order = 0;  // largest BDF order of cvode/ida; 0 = from the physics
};
void add_dynamics_options(CLI::App& sub, DynamicsOptions& options);
void add_reference_options(CLI::App& sub, study::ReferenceOptions& options);
// --stiffening none|static|centrifugal|both (empty: what the physics needs with the scene's, as
// recommend decides).
void add_stiffening_option(CLI::App& sub, std::string& stiffening);

// A command-line value that is not valid: the message names the option, the value and the range.
struct BadOption : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The boom model as typed on the command line (`run`, `baseline record|check`); an option not given
// is empty.
struct ModelOptions {
  std::string boom;  // empty: nodal (run, record) or the baseline's (check)
  std::optional<int> elements;
  std::optional<int> modes;
  bool static_modes = false;
  bool no_static_modes = false;
  std::string stiffening;  // empty: the scene's boom.stiffening (or the baseline's)
  std::string mode_set;    // empty: clamped-free (or the baseline's)
  std::string stress_recovery;  // empty: acceleration (or the baseline's)
};
// --boom --elements/-N --modes/-k --static-modes --no-static-modes --stiffening --mode-set.
void add_model_options(CLI::App& sub, ModelOptions& options);
// The boom of a scene when no option is given (study/boom_choice.hpp).
using study::default_boom_choice;
// `base` with the options that were given (checked by study::boom_choice); throws BadOption naming
// the option (or boom.elements of the scene), the value and the range.
scene::BoomChoice boom_choice(const ModelOptions& options, scene::BoomChoice base);

// The integrator settings for a scene (progress on a terminal); throws BadOption.
multibody::RunSettings integrator_settings(const DynamicsOptions& options, const scene::Scene& scene);
// "1%" → 0.01, "0.01" → 0.01 (--tolerance of compare, sweep, recommend); throws BadOption when not a
// number in (0, 1).
double parse_tolerance(std::string text);
// --tolerance (default "1%"); `what` says what it bounds.
void add_tolerance_option(CLI::App& sub, std::string& tolerance, const std::string& what);
// --stiffening as given (empty: not given); throws BadOption for an unknown name.
std::optional<scene::Stiffening> stiffening_option(const std::string& stiffening);
// The option a study setting comes from ("--rtol").
std::string_view option_name(study::Setting setting);
// "--rtol 0: not a valid tolerance (valid range (0, 1))"
std::string option_message(const study::SettingError& error);

// --set KEY=VALUE (repeatable) of every command that reads a scene: a scene value given beside the
// file, checked as the file's own (scene/scene_overrides.hpp).
void add_set_option(CLI::App& sub, std::vector<std::string>& values);
// The --set values; throws scene::SceneError for one that is not KEY=VALUE.
scene::SceneOverrides scene_overrides(const std::vector<std::string>& values);

// "\n--set boom.angle=55 deg" per value the scene was given beside its file (empty: none): what a
// journal's settings add to the file's text, so that a rerun with other values starts afresh.
std::string overrides_text(const scene::Scene& scene);

// Loads the scene with the --set values; prints every problem on stderr and returns nothing on
// failure (exit 2). With `needs_base`, a scene without [hull] or [hub] is refused (the crane commands).
std::optional<scene::Scene> load_scene(const std::string& path, const std::vector<std::string>& set,
                                       const std::string& command, bool needs_base);

// "ffrf CMD: error: MESSAGE" on stderr; returns exit_bad_input.
int bad_input(const std::string& command, const std::string& message);
// Every problem of a scene that cannot make the crane, then the error line; returns exit_bad_input.
int scene_error(const std::string& command, const std::string& path, const scene::SceneError& error, const std::string& what);
// The options behind a neutral adjustment of a remedy ("--rtol/--atol" for the tolerances).
std::string option_names(solve::Adjustment adjustment);
// "options: --rtol/--atol, --min-step, ..." for a failure kind's adjustments.
std::string remedy_options(solve::FailureKind kind);
// The pair the options name; throws BadOption naming the option and the valid choices or pairs.
solve::Integrator integrator_choice(const DynamicsOptions& options);
// "ffrf CMD: solver failure (WHAT): ... Try: remedy (options: --rtol/--atol, ...)" (and "nothing written
// to OUT"); returns exit_solver_failure.
int solver_failure(const std::string& command, const std::string& what, const solve::SolverFailure& failure,
                   const std::string& out);

// True when stderr is a terminal (progress lines are printed there only).
bool stderr_is_terminal();
// A progress line for a terminal: "\r\033[Kffrf CMD: WHAT" (nothing when stderr is not a terminal;
// an empty WHAT clears the line).
void progress(const std::string& command, const std::string& what, bool newline = false);

}  // namespace ffrf::app
