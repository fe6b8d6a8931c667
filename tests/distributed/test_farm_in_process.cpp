// The farm in one process (serial session, compute threads): every task computed exactly once and
// its outcome equal to calling the work function directly; outcomes in task order whatever the
// threads; failures recorded and the rest completed; a rerun computes only what the journal lacks;
// mismatched journals refused; failed tasks retried on request; costliest tasks handed out first;
// shards merged to the whole. Process counts and kills are in test_farm_processes.cpp.
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <mutex>
#include <stdexcept>

#include "child_process.hpp"
#include "distributed/atomic_file.hpp"
#include "distributed/errors.hpp"
#include "distributed/farm.hpp"
#include "distributed/merge.hpp"
#include "scratch_directory.hpp"

namespace ffrf::distributed {
namespace {

using test::ScratchDirectory;

std::vector<Task> numbered_tasks(std::size_t count) {
  std::vector<std::string> keys;
  for (std::size_t i = 0; i < count; ++i) keys.push_back("case-" + std::to_string(i * 37 % 101));
  return make_tasks(keys);
}

// A deterministic work function with a cost that depends on the task, counting its calls.
class CountingWork {
 public:
  explicit CountingWork(std::size_t tasks, std::size_t fail_every = 0) : calls_(tasks), fail_every_(fail_every) {}
  std::string operator()(const Task& task) {
    ++calls_[task.index];
    {
      std::lock_guard lock(order_mutex_);
      order_.push_back(task.index);
    }
    if (fail_every_ > 0 && (task.index + 1) % fail_every_ == 0) throw std::runtime_error("task " + std::to_string(task.index) + " diverged");
    return expected(task);
  }
  static std::string expected(const Task& task) {
    std::uint64_t x = task_seed(task);
    for (std::size_t k = 0; k < 2000 * (1 + task.index % 4); ++k) x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return task.key + "," + std::to_string(x);
  }
  int calls(std::size_t index) const { return calls_[index]; }
  std::size_t total_calls() const {
    std::size_t total = 0;
    for (const auto& c : calls_) total += static_cast<std::size_t>(c.load());
    return total;
  }
  std::vector<std::size_t> order() const { return order_; }

