// The version text (see version.hpp); the commit comes from the header app/build_info.cmake writes.
#include "app/version.hpp"

#include <fmt/format.h>

#include "ffrf_build_info.hpp"

namespace ffrf::app {

std::string version_text() {
  return fmt::format("ffrf {}\ncommit {}\nfeatures: MPI {} (the distributed engine's {} task farm)", FFRF_VERSION,
                     FFRF_GIT_COMMIT, FFRF_WITH_MPI ? "on" : "off", FFRF_WITH_MPI ? "multi-process" : "serial");
}

}  // namespace ffrf::app
