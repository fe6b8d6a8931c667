// The subcommands of the `ffrf` program. Each registers its options on the parent CLI11 app and
// returns the function that runs it after parsing; the function returns the process exit code:
// 0 success, 1 a computation or output failed (recommend: no model met the tolerance), 2 bad input
// (scene file or command line), 3 a solver (KINSOL, CVODE, IDA, ARKODE) failed, 4 a regression
// (`baseline check`: a quantity outside its tolerance).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace ffrf::app {

inline constexpr int exit_ok = 0;
inline constexpr int exit_failure = 1;
inline constexpr int exit_bad_input = 2;
inline constexpr int exit_solver_failure = 3;
inline constexpr int exit_regression = 4;

struct Command {
  CLI::App* subcommand;
  std::function<int()> run;
};

Command add_check_command(CLI::App& parent);            // command_check.cpp
Command add_modes_command(CLI::App& parent);            // command_modes.cpp
Command add_run_command(CLI::App& parent);              // command_run.cpp
Command add_statics_command(CLI::App& parent);          // command_statics.cpp
Command add_compare_command(CLI::App& parent);          // command_compare.cpp
Command add_sweep_command(CLI::App& parent);            // command_sweep.cpp
Command add_stability_command(CLI::App& parent);        // command_stability.cpp
Command add_recommend_command(CLI::App& parent);        // command_recommend.cpp
Command add_scene_reference_command(CLI::App& parent);  // command_scene_reference.cpp
Command add_baseline_command(CLI::App& parent);         // command_baseline.cpp
Command add_rao_command(CLI::App& parent);              // command_rao.cpp
Command add_operability_command(CLI::App& parent);      // command_operability.cpp

}  // namespace ffrf::app