 private:
  std::vector<std::atomic<int>> calls_;
  std::size_t fail_every_;
  std::mutex order_mutex_;
  std::vector<std::size_t> order_;
};

FarmOptions options_for(const std::filesystem::path& out, int threads) {
  FarmOptions options;
  options.output_directory = out;
  options.study = "in-process test";
  options.settings = "settings v1";
  options.threads = threads;
  options.progress_on_terminal = false;
  return options;
}

FarmResult farm(const std::vector<Task>& tasks, CountingWork& work, const FarmOptions& options) {
  Session serial(LaunchInfo{});
  return run_farm(serial, tasks, [&](const Task& task) { return work(task); }, options);
}

std::vector<std::string> records(const FarmResult& result) {
  std::vector<std::string> out;
  for (const TaskOutcome& o : result.outcomes) out.push_back(std::to_string(o.index) + (o.ok ? o.record : "!" + o.error));
  return out;
}

class FarmThreads : public ::testing::TestWithParam<int> {};

TEST_P(FarmThreads, EveryTaskIsComputedOnceAndEqualsADirectCall) {
  ScratchDirectory dir;
  const std::vector<Task> tasks = numbered_tasks(37);
  CountingWork work(tasks.size());
  const FarmResult result = farm(tasks, work, options_for(dir.path(), GetParam()));
  EXPECT_TRUE(result.root);
  EXPECT_EQ(result.root_threads, static_cast<std::size_t>(GetParam()));
  EXPECT_EQ(result.computed, tasks.size());
  EXPECT_EQ(result.resumed, 0u);
  ASSERT_EQ(result.outcomes.size(), tasks.size());
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    EXPECT_EQ(work.calls(i), 1) << "task " << i;
    EXPECT_EQ(result.outcomes[i].index, i);
    EXPECT_EQ(result.outcomes[i].record, CountingWork::expected(tasks[i]));
  }
}

INSTANTIATE_TEST_SUITE_P(Threads, FarmThreads, ::testing::Values(1, 2, 5));

TEST(Farm, AFailingTaskIsRecordedAndTheOthersComplete) {
  ScratchDirectory dir;
  const std::vector<Task> tasks = numbered_tasks(20);
  CountingWork work(tasks.size(), 6);
  const FarmResult result = farm(tasks, work, options_for(dir.path(), 3));
  EXPECT_EQ(result.failed, 3u);  // tasks 5, 11, 17
  for (const TaskOutcome& o : result.outcomes) {
    const bool should_fail = (o.index + 1) % 6 == 0;
    EXPECT_EQ(o.ok, !should_fail) << o.index;
    if (should_fail) {
      EXPECT_EQ(o.error, "task " + std::to_string(o.index) + " diverged");
    }
  }
}

TEST(Farm, ARerunComputesOnlyWhatTheJournalLacks) {
  ScratchDirectory dir;
  const std::vector<Task> tasks = numbered_tasks(30);
  CountingWork first(tasks.size());
  const FarmResult complete = farm(tasks, first, options_for(dir.path(), 2));
  // Keep the header and the first 11 journaled tasks, as a kill would.
  const auto journal = journal_path(dir.path(), Shard{});
  std::string text = test::read_text(journal);
  std::size_t cut = 0;
  for (int line = 0; line < 12; ++line) cut = text.find('\n', cut) + 1;
  std::ofstream(journal, std::ios::binary | std::ios::trunc) << text.substr(0, cut);

  CountingWork second(tasks.size());
  const FarmResult resumed = farm(tasks, second, options_for(dir.path(), 2));
  EXPECT_EQ(resumed.resumed, 11u);
  EXPECT_EQ(resumed.computed, 19u);
  EXPECT_EQ(second.total_calls(), 19u);
  EXPECT_EQ(records(resumed), records(complete));
  std::size_t from_journal = 0;
  for (const TaskOutcome& o : resumed.outcomes) {
    from_journal += o.resumed ? 1 : 0;
    EXPECT_EQ(second.calls(o.index), o.resumed ? 0 : 1) << o.index;
  }
  EXPECT_EQ(from_journal, 11u);

  CountingWork third(tasks.size());  // everything journaled now: nothing to compute
  EXPECT_EQ(records(farm(tasks, third, options_for(dir.path(), 2))), records(complete));
  EXPECT_EQ(third.total_calls(), 0u);
}

TEST(Farm, AJournalOfOtherTasksOrSettingsIsRefusedAndLeftAsItWas) {
  ScratchDirectory dir;
  CountingWork work(40);
  farm(numbered_tasks(30), work, options_for(dir.path(), 2));
  const std::string before = test::read_text(journal_path(dir.path(), Shard{}));
  EXPECT_THROW(farm(numbered_tasks(31), work, options_for(dir.path(), 2)), JournalError);
  FarmOptions changed = options_for(dir.path(), 2);
  changed.settings = "settings v2";
  EXPECT_THROW(farm(numbered_tasks(30), work, changed), JournalError);
  EXPECT_EQ(test::read_text(journal_path(dir.path(), Shard{})), before);
  EXPECT_EQ(work.total_calls(), 30u);
}

TEST(Farm, AnAbandonedTaskIsNotJournaledAndTheRerunComputesIt) {
  // A stop request (Ctrl-C, a time limit) makes the work function give task 4 up: the farm hands out
  // nothing more, rethrows, and journals neither a result nor a failure for it; the rerun computes
  // every task the journal lacks (task 4 among them) and equals an uninterrupted run.
  ScratchDirectory dir;
  const std::vector<Task> tasks = numbered_tasks(12);
  CountingWork work(tasks.size());
  Session serial(LaunchInfo{});
  const auto stopping = [&](const Task& task) {
    if (task.index == 4) throw TaskAbandoned("interrupted by SIGINT");
    return work(task);
  };
  EXPECT_THROW(run_farm(serial, tasks, stopping, options_for(dir.path(), 1)), TaskAbandoned);
  EXPECT_LT(work.total_calls(), tasks.size());
  EXPECT_EQ(work.calls(4), 0);
  CountingWork again(tasks.size());
  const FarmResult rerun = farm(tasks, again, options_for(dir.path(), 2));
  EXPECT_EQ(again.calls(4), 1);
  EXPECT_EQ(rerun.failed, 0u);
  EXPECT_EQ(rerun.computed + rerun.resumed, tasks.size());
  EXPECT_EQ(rerun.resumed, work.total_calls());
  CountingWork fresh(tasks.size());
  EXPECT_EQ(records(rerun), records(farm(tasks, fresh, options_for(dir / "uninterrupted", 2))));
}

TEST(Farm, FailedTasksAreRetriedOnlyOnRequest) {
  ScratchDirectory dir;
  const std::vector<Task> tasks = numbered_tasks(12);
  CountingWork failing(tasks.size(), 4);  // tasks 3, 7, 11 fail
  EXPECT_EQ(farm(tasks, failing, options_for(dir.path(), 2)).failed, 3u);
  CountingWork again(tasks.size());
  const FarmResult kept = farm(tasks, again, options_for(dir.path(), 2));
  EXPECT_EQ(kept.failed, 3u);
  EXPECT_EQ(again.total_calls(), 0u);
  FarmOptions retry = options_for(dir.path(), 2);
  retry.retry_failed = true;
  CountingWork fixed(tasks.size());
  const FarmResult retried = farm(tasks, fixed, retry);
  EXPECT_EQ(retried.failed, 0u);
  EXPECT_EQ(fixed.total_calls(), 3u);
  EXPECT_EQ(fixed.calls(3) + fixed.calls(7) + fixed.calls(11), 3);
}

TEST(Farm, CostliestTasksAreHandedOutFirst) {
  ScratchDirectory dir;
  std::vector<Task> tasks = numbered_tasks(6);
  const double costs[] = {1.0, 5.0, 2.0, 5.0, 0.0, 3.0};
  for (std::size_t i = 0; i < tasks.size(); ++i) tasks[i].expected_cost = costs[i];
  CountingWork work(tasks.size());
  farm(tasks, work, options_for(dir.path(), 1));
  EXPECT_EQ(work.order(), (std::vector<std::size_t>{1, 3, 5, 2, 0, 4}));  // ties keep task order
}

TEST(Farm, ShardsMergeIntoTheWholeAndGapsOrOverlapsAreNamed) {
  ScratchDirectory dir;
  const std::vector<Task> tasks = numbered_tasks(17);
  CountingWork whole_work(tasks.size());
  const FarmResult whole = farm(tasks, whole_work, options_for(dir / "whole", 2));
  CountingWork shard_work(tasks.size());
  for (std::size_t i = 0; i < 3; ++i) {
    FarmOptions options = options_for(dir / "shards", 1);  // one directory: journals named per shard
    options.shard = Shard{i, 3};
    const FarmResult part = farm(tasks, shard_work, options);
    for (const TaskOutcome& o : part.outcomes) EXPECT_EQ(o.index % 3, i);
  }
  EXPECT_EQ(shard_work.total_calls(), tasks.size());
  const MergedJournals merged = merge_journals({dir / "shards"});
  EXPECT_EQ(merged.journals.size(), 3u);
  ASSERT_EQ(merged.outcomes.size(), tasks.size());
  for (std::size_t i = 0; i < tasks.size(); ++i) EXPECT_EQ(merged.outcomes[i].record, whole.outcomes[i].record);

  const auto shard = [&](std::size_t i) { return journal_path(dir / "shards", Shard{i, 3}); };
  EXPECT_THROW(merge_journals({shard(0), shard(1)}), JournalError);
  try {
    merge_journals({shard(0), shard(1)});
  } catch (const JournalError& error) {
    EXPECT_NE(std::string(error.what()).find("5 of the 17 tasks are in none"), std::string::npos) << error.what();
  }
  try {
    merge_journals({shard(0), shard(1), shard(2), journal_path(dir / "whole", Shard{})});
    ADD_FAILURE() << "overlapping journals merged";
  } catch (const JournalError& error) {
    EXPECT_NE(std::string(error.what()).find("overlapping shards"), std::string::npos) << error.what();
  }
}

TEST(Farm, BadOptionsAreRefusedBeforeAJournalExists) {
  ScratchDirectory dir;
  CountingWork work(3);
  try {
    farm(numbered_tasks(3), work, options_for(dir / "out", -2));
    ADD_FAILURE() << "-2 threads accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("-2 compute threads (valid range [0, inf)"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  EXPECT_EQ(work.total_calls(), 0u);
}

TEST(AtomicFile, ReplacesTheTargetWholeAndLeavesNoTemporary) {
  ScratchDirectory dir;
  write_file_atomically(dir / "table.csv", "old\n");
  write_file_atomically(dir / "table.csv", "new,table\n");
  EXPECT_EQ(test::read_text(dir / "table.csv"), "new,table\n");
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) files += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1u);
}

}  // namespace
}  // namespace ffrf::distributed
