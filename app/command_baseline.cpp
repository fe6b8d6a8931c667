// `ffrf baseline record SCENE --out FILE` and `ffrf baseline check SCENE FILE`: regression baselines
// for users (docs/baselines.md). record runs one model (study::record_baseline, the one
// run pipeline) and writes the baseline file (report/baseline_file.hpp); check runs the baseline's
// model again — or the one the options name, reporting the difference — and judges every recorded
// quantity against its tolerance (study::check_baseline). Exit 0 when every quantity passes, 4 on a
// regression, 2 for bad input (scene, baseline file, options), 3 when a solver fails.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "modal/eigen_solver.hpp"
#include "report/baseline_file.hpp"
#include "report/baseline_report.hpp"
#include "study/baseline_check.hpp"

namespace ffrf::app {
namespace {

namespace fs = std::filesystem;

struct RecordOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  ModelOptions model;
  DynamicsOptions dynamics;
  std::string outputs;  // empty: the judged outputs
  std::string out;
};

struct CheckOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  std::string baseline;
  ModelOptions model;  // given: overrides the baseline's
  std::string integrator;
  std::optional<double> duration;
  std::optional<double> step;
  std::optional<int> max_order;
  std::optional<double> integrator_rtol, integrator_atol;
  std::optional<double> relative, absolute, frequency;
  std::vector<std::string> tolerances;  // NAME=RELATIVE
  bool json = false;
};

// "cargo_heave,wire_tension_N" → the columns; throws BadOption naming an unknown one.
std::vector<std::string> parse_outputs(const std::string& text) {
  std::vector<std::string> outputs;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) {
    if (!study::output_column(item)) {
      throw BadOption(fmt::format("--outputs {}: unknown output '{}'; choose from {} (or a judged channel: cargo_heave, "
                                  "cargo_pitch, crane_heave, crane_pitch, wire_tension, tip_deflection, joint_moment)",
                                  text, item, study::output_columns()));
    }
    outputs.push_back(item);
  }
  if (outputs.empty()) throw BadOption(fmt::format("--outputs {}: no output given; choose from {}", text, study::output_columns()));
  return outputs;
}

double tolerance_value(const std::string& option, const std::string& text, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw BadOption(fmt::format("{} {}: not a tolerance (valid range [0, inf))", option, text));
  }
  return value;
}

// An integrator tolerance of the check's run, in (0, 1); throws BadOption.
std::optional<double> integrator_tolerance(const char* option, std::optional<double> value) {
  if (value && !(*value > 0.0 && *value < 1.0)) {
    throw BadOption(fmt::format("{} {}: not a valid tolerance (valid range (0, 1))", option, *value));
  }
  return value;
}

// The check's tolerances from the options; throws BadOption.
study::BaselineTolerances tolerances(const CheckOptions& options) {
  study::BaselineTolerances t;
  if (options.relative) t.relative = tolerance_value("--rtol", fmt::format("{}", *options.relative), *options.relative);
  if (options.absolute) t.absolute = tolerance_value("--atol", fmt::format("{}", *options.absolute), *options.absolute);
  if (options.frequency) {
    t.frequency = tolerance_value("--frequency-rtol", fmt::format("{}", *options.frequency), *options.frequency);
  }
  for (const std::string& item : options.tolerances) {
    const std::size_t equals = item.find('=');
    std::size_t used = 0;
    double value = NAN;
    if (equals != std::string::npos) {
      try {
        value = std::stod(item.substr(equals + 1), &used);
      } catch (const std::exception&) {
        used = 0;
      }
    }
    if (equals == std::string::npos || equals == 0 || used == 0 || used != item.size() - equals - 1) {
      throw BadOption(fmt::format("--tolerance {}: not NAME=RELATIVE (e.g. wire_tension_N=1e-3, frequencies=1e-8)", item));
    }
    t.per_name[item.substr(0, equals)] = tolerance_value("--tolerance", item, value);
  }
  return t;
}

