// `ffrf`: the floating-crane toolkit's command-line program (DESIGN.md §5). One file per
// subcommand; this file only wires them to CLI11 and maps errors to exit codes.
#include <fmt/format.h>

#include <exception>
#include <vector>

#include "app/commands.hpp"

int main(int argc, char** argv) {
  using namespace ffrf::app;
  CLI::App app{"ffrf: a floating crane with an elastic boom; nodal vs modal elastic coordinates"};
  app.require_subcommand(1);
  std::vector<Command> commands{add_check_command(app), add_modes_command(app), add_run_command(app),
                                add_compare_command(app), add_sweep_command(app),
                                add_stability_command(app),
                                add_recommend_command(app),
                                add_scene_reference_command(app),
                                add_baseline_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version exit 0; every other parse error (unknown option, missing argument) is bad input.
    return app.exit(error) == 0 ? exit_ok : exit_bad_input;
  }
  for (const Command& command : commands) {
    if (!command.subcommand->parsed()) continue;
    try {
      return command.run();
    } catch (const std::exception& error) {
      fmt::print(stderr, "ffrf {}: error: {}\n", command.subcommand->get_name(), error.what());
      return exit_failure;
    }
  }
  return exit_failure;
}
