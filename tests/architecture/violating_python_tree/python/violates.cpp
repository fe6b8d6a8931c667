// A Python-module file that breaks the layering on purpose (tests/architecture/CMakeLists.txt): it
// includes the program's layer and prints. Not compiled.
#include "app/cli_options.hpp"

void shout() { std::cout << "results are returned, not printed\n"; }
