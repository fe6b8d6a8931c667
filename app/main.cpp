// `ffrf`: the floating-crane toolkit's command-line program (docs/architecture.md). One file per
// subcommand; this file wires them to CLI11, installs the SIGINT/SIGTERM handling, and maps every
// error to a message and an exit code (commands.hpp): no bare library message (std::bad_alloc, a
// std::logic_error's text, a filesystem error) reaches the user.
#include <fmt/format.h>

#include <exception>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli_errors.hpp"
#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/stop_signals.hpp"
#include "app/version.hpp"
#include "solve/stop_request.hpp"
#include "report/output_directory.hpp"

namespace {

using namespace ffrf::app;

int interrupted(const std::string& command, int signal) {
  fmt::print(stderr, "ffrf {}: interrupted by {}: stopped; no output was committed\n", command, signal_name(signal));
  return stopped_exit_code(signal);
}

// Runs a parsed command; every exception becomes a named message and its exit code.
int run_command(const Command& command) {
  const std::string name = command.subcommand->get_name();
  try {
    const int code = command.run();
    return ffrf::solve::stop_requested() ? interrupted(name, ffrf::solve::stop_signal()) : code;
  } catch (const ffrf::solve::Interrupted& stop) {
    return interrupted(name, stop.signal);
  } catch (const std::exception& error) {
    // Whatever failed after a stop request (a gnuplot killed by the same Ctrl-C) is the interrupt.
    if (ffrf::solve::stop_requested()) return interrupted(name, ffrf::solve::stop_signal());
    if (const auto* output = dynamic_cast<const ffrf::report::OutputError*>(&error)) return bad_input(name, output->what());
    if (const auto* setting = dynamic_cast<const ffrf::study::SettingError*>(&error)) {
      return bad_input(name, option_message(*setting));
    }
    if (const auto* file = dynamic_cast<const std::filesystem::filesystem_error*>(&error)) {
      return bad_input(name, fmt::format("{}: {}", file->path1().string(), file->code().message()));
    }
    if (dynamic_cast<const std::bad_alloc*>(&error) != nullptr || dynamic_cast<const std::length_error*>(&error) != nullptr) {
      fmt::print(stderr, "ffrf {}: error: out of memory: the computation needs more memory than this machine gives it; "
                         "use fewer elements or modes, a shorter duration or a longer output interval\n", name);
      return exit_failure;
    }
    if (dynamic_cast<const std::logic_error*>(&error) != nullptr && dynamic_cast<const std::invalid_argument*>(&error) == nullptr) {
      fmt::print(stderr, "ffrf {}: internal error (a bug in ffrf; please report it with the command line): {}\n", name,
                 error.what());
      return exit_failure;
    }
    fmt::print(stderr, "ffrf {}: error: {}\n", name, error.what());
    return exit_failure;
  }
}

}  // namespace

int main(int argc, char** argv) {
  install_stop_handlers();
  CLI::App app{"ffrf: a floating crane with an elastic boom; nodal vs modal elastic coordinates"};
  app.set_version_flag("--version", version_text(), "Print the version, the git commit and the build's features (MPI)");
  app.require_subcommand(1);
  std::vector<Command> commands{add_check_command(app), add_modes_command(app), add_run_command(app),
                                add_statics_command(app),
                                add_compare_command(app), add_sweep_command(app),
                                add_stability_command(app),
                                add_recommend_command(app),
                                add_scene_reference_command(app),
                                add_baseline_command(app),
                                add_rao_command(app),
                                add_operability_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {
    return app.exit(success) == 0 ? exit_ok : exit_bad_input;  // --help, --version
  } catch (const CLI::ParseError& error) {
    const CommandLineError explained = explain_parse_error(app, error, std::vector<std::string>(argv + 1, argv + argc));
    fmt::print(stderr, "ffrf{}: error: {}\n", explained.command.empty() ? "" : " " + explained.command, explained.message);
    return exit_bad_input;
  }
  for (const Command& command : commands) {
    if (!command.subcommand->parsed()) continue;
    if (const auto empty = empty_value(*command.subcommand)) return bad_input(command.subcommand->get_name(), *empty);
    return run_command(command);
  }
  return exit_failure;
}
