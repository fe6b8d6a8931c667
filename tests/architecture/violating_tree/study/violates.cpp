// A study file that breaks the layering on purpose (tests/architecture/CMakeLists.txt): it includes
// the report and app layers, CLI11 and netCDF, and prints. Not compiled.
#include <CLI/CLI.hpp>
#include <netcdf.h>

#include "app/commands.hpp"
#include "report/json.hpp"

void shout() { fmt::print("results belong in a struct\n"); }