int record(const RecordOptions& options) {
  const std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "baseline record", true);
  if (!scene) return exit_bad_input;
  study::BaselineRequest request;
  report::BaselineFile file;
  try {
    request.choice = boom_choice(options.model, default_boom_choice(*scene));
    request.settings = integrator_settings(options.dynamics, *scene);
    if (!options.outputs.empty()) request.outputs = parse_outputs(options.outputs);
    const fs::path directory = fs::absolute(options.out).parent_path();
    if (!fs::is_directory(directory)) {
      throw BadOption(fmt::format("--out {}: the directory {} does not exist", options.out, directory.string()));
    }
    file.provenance = report::baseline_provenance(options.scene, scene->name);
  } catch (const BadOption& error) {
    return bad_input("baseline record", error.what());
  } catch (const report::BaselineFileError& error) {
    return bad_input("baseline record", error.what());
  }
  try {
    progress("baseline record", "running " + request.choice.label());
    file.baseline = study::record_baseline(*scene, request);
    progress("baseline record", "");
  } catch (const scene::SceneError& error) {
    return scene_error("baseline record", options.scene, error, "this crane");
  } catch (const solve::SolverFailure& failure) {
    return solver_failure("baseline record", std::string(solve::to_string(failure.kind())), failure, options.out);
  }
  try {
    report::write_baseline(options.out, report::baseline_json(file));
  } catch (const std::runtime_error& error) {
    fmt::print(stderr, "ffrf baseline record: error: {}\n", error.what());
    return exit_failure;
  }
  fmt::print("{}\nwrote {}\n", report::baseline_record_text(file), options.out);
  return exit_ok;
}

int check(const CheckOptions& options) {
  const std::optional<scene::Scene> scene = load_scene(options.scene, options.set, "baseline check", true);
  if (!scene) return exit_bad_input;
  report::BaselineFile baseline;
  study::BaselineTolerances limits;
  scene::BoomChoice choice;
  multibody::RunSettings settings;
  std::string scene_hash;
  try {
    baseline = report::read_baseline(options.baseline);
    scene_hash = report::scene_file_hash(options.scene);
    limits = tolerances(options);
    study::validate(limits, baseline.baseline);
    const study::BaselineModel& model = baseline.baseline.model;
    choice = boom_choice(options.model, model.choice);
    DynamicsOptions dynamics;
    dynamics.integrator = options.integrator.empty() ? std::string(solve::to_string(model.integrator)) : options.integrator;
    dynamics.rtol = integrator_tolerance("--integrator-rtol", options.integrator_rtol).value_or(model.relative_tolerance);
    dynamics.atol = integrator_tolerance("--integrator-atol", options.integrator_atol).value_or(model.absolute_tolerance);
    dynamics.duration = options.duration.value_or(model.duration);
    dynamics.step = options.step.value_or(model.fixed_step);
    dynamics.max_order = options.max_order.value_or(model.max_order);
    settings = integrator_settings(dynamics, *scene);
  } catch (const report::BaselineFileError& error) {
    return bad_input("baseline check", error.what());
  } catch (const BadOption& error) {
    return bad_input("baseline check", error.what());
  } catch (const study::ToleranceError& error) {  // a --tolerance that names nothing in the baseline
    return bad_input("baseline check", fmt::format("--tolerance {}={}: {}: {}", error.name(), error.value(), options.baseline,
                                                   error.problem()));
  }
  study::BaselineCheck result;
  try {
    progress("baseline check", "running " + choice.label());
    result = study::check_baseline(*scene, baseline.baseline, choice, settings, limits);
    progress("baseline check", "");
  } catch (const scene::SceneError& error) {
    return scene_error("baseline check", options.scene, error, "this crane");
  } catch (const solve::SolverFailure& failure) {
    return solver_failure("baseline check", std::string(solve::to_string(failure.kind())), failure, "");
  }
  const report::BaselineCheckContext context{options.baseline, &baseline, options.scene, scene_hash};
  fmt::print("{}", options.json ? report::baseline_check_json(context, result) : report::baseline_check_text(context, result));
  std::fflush(stdout);
  if (!result.passed()) {
    fmt::print(stderr, "ffrf baseline check: regression: {} of {} quantities outside their tolerances (exit {})\n",
               result.failures(), result.deviations.size(), exit_regression);
    return exit_regression;
  }
  return exit_ok;
}

}  // namespace

