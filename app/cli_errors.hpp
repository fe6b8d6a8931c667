// What the program says when CLI11 refuses a command line, so that a typo is named with its fix: an unknown option gets
// a "did you mean" — first an option of the command that takes the value given (`--model modal` →
// `--boom modal`), else the nearest option name by edit distance — an unknown command the nearest
// command, a value refused by an app/option_checks.hpp check "--option VALUE: ... (valid range ...)",
// and an empty value ("--out ''") is named. CLI11 itself has no suggestions.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace ffrf::app {

struct CommandLineError {
  std::string command;  // the subcommand's name, empty when none was recognized
  std::string message;  // without the "ffrf CMD: error: " prefix
};

// The error for a command line CLI11 refused with `error` (not --help or --version).
CommandLineError explain_parse_error(const CLI::App& app, const CLI::ParseError& error,
                                     const std::vector<std::string>& arguments);

// After a successful parse: an option or argument given an empty value, named; nothing when none.
std::optional<std::string> empty_value(const CLI::App& command);

}  // namespace ffrf::app
