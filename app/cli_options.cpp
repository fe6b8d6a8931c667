// The options the commands share and the lines they print on stderr (see cli_options.hpp).
#include "app/cli_options.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

#include "app/commands.hpp"
#include "app/option_checks.hpp"
#include "scene/scene_key.hpp"
#include "solve/integrator_table.hpp"
#include "study/work_limits.hpp"

namespace ffrf::app {

void add_dynamics_options(CLI::App& sub, DynamicsOptions& options) {
  std::string pairs;
  for (const solve::IntegratorEntry& entry : solve::integrator_table()) {
    pairs += fmt::format("; {} = {} x {}: {}", entry.name, solve::to_string(entry.choice.formulation),
                         solve::to_string(entry.choice.solver), entry.summary);
  }
  sub.add_option("--integrator", options.integrator,
                 "Integrator " + solve::integrator_choices() + " (default cvode), each a formulation x solver pair" + pairs);
  sub.add_option("--formulation", options.formulation,
                 "Constraint formulation " + solve::formulation_choices() +
                     " (with --solver; instead of --integrator; default minimal): minimal coordinates, or Lagrange "
                     "multipliers at index 3, stabilized index 2, index 1 (drifts), index 1 with Baumgarte feedback or "
                     "with projection");
  sub.add_option("--solver", options.solver,
                 "Solver " + solve::solver_choices() + " (with --formulation; default bdf): BDF (CVODE/IDA), explicit "
                 "Runge-Kutta (ARKODE), generalized-alpha (fixed step, needs --step)");
  sub.add_option("--max-steps", options.max_steps, "Work limit: steps over the whole run (then 'too much work')")
      ->capture_default_str()
      ->check(whole_number(1, 1000000000));
  sub.add_option("--max-wall-time", options.max_wall_time,
                 "Work limit: wall-clock seconds of each integration (then 'too much work'; default: none)")
      ->check(finite_number(0.0, 1e6, "s", true));
  sub.add_option("--min-step", options.min_step,
                 "Work limit: step-size floor of the adaptive solvers [s] (then 'step-size collapse'; 0: none)")
      ->capture_default_str()
      ->check(finite_number(0.0, 3600.0, "s"));
  const CLI::Validator tolerance = finite_number(study::min_tolerance, study::max_tolerance);
  sub.add_option("--rtol", options.rtol, "Relative tolerance")->capture_default_str()->check(tolerance);
  sub.add_option("--atol", options.atol, "Absolute tolerance (scaled by each coordinate's typical size)")
      ->capture_default_str()
      ->check(tolerance);
  sub.add_option("--duration", options.duration, "Simulated time [s] (default: simulation.duration of the scene)")
      ->check(scene_key_range(scene::scene_key("simulation.duration")));
  sub.add_option("--max-order", options.max_order,
                 "Largest BDF order of cvode and ida, 1-5 (default: 2 for an undamped boom, where BDF 3-5 are not "
                 "stable on its undamped stiff modes; 5 otherwise)")
      ->check(whole_number(1, 5));
  sub.add_option("--step", options.step,
                 "Fixed time step [s] of generalized-alpha (required) and arkode (0: adaptive), at most the output interval")
      ->capture_default_str()
      ->check(finite_number(0.0, 3600.0, "s"));
}

void add_reference_options(CLI::App& sub, study::ReferenceOptions& options) {
  sub.add_option("--reference-elements", options.start_elements, "Reference: elements of the first level")
      ->capture_default_str()
      ->check(scene_key_count(scene::scene_key("boom.elements")));
  sub.add_option("--reference-rtol", options.start_relative_tolerance,
                 "Reference: CVODE relative tolerance of the first level")
      ->capture_default_str()
      ->check(finite_number(study::min_tolerance, study::max_tolerance));
  sub.add_option("--reference-bound", options.bound,
                 "Reference: converged when the worst normalized RMS change between two levels is below this")
      ->capture_default_str()
      ->check(finite_number(0.0, 1.0, {}, true));
  sub.add_option("--reference-levels", options.max_levels,
                 "Reference: at most this many levels (each doubles the elements and tightens rtol 10x)")
      ->capture_default_str()
      ->check(whole_number(1, 6));
}

void add_stiffening_option(CLI::App& sub, std::string& stiffening) {
  sub.add_option("--stiffening", stiffening,
                 "Geometric stiffening none|static|centrifugal|both of every model and the reference (default: what "
                 "the physics needs at 1 % with boom.stiffening of the scene, as recommend decides)");
}

void add_model_options(CLI::App& sub, ModelOptions& options) {
  sub.add_option("--boom", options.boom, "Boom model " + scene::boom_kind_choices() + " (default: nodal)");
  sub.add_option("--elements,-N", options.elements, "Number of beam elements (default: boom.elements of the scene)")
      ->check(scene_key_count(scene::scene_key("boom.elements")));
  sub.add_option("--modes,-k", options.modes,
                 fmt::format("Number of vibration modes of the modal boom (default: {}, with static modes)", study::default_modal_modes))
      ->check(whole_number(1, 1000));
  sub.add_flag("--static-modes", options.static_modes,
               "Add the static correction modes to the modal boom (the default; docs/validation.md)");
  sub.add_flag("--no-static-modes", options.no_static_modes,
               "Vibration modes only (misses the static deflection under a hanging load)");
  sub.add_option("--stiffening", options.stiffening,
                 "Geometric stiffening none|static|centrifugal|both (default: boom.stiffening of the scene)");
  sub.add_option("--mode-set", options.mode_set,
                 "The modal boom's mode set (its floating frame's reference condition): clamped-free (the default), "
                 "free-free (the unsupported boom's modes in the heel's tangent frame) or, for a boom pinned at its heel, "
                 "pinned-pinned (the chord frame)");
  sub.add_option("--stress-recovery", options.stress_recovery,
                 "How the modal boom's stresses are recovered: acceleration (mode acceleration, the default: the static "
                 "response to every load the modes leave unbalanced added) or displacement (mode displacement: from the "
                 "modes' own deflection)");
}

scene::BoomChoice boom_choice(const ModelOptions& options, scene::BoomChoice base) {
  if (options.static_modes && options.no_static_modes) throw BadOption("--static-modes and --no-static-modes exclude each other");
  study::BoomRequest request;
  request.kind = options.boom;
  request.elements = options.elements;
  request.modes = options.modes;
  if (options.static_modes) request.static_modes = true;
  if (options.no_static_modes) request.static_modes = false;
  request.stiffening = options.stiffening;
  request.mode_set = options.mode_set;
  request.stress_recovery = options.stress_recovery;
  try {
    return study::boom_choice(request, base);
  } catch (const study::SettingError& error) {  // name where the element count came from
    if (error.setting() == study::Setting::elements && !options.elements)
      throw BadOption(fmt::format("boom.elements = {}: {}", base.elements, error.problem()));
    throw BadOption(option_message(error));
  }
}

std::string_view option_name(study::Setting setting) {
  switch (setting) {
    case study::Setting::relative_tolerance: return "--rtol";
    case study::Setting::absolute_tolerance: return "--atol";
    case study::Setting::duration: return "--duration";
    case study::Setting::fixed_step: return "--step";
    case study::Setting::max_order: return "--max-order";
    case study::Setting::reference_elements: return "--reference-elements";
    case study::Setting::reference_tolerance: return "--reference-rtol";
    case study::Setting::reference_bound: return "--reference-bound";
    case study::Setting::reference_levels: return "--reference-levels";
    case study::Setting::tolerance: return "--tolerance";
    case study::Setting::jobs: return "--jobs";
    case study::Setting::elements: return "--elements";
    case study::Setting::boom_model: return "--boom";
    case study::Setting::modes: return "--modes";
    case study::Setting::stiffening: return "--stiffening";
    case study::Setting::mode_set: return "--mode-set";
    case study::Setting::stress_recovery: return "--stress-recovery";
    case study::Setting::integrator: return "--integrator";
    case study::Setting::formulation: return "--formulation";
    case study::Setting::solver: return "--solver";
    case study::Setting::step_limit: return "--max-steps";
    case study::Setting::wall_clock_limit: return "--max-wall-time";
    case study::Setting::step_floor: return "--min-step";
    case study::Setting::wave_periods: return "--periods";
    case study::Setting::wave_frequencies: return "--frequencies";
    case study::Setting::outputs: return "--outputs";
    case study::Setting::eigen_solver: return "--solver";
    case study::Setting::boundary: return "--boundary";
    case study::Setting::grid: return "--quick/--medium/--full";
    case study::Setting::headings: return "--heading";
  }
  return "?";
}

std::string option_message(const study::SettingError& error) {
  return fmt::format("{} {}: {}", option_name(error.setting()), error.value(), error.problem());
}

solve::Integrator integrator_choice(const DynamicsOptions& options) {
  try {
    return study::integrator_choice(options.integrator, options.formulation, options.solver);
  } catch (const study::SettingError& error) {
    throw BadOption(option_message(error));
  }
}

multibody::RunSettings integrator_settings(const DynamicsOptions& options, const scene::Scene& scene) {
  study::DynamicsRequest request{integrator_choice(options), options.rtol, options.atol, options.duration, options.step,
                                 options.max_order};
  request.work.max_steps = options.max_steps;
  if (options.max_wall_time) request.work.max_wall_seconds = *options.max_wall_time;
  request.work.min_step = options.min_step;
  try {
    multibody::RunSettings settings = study::integrator_settings(scene, request);
    settings.progress = stderr_is_terminal();
    return settings;
  } catch (const study::SettingError& error) {
    throw BadOption(option_message(error));
  }
}

std::string option_names(solve::Adjustment adjustment) {
  switch (adjustment) {
    case solve::Adjustment::tolerances: return "--rtol/--atol";
    case solve::Adjustment::fixed_step: return "--step";
    case solve::Adjustment::step_limit: return "--max-steps";
    case solve::Adjustment::wall_clock_limit: return "--max-wall-time";
    case solve::Adjustment::step_floor: return "--min-step";
    case solve::Adjustment::solver: return "--solver";
    case solve::Adjustment::formulation: return "--formulation";
    case solve::Adjustment::stiffening: return "--stiffening";
    case solve::Adjustment::model_size: return "--elements/--modes";
    case solve::Adjustment::scene_values: return "the scene file";
  }
  return "?";
}

std::string remedy_options(solve::FailureKind kind) {
  std::string text;
  for (const solve::Adjustment adjustment : solve::adjustments(kind)) {
    text += (text.empty() ? "options: " : ", ") + option_names(adjustment);
  }
  return text;
}

// "1%" → 0.01, "0.01" → 0.01; throws BadOption when not a number in (0, 1).
double parse_tolerance(std::string text) {
  const std::string given = text;
  double scale = 1.0;
  if (!text.empty() && text.back() == '%') {
    text.pop_back();
    scale = 0.01;
  }
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  value *= scale;
  if (used == 0 || used != text.size() || !(value > 0.0 && value < 1.0)) {
    throw BadOption(fmt::format("--tolerance {}: not a tolerance (valid range (0, 1), or a percentage like 1%)", given));
  }
  return value;
}

void add_tolerance_option(CLI::App& sub, std::string& tolerance, const std::string& what) {
  sub.add_option("--tolerance", tolerance,
                 "Tolerance of the verdict: " + what + ", in (0, 1) or as a percentage (default 1%)")
      ->capture_default_str();
}

std::optional<scene::Stiffening> stiffening_option(const std::string& stiffening) {
  if (stiffening.empty()) return std::nullopt;
  const auto parsed = scene::parse_stiffening(stiffening);
  if (!parsed) {
    throw BadOption(fmt::format("--stiffening {}: unknown stiffening; choose one of none, static, centrifugal, both", stiffening));
  }
  return parsed;
}

void add_set_option(CLI::App& sub, std::vector<std::string>& values) {
  sub.add_option("--set", values,
                 "Set a scene key for this run, as if the scene file said so: KEY=VALUE with the value as in the file, "
                 "a unit where it has one (--set boom.angle=\"55 deg\" --set cargo.mass=\"2400 t\"); repeatable; "
                 "checked like the file (docs/scenes.md)")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

scene::SceneOverrides scene_overrides(const std::vector<std::string>& values) {
  scene::SceneOverrides overrides;
  for (const std::string& value : values) overrides.values.push_back(scene::parse_override(value, overrides.origin));
  return overrides;
}

std::string overrides_text(const scene::Scene& scene) {
  std::string text;
  for (const std::string& value : scene.overrides) text += "\n--set " + value;
  return text;
}

std::optional<scene::Scene> load_scene(const std::string& path, const std::vector<std::string>& set,
                                       const std::string& command, bool needs_base) {
  try {
    scene::Scene scene = scene::load_scene(path, scene_overrides(set));
    for (const std::string& warning : scene.warnings) fmt::print(stderr, "warning: {}\n", warning);
    if (needs_base && !scene.has_base()) {
      bad_input(command, fmt::format("{}: not a crane scene: it has neither a [hull] section (a crane needs [hull], [cargo], "
                                     "[wire] and boom.angle/root_x/root_y) nor a [hub]; `ffrf modes` analyses a single beam",
                                     path));
      return std::nullopt;
    }
    return scene;
  } catch (const scene::SceneError& error) {
    for (const auto& problem : error.problems()) fmt::print(stderr, "{}\n", scene::format_problem(problem));
    bad_input(command, fmt::format("{}: {} problem{} in the scene", path, error.problems().size(),
                                   error.problems().size() == 1 ? "" : "s"));
    return std::nullopt;
  }
}

int bad_input(const std::string& command, const std::string& message) {
  fmt::print(stderr, "ffrf {}: error: {}\n", command, message);
  return exit_bad_input;
}

int scene_error(const std::string& command, const std::string& path, const scene::SceneError& error, const std::string& what) {
  for (const auto& problem : error.problems()) fmt::print(stderr, "{}\n", scene::format_problem(problem));
  return bad_input(command, fmt::format("{}: the scene cannot make {}", path, what));
}

int solver_failure(const std::string& command, const std::string& what, const solve::SolverFailure& failure,
                   const std::string& out) {
  const std::string options = remedy_options(failure.kind());
  fmt::print(stderr, "ffrf {}: solver failure ({}): {}{}\n", command, what, failure.what(),
             options.empty() ? "" : " (" + options + ")");
  if (!out.empty()) fmt::print(stderr, "ffrf {}: nothing written to {}\n", command, out);
  return exit_solver_failure;
}

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) != 0; }

void progress(const std::string& command, const std::string& what, bool newline) {
  if (!stderr_is_terminal()) return;
  if (what.empty()) {
    fmt::print(stderr, "\r\033[K");  // clears the line
  } else {
    fmt::print(stderr, "\r\033[Kffrf {}: {}{}", command, what, newline ? "\n" : "");
  }
  std::fflush(stderr);
}

}  // namespace ffrf::app