Command add_baseline_command(CLI::App& parent) {
  auto record_options = std::make_shared<RecordOptions>();
  auto check_options = std::make_shared<CheckOptions>();
  CLI::App* sub = parent.add_subcommand(
      "baseline", "Regression baselines: record a model's frequencies and responses, check a later run against them");
  sub->require_subcommand(1);

  CLI::App* rec = sub->add_subcommand("record", "Run one model and write its baseline file (docs/baselines.md)");
  rec->add_option("scene", record_options->scene, "Scene file (TOML) of a crane or a hub")->required();
  add_set_option(*rec, record_options->set);
  add_model_options(*rec, record_options->model);
  add_dynamics_options(*rec, record_options->dynamics);
  rec->add_option("--outputs", record_options->outputs,
                  "Comma-separated outputs to record: time-series columns (wire_tension_N, tip_axial_m, ...) or judged "
                  "channels (wire_tension, ...); default: the judged outputs of compare and recommend");
  rec->add_option("--out", record_options->out, "The baseline file to write (JSON)")->required();

  CLI::App* chk = sub->add_subcommand(
      "check", "Run the baseline's model again and judge every recorded quantity; exit 4 on a regression");
  chk->add_option("scene", check_options->scene, "Scene file (TOML)")->required();
  add_set_option(*chk, check_options->set);
  chk->add_option("baseline", check_options->baseline, "Baseline file written by `ffrf baseline record`")->required();
  add_model_options(*chk, check_options->model);
  chk->add_option("--integrator", check_options->integrator,
                  "Integrator " + solve::integrator_choices() + " (default: the baseline's)");
  chk->add_option("--duration", check_options->duration, "Simulated time [s] (default: the baseline's)");
  chk->add_option("--step", check_options->step, "Fixed step [s] (default: the baseline's)");
  chk->add_option("--max-order", check_options->max_order, "Largest BDF order, 1-5 (default: the baseline's)");
  chk->add_option("--integrator-rtol", check_options->integrator_rtol,
                  "Relative tolerance of the integrator (default: the baseline's; a tighter one shows the global error "
                  "of the baseline's run)");
  chk->add_option("--integrator-atol", check_options->integrator_atol, "Absolute tolerance of the integrator (default: the baseline's)");
  chk->add_option("--rtol", check_options->relative,
                  fmt::format("Relative tolerance of every response statistic and history, in units of the channel's "
                              "standard deviation (default: {:g} x the baseline's integrator rtol)",
                              study::response_tolerance_factor));
  chk->add_option("--atol", check_options->absolute, "Absolute tolerance of every response, in its channel's unit (default 0)");
  chk->add_option("--frequency-rtol", check_options->frequency,
                  fmt::format("Relative tolerance of the boom frequencies (default {:g})", study::default_frequency_tolerance));
  chk->add_option("--tolerance", check_options->tolerances,
                  "Relative tolerance of one channel, of 'frequencies' or of 'wire_amplification': NAME=VALUE (repeatable)");
  chk->add_flag("--json", check_options->json, "Print the check as JSON on stdout");

  return {sub, [rec, chk, record_options, check_options] {
            if (rec->parsed()) return record(*record_options);
            if (chk->parsed()) return check(*check_options);
            return exit_failure;
          }};
}

}  // namespace ffrf::app
