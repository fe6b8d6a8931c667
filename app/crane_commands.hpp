// The crane-dynamics subcommands `ffrf run`, `ffrf compare` and `ffrf sweep` (same contract as commands.hpp),
// and the exit code they add: 3 when a solver (KINSOL, CVODE, IDA) failed.
#pragma once

#include "app/commands.hpp"

namespace ffrf::app {

inline constexpr int exit_solver_failure = 3;

Command add_run_command(CLI::App& parent);      // command_run.cpp
Command add_compare_command(CLI::App& parent);  // command_compare.cpp
Command add_sweep_command(CLI::App& parent);    // command_sweep.cpp

}  // namespace ffrf::app
