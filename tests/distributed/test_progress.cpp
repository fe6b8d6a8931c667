// The progress line: durations, the estimate of the time left (rate of this run's completions
// times the tasks left, with and without work inside unfinished tasks, checked by hand), and quiet
// unless on a terminal.
#include <gtest/gtest.h>

#include "distributed/progress.hpp"

namespace ffrf::distributed {
namespace {

TEST(Progress, DurationsReadAsATimer) {
  EXPECT_EQ(format_duration(0.4), "0s");
  EXPECT_EQ(format_duration(42.0), "42s");
  EXPECT_EQ(format_duration(185.0), "3m05s");
  EXPECT_EQ(format_duration(2 * 3600 + 7 * 60 + 30), "2h07m");
}

TEST(Progress, TheEstimateIsThisRunsRateTimesTheTasksLeft) {
  // 10 tasks, 2 resumed, 4 computed in 8 s: 2 s a task, 4 left -> 8 s.
  const ProgressCounts counts{10, 2, 4, 1};
  ASSERT_TRUE(estimated_seconds_left(counts, 8.0));
  EXPECT_DOUBLE_EQ(*estimated_seconds_left(counts, 8.0), 8.0);
  EXPECT_FALSE(estimated_seconds_left(ProgressCounts{10, 2, 0, 0}, 3.0));  // no rate yet
  EXPECT_EQ(progress_line("sweep", counts, 8.0), "sweep: 6/10 done (2 resumed), 1 failed, elapsed 8s, ETA 8s");
  EXPECT_EQ(progress_line("sweep", ProgressCounts{5, 0, 0, 0}, 1.0), "sweep: 0/5 done, 0 failed, elapsed 1s, ETA ?");
}

TEST(Progress, WorkInsideTasksGivesAnEstimateBeforeTheFirstFinishes) {
  // 8 tasks, none finished; after 30 s two workers are each 1/4 through a task: 0.5 tasks done in
  // 30 s is 60 s a task, and 7.5 tasks' worth is left -> 450 s.
  const ProgressCounts none{8, 0, 0, 0};
  ASSERT_TRUE(estimated_seconds_left(none, 30.0, 0.5));
  EXPECT_DOUBLE_EQ(*estimated_seconds_left(none, 30.0, 0.5), 450.0);
  EXPECT_EQ(progress_line("records", none, 30.0, "", 0.5), "records: 0/8 done, 0 failed, elapsed 30s, ETA 7m30s");
  // With finished tasks the work in progress adds to them: 2 done + 1.0 in progress in 30 s -> 10 s
  // a task, 6 − 1 = 5 tasks' worth left -> 50 s.
  EXPECT_DOUBLE_EQ(*estimated_seconds_left(ProgressCounts{8, 0, 2, 0}, 30.0, 1.0), 50.0);
}

TEST(Progress, QuietUnlessOnATerminal) {
  testing::internal::CaptureStderr();
  {
    ProgressMeter quiet("farm", ProgressCounts{3, 0, 0, 0}, false);
    quiet.finished(true);
    quiet.close();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  testing::internal::CaptureStderr();
  {
    ProgressMeter shown("farm", ProgressCounts{3, 0, 0, 0}, true);
    shown.finished(false);
  }
  const std::string drawn = testing::internal::GetCapturedStderr();
  EXPECT_NE(drawn.find("\r\033[Kfarm: 0/3 done"), std::string::npos) << drawn;
  EXPECT_NE(drawn.find("farm: 1/3 done, 1 failed"), std::string::npos) << drawn;  // the last redraw is forced
  EXPECT_EQ(drawn.back(), '\n');
}

}  // namespace
}  // namespace ffrf::distributed
