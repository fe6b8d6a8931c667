// docs/user-guide.md's "Errors, exit codes and failure names" cannot drift from the code: every
// failure kind of solve/failure.hpp has its row with a remedy, every exit code of app/commands.hpp
// and of a stop by SIGINT/SIGTERM (128 + signal) has its row, and every status word of the sweep and
// recommend studies is named.
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include "app/commands.hpp"
#include "solve/failure.hpp"
#include "study/recommend.hpp"
#include "study/sweep.hpp"

namespace {

using namespace ffrf;

std::string errors_section() {
  std::ifstream in(FFRF_SOURCE_DIR "/docs/user-guide.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string guide = text.str();
  const auto start = guide.find("\n## Errors, exit codes and failure names\n");
  if (start == std::string::npos) return {};
  const auto end = guide.find("\n## ", start + 1);
  return guide.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The cells of the table row that starts with `first` (empty when there is none).
std::vector<std::string> row(const std::string& section, const std::string& first) {
  std::istringstream lines(section);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| " + first + " |", 0) != 0) continue;
    std::vector<std::string> cells;
    std::size_t start = 1;
    for (std::size_t bar = line.find(" |", start); bar != std::string::npos; bar = line.find(" |", start)) {
      cells.push_back(line.substr(start + 1, bar - start - 1));
      start = bar + 2;
    }
    return cells;
  }
  return {};
}

TEST(UserGuideErrors, EveryFailureKindHasItsRowAndRemedy) {
  const std::string section = errors_section();
  ASSERT_FALSE(section.empty()) << "docs/user-guide.md lacks the errors section";
  for (const solve::FailureKind kind : solve::all_failure_kinds) {
    const std::string name(solve::to_string(kind));
    const auto cells = row(section, "`" + name + "`");
    ASSERT_EQ(cells.size(), 4u) << "no row for the failure kind '" << name << "'";
    EXPECT_TRUE(cells[1] == "yes" || cells[1] == "no") << name;
    EXPECT_GT(cells[2].size(), 10u) << name << ": what happened";
    EXPECT_GT(cells[3].size(), 10u) << name << ": the remedy";
  }
}

TEST(UserGuideErrors, EveryExitCodeHasItsRow) {
  const std::string section = errors_section();
  for (const int code : {app::exit_ok, app::exit_failure, app::exit_bad_input, app::exit_solver_failure, 128 + SIGINT,
                         128 + SIGTERM}) {
    EXPECT_EQ(row(section, std::to_string(code)).size(), 2u) << "no row for exit code " << code;
  }
}

TEST(UserGuideErrors, StudyStatusWordsAreNamed) {
  const std::string section = errors_section();
  for (const study::RunStatus status : {study::RunStatus::ok, study::RunStatus::failed, study::RunStatus::skipped}) {
    EXPECT_NE(section.find("`" + std::string(study::to_string(status)) + "`"), std::string::npos);
  }
  for (const study::CandidateStatus status :
       {study::CandidateStatus::pruned, study::CandidateStatus::not_run, study::CandidateStatus::passed,
        study::CandidateStatus::failed, study::CandidateStatus::solver_failure}) {
    EXPECT_NE(section.find("`" + std::string(study::to_string(status)) + "`"), std::string::npos)
        << study::to_string(status);
  }
}

}  // namespace
