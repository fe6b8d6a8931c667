// The version text (see version.hpp); the commit is the one report/git_commit.cmake recorded at build time.
#include "app/version.hpp"

#include <fmt/format.h>

#include "report/git_commit.hpp"

namespace ffrf::app {

std::string version_text() {
  return fmt::format("ffrf {}\ncommit {}\nfeatures: MPI {} (the distributed engine's {} task farm)", FFRF_VERSION,
                     report::built_git_commit(), FFRF_WITH_MPI ? "on" : "off", FFRF_WITH_MPI ? "multi-process" : "serial");
}

}  // namespace ffrf::app
