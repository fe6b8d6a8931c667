// The git commit ffrf was built from ("unknown" outside a git checkout, "-dirty" with uncommitted
// changes), written at build time by report/git_commit.cmake: the provenance of baselines and reports,
// and `ffrf --version`.
#pragma once

namespace ffrf::report {

const char* built_git_commit();  // defined in the generated git_commit.cpp

}  // namespace ffrf::report
