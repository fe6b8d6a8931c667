// `ffrf --version`: the version, the git commit the program was built from (when known) and the
// features of this build (MPI on or off).
#pragma once

#include <string>

namespace ffrf::app {

std::string version_text();

}  // namespace ffrf::app
