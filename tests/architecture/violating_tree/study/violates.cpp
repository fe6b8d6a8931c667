// A study file that breaks the layering on purpose (tests/architecture/CMakeLists.txt): it includes
// the report and app layers and CLI11, and prints. Not compiled.
#include <CLI/CLI.hpp>

#include "app/commands.hpp"
#include "report/json.hpp"

void shout() { fmt::print("results belong in a struct\n"); }
