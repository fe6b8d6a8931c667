// The toy farm as users run it: alone (one compute thread, or several), under `mpirun -np 2` and
// `mpirun --oversubscribe -np 3`. Independent facts: the tables are byte-identical to the
// single-thread run (timing.csv, the timing, is apart); every task is computed exactly once (the
// program's own trace files); rank 0 computes too; a failing task is a row and the others
// complete; a rank that built another task list is named; a mismatched journal is refused; a torn last line is ignored and its task recomputed;
// shard jobs merge into the whole table; progress only on a terminal (skipped where no pseudo-terminal
// can be opened). Kills: test_farm_kill_resume.
#include <gtest/gtest.h>
#include <fmt/format.h>
#include <pty.h>
#include <unistd.h>

#include <fstream>

#include "../pseudo_terminal.hpp"
#include "scratch_directory.hpp"
#include "toy_farm_runs.hpp"

namespace ffrf::test {
namespace {

const Launcher alone{"alone", 0};

// The reference table: one process, one compute thread.
std::string reference_table(const ScratchDirectory& dir, const std::vector<std::string>& arguments) {
  std::vector<std::string> args = {"--out", (dir / "reference").string(), "--threads", "1"};
  args.insert(args.end(), arguments.begin(), arguments.end());
  const RunOutput run = run_toy_farm(alone, args, dir.path());
  EXPECT_EQ(run.end.exit_code, 0) << run.err;
  return read_text(dir / "reference/table.csv");
}

struct FarmSetup {
  Launcher launcher;
  int threads;  // on rank 0
};

void PrintTo(const FarmSetup& setup, std::ostream* os) { *os << setup.launcher.name << " threads " << setup.threads; }

class ProcessCount : public ::testing::TestWithParam<FarmSetup> {};

TEST_P(ProcessCount, TheTableIsByteIdenticalAndEveryTaskIsComputedOnce) {
  const FarmSetup setup = GetParam();
  if (setup.launcher.processes > 0 && !mpirun_unavailable_reason().empty()) GTEST_SKIP() << mpirun_unavailable_reason();
  ScratchDirectory dir;
  const std::string reference = reference_table(dir, {"--tasks", "24"});
  const RunOutput run = run_toy_farm(setup.launcher,
                                     {"--out", (dir / "out").string(), "--tasks", "24", "--threads",
                                      std::to_string(setup.threads), "--trace", (dir / "trace").string()},
                                     dir.path());
  ASSERT_EQ(run.end.exit_code, 0) << run.out << run.err;
  EXPECT_EQ(read_text(dir / "out/table.csv"), reference);
  EXPECT_NE(reference.find("\n23,pi-23-"), std::string::npos);  // the table has all 24 rows
  const std::map<std::size_t, int> computed = traced_computations(dir / "trace");
  ASSERT_EQ(computed.size(), 24u);
  for (const auto& [index, count] : computed) EXPECT_EQ(count, 1) << "task " << index;
  EXPECT_NE(run.out.find("tasks 24 computed 24 resumed 0 failed 0"), std::string::npos) << run.out;
  const std::set<int> ranks = ranks_in_timing(dir / "out/timing.csv");
  if (setup.launcher.processes > 0) {
    EXPECT_NE(run.out.find(fmt::format("engine: MPI, {} processes", setup.launcher.processes)), std::string::npos) << run.out;
    for (int rank = 0; rank < setup.launcher.processes; ++rank) EXPECT_TRUE(ranks.count(rank)) << "rank " << rank << " computed nothing";
  } else {
    EXPECT_NE(run.out.find("engine: serial (no launcher)"), std::string::npos) << run.out;
    EXPECT_EQ(ranks, std::set<int>{0});
  }
}

INSTANTIATE_TEST_SUITE_P(Engine, ProcessCount,
                         ::testing::Values(FarmSetup{alone, 3}, FarmSetup{Launcher{"mpirun_np2", 2}, 1},
                                           FarmSetup{Launcher{"mpirun_np3", 3}, 1}),
                         [](const auto& param_info) { return param_info.param.launcher.name + "_threads" + std::to_string(param_info.param.threads); });

class Failures : public ::testing::TestWithParam<Launcher> {};

TEST_P(Failures, AFailingTaskIsARowAndTheOthersComplete) {
  if (GetParam().processes > 0 && !mpirun_unavailable_reason().empty()) GTEST_SKIP() << mpirun_unavailable_reason();
  ScratchDirectory dir;
  const RunOutput run = run_toy_farm(GetParam(), {"--out", (dir / "out").string(), "--tasks", "20", "--fail-every", "5"}, dir.path());
  ASSERT_EQ(run.end.exit_code, 0) << run.err;
  const std::string table = read_text(dir / "out/table.csv");
  for (int i : {4, 9, 14, 19}) {
    EXPECT_NE(table.find(fmt::format("\n{},pi-{}-samples-", i, i)), std::string::npos);
    EXPECT_NE(table.find(fmt::format(",failed,,,,\"toy failure: task {} rejects its samples\"\n", i)), std::string::npos) << table;
  }
  EXPECT_NE(run.out.find("failed 4 "), std::string::npos) << run.out;
  EXPECT_EQ(table, reference_table(dir, {"--tasks", "20", "--fail-every", "5"}));
}

INSTANTIATE_TEST_SUITE_P(Engine, Failures, ::testing::Values(alone, Launcher{"mpirun_np3", 3}),
                         [](const auto& param_info) { return param_info.param.name; });

TEST(Ranks, ARankWithAnotherTaskListIsNamedAndNothingIsComputed) {
  if (!mpirun_unavailable_reason().empty()) GTEST_SKIP() << mpirun_unavailable_reason();
  ScratchDirectory dir;
  const RunOutput run = run_toy_farm(Launcher{"np3", 3},
                                     {"--out", (dir / "out").string(), "--tasks", "10", "--skew-rank", "2", "--trace",
                                      (dir / "trace").string()},
                                     dir.path());
  EXPECT_EQ(run.end.exit_code, 3) << run.out << run.err;
  EXPECT_NE(run.err.find("engine error: rank 2 built another farm than rank 0"), std::string::npos) << run.err;
  EXPECT_TRUE(traced_computations(dir / "trace").empty());
  EXPECT_FALSE(std::filesystem::exists(dir / "out/table.csv"));
}

TEST(Journal, AJournalOfAnotherTaskListOrSettingsIsRefusedWithTheReason) {
  ScratchDirectory dir;
  const std::string out = (dir / "out").string();
  ASSERT_EQ(run_toy_farm(alone, {"--out", out, "--tasks", "10"}, dir.path()).end.exit_code, 0);
  const std::string table = read_text(dir / "out/table.csv");
  const RunOutput more_tasks = run_toy_farm(alone, {"--out", out, "--tasks", "12"}, dir.path());
  EXPECT_EQ(more_tasks.end.exit_code, 2);
  EXPECT_NE(more_tasks.err.find("made for another task list (10 tasks"), std::string::npos) << more_tasks.err;
  EXPECT_NE(more_tasks.err.find("journal.tsv"), std::string::npos) << more_tasks.err;
  const RunOutput other_settings = run_toy_farm(alone, {"--out", out, "--tasks", "10", "--samples", "999"}, dir.path());
  EXPECT_EQ(other_settings.end.exit_code, 2);
  EXPECT_NE(other_settings.err.find("made with other settings"), std::string::npos) << other_settings.err;
  EXPECT_EQ(read_text(dir / "out/table.csv"), table);  // nothing mixed in, nothing overwritten
}

TEST(Journal, ATornLastLineIsIgnoredAndItsTaskRecomputed) {
  ScratchDirectory dir;
  const std::string out = (dir / "out").string();
  ASSERT_EQ(run_toy_farm(alone, {"--out", out, "--tasks", "16"}, dir.path()).end.exit_code, 0);
  const std::string table = read_text(dir / "out/table.csv");
  const std::filesystem::path journal = dir / "out/journal.tsv";
  const std::string text = read_text(journal);
  std::ofstream(journal, std::ios::binary | std::ios::trunc) << text.substr(0, text.size() - 9);
  std::filesystem::remove(dir / "out/table.csv");
  const RunOutput rerun = run_toy_farm(alone, {"--out", out, "--tasks", "16", "--trace", (dir / "trace").string()}, dir.path());
  ASSERT_EQ(rerun.end.exit_code, 0) << rerun.err;
  EXPECT_NE(rerun.out.find("computed 1 resumed 15 failed 0 root_threads"), std::string::npos) << rerun.out;
  EXPECT_NE(rerun.out.find("torn_tail_repaired true"), std::string::npos) << rerun.out;
  EXPECT_EQ(traced_computations(dir / "trace").size(), 1u);
  EXPECT_EQ(read_text(dir / "out/table.csv"), table);
  EXPECT_EQ(journaled_indices(journal).size(), 16u);
}

TEST(Shards, ShardJobsMergeIntoTheWholeTable) {
  ScratchDirectory dir;
  const std::string whole = reference_table(dir, {"--tasks", "19"});
  for (int i = 0; i < 3; ++i) {
    const RunOutput run = run_toy_farm(
        alone, {"--out", (dir / ("shard" + std::to_string(i))).string(), "--tasks", "19", "--shard", fmt::format("{}/3", i)},
        dir.path());
    ASSERT_EQ(run.end.exit_code, 0) << run.err;
  }
  const RunOutput merged = run_toy_farm(
      alone, {"--out", (dir / "merged").string(), "--merge", (dir / "shard0").string(), (dir / "shard1").string(),
              (dir / "shard2").string()},
      dir.path());
  ASSERT_EQ(merged.end.exit_code, 0) << merged.err;
  EXPECT_EQ(read_text(dir / "merged/table.csv"), whole);
  const RunOutput gap = run_toy_farm(
      alone, {"--out", (dir / "gap").string(), "--merge", (dir / "shard0").string(), (dir / "shard2").string()}, dir.path());
  EXPECT_EQ(gap.end.exit_code, 2);
  EXPECT_NE(gap.err.find("6 of the 19 tasks are in none of the 2 journals (tasks 1, 4, 7"), std::string::npos) << gap.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "gap/table.csv"));
}

