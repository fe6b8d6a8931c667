// Killing a run loses no finished task, and the rerun computes only the rest. The toy farm runs
// alone or under mpirun; once the journal holds some tasks, its whole process group gets SIGKILL,
// SIGTERM or SIGINT (a Ctrl-C). Independent facts: the killed run wrote no table; its processes
// end (the journal lock frees); the rerun computes exactly the tasks missing from the journal
// (counted from the journal's own lines and the program's trace); its table is byte-identical to
// an uninterrupted run. A lost rank ends an MPI job non-zero with the journal intact.
#include <gtest/gtest.h>
#include <fmt/format.h>
#include <signal.h>

#include <algorithm>
#include <thread>

#include "distributed/journal_format.hpp"
#include "scratch_directory.hpp"
#include "toy_farm_runs.hpp"

namespace ffrf::test {
namespace {

constexpr std::size_t tasks = 48;
const std::vector<std::string> workload = {"--tasks", std::to_string(tasks), "--samples", "2000000"};
// In the run that is killed every task lasts at least 250 ms (sleeping; the results and the journal's
// settings do not depend on it), so the 42 or more tasks left when the signal is sent take ≥ 3.5 s
// on three compute threads: longer than Open MPI's mpirun takes to end its ranks after SIGTERM
// (about 2.3 s measured here), so the run cannot finish first, however idle the machine.
const std::vector<std::string> slow_tasks = {"--task-floor-ms", "250"};

std::vector<std::string> with(std::vector<std::string> arguments, const std::vector<std::string>& more) {
  arguments.insert(arguments.end(), more.begin(), more.end());
  return arguments;
}

std::string uninterrupted_table(const ScratchDirectory& dir) {
  const RunOutput run = run_toy_farm(Launcher{"alone", 0}, with({"--out", (dir / "reference").string()}, workload), dir.path());
  EXPECT_EQ(run.end.exit_code, 0) << run.err;
  return read_text(dir / "reference/table.csv");
}

struct Kill {
  Launcher launcher;
  int signal;
  const char* name;
};

void PrintTo(const Kill& kill, std::ostream* os) { *os << kill.name; }

class KillAndResume : public ::testing::TestWithParam<Kill> {};

TEST_P(KillAndResume, TheRerunComputesOnlyTheMissingTasksAndGivesTheSameTable) {
  const Kill kill = GetParam();
  if (kill.launcher.processes > 0 && !mpirun_unavailable_reason().empty()) GTEST_SKIP() << mpirun_unavailable_reason();
  ScratchDirectory dir;
  const std::filesystem::path out = dir / "out";
  const std::filesystem::path journal = out / "journal.tsv";
  {
    ChildSpec spec = toy_farm(kill.launcher, with(with({"--out", out.string()}, workload), slow_tasks));
    spec.stdout_file = dir / "killed.out";
    spec.stderr_file = dir / "killed.err";
    ChildProcess child(spec);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while (journaled_indices(journal).size() < 6 && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_LT(journaled_indices(journal).size(), tasks) << "the run finished before it could be killed";
    child.signal_group(kill.signal);
    ASSERT_TRUE(child.wait(std::chrono::seconds(30))) << "the launcher outlived " << kill.name;
  }
  ASSERT_TRUE(wait_until_unlocked(journal, std::chrono::seconds(30))) << "a process of the killed run still holds the journal";
  EXPECT_FALSE(std::filesystem::exists(out / "table.csv")) << "a table was written before every task was done";
  const std::vector<std::size_t> journaled = journaled_indices(journal);
  ASSERT_GE(journaled.size(), 6u);
  ASSERT_LT(journaled.size(), tasks);

  const RunOutput rerun = run_toy_farm(kill.launcher, with({"--out", out.string(), "--trace", (dir / "trace").string()}, workload),
                                       dir.path());
  ASSERT_EQ(rerun.end.exit_code, 0) << rerun.err;
  const std::size_t missing = tasks - journaled.size();
  EXPECT_NE(rerun.out.find(fmt::format("computed {} resumed {} failed 0", missing, journaled.size())), std::string::npos)
      << rerun.out;
  const std::map<std::size_t, int> recomputed = traced_computations(dir / "trace");
  EXPECT_EQ(recomputed.size(), missing);
  for (const auto& [index, count] : recomputed) {
    EXPECT_EQ(count, 1) << "task " << index;
    EXPECT_EQ(std::count(journaled.begin(), journaled.end(), index), 0) << "task " << index << " was journaled yet recomputed";
  }
  EXPECT_EQ(read_text(out / "table.csv"), uninterrupted_table(dir));
}

INSTANTIATE_TEST_SUITE_P(
    Engine, KillAndResume,
    ::testing::Values(Kill{Launcher{"alone", 0}, SIGKILL, "alone_SIGKILL"}, Kill{Launcher{"alone", 0}, SIGTERM, "alone_SIGTERM"},
                      Kill{Launcher{"alone", 0}, SIGINT, "alone_SIGINT"}, Kill{Launcher{"np2", 2}, SIGKILL, "mpirun_np2_SIGKILL"},
                      Kill{Launcher{"np3", 3}, SIGTERM, "mpirun_np3_SIGTERM"}, Kill{Launcher{"np2", 2}, SIGINT, "mpirun_np2_SIGINT"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(LostRank, TheJobEndsNonZeroAndItsJournalResumes) {
  if (!mpirun_unavailable_reason().empty()) GTEST_SKIP() << mpirun_unavailable_reason();
  ScratchDirectory dir;
  const std::filesystem::path out = dir / "out";
  const RunOutput lost = run_toy_farm(Launcher{"np3", 3}, with({"--out", out.string(), "--lose-rank-after", "8"}, workload), dir.path());
  EXPECT_FALSE(lost.end.exited && lost.end.exit_code == 0) << "a job with a lost rank ended as a success";
  EXPECT_NE(lost.err.find("signal 9"), std::string::npos) << "the launcher names the lost rank's end:\n" << lost.err;
  ASSERT_TRUE(wait_until_unlocked(out / "journal.tsv", std::chrono::seconds(30)));
  EXPECT_FALSE(std::filesystem::exists(out / "table.csv"));
  const distributed::JournalContents contents = distributed::read_journal(out / "journal.tsv");  // intact
  EXPECT_LT(contents.outcomes.size(), tasks);

  const RunOutput rerun = run_toy_farm(Launcher{"np2", 2}, with({"--out", out.string()}, workload), dir.path());
  ASSERT_EQ(rerun.end.exit_code, 0) << rerun.err;
  EXPECT_NE(rerun.out.find(fmt::format("resumed {}", contents.outcomes.size())), std::string::npos) << rerun.out;
  EXPECT_EQ(read_text(out / "table.csv"), uninterrupted_table(dir));
}

}  // namespace
}  // namespace ffrf::test