TEST(Terminal, QuietWhenStderrIsNotATerminal) {
  ScratchDirectory dir;
  const RunOutput run = run_toy_farm(alone, {"--out", (dir / "out").string(), "--tasks", "8"}, dir.path());
  ASSERT_EQ(run.end.exit_code, 0);
  EXPECT_EQ(run.err, "");
}

TEST(Terminal, ProgressIsDrawnInPlaceOnATerminal) {
  if (const std::string reason = ffrf::test::pseudo_terminal_unavailable_reason(); !reason.empty()) GTEST_SKIP() << reason;
  ScratchDirectory dir;
  int master = -1, slave = -1;
  ASSERT_EQ(::openpty(&master, &slave, nullptr, nullptr, nullptr), 0);
  ChildSpec spec = toy_farm(alone, {"--out", (dir / "out").string(), "--tasks", "8"});
  spec.stdout_file = dir / "stdout.txt";
  spec.stderr_descriptor = slave;
  const RunOutput run = run_child(spec, dir.path(), std::chrono::minutes(1));
  ::close(slave);
  std::string drawn;
  char buffer[4096];
  for (ssize_t n; (n = ::read(master, buffer, sizeof buffer)) > 0;) drawn.append(buffer, static_cast<std::size_t>(n));
  ::close(master);
  ASSERT_EQ(run.end.exit_code, 0);
  EXPECT_NE(drawn.find("\r\033[Ktoy farm: 0/8 done, 0 failed, elapsed 0s, ETA ?"), std::string::npos) << drawn;
  EXPECT_NE(drawn.find("toy farm: 8/8 done, 0 failed, elapsed"), std::string::npos) << drawn;
}

}  // namespace
}  // namespace ffrf::test
