// `ffrf sweep` moved onto the distributed engine: the engine's rows equal the rows of the
// threaded sweep it replaced (study::sweep, the second method) apart from the timing column, for the
// whole grid and for a shard; a rerun on the same journal computes nothing and gives the same rows.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "distributed/session.hpp"
#include "report/sweep_csv.hpp"
#include "study/sweep.hpp"
#include "../study/study_test_support.hpp"

namespace ffrf::study {
namespace sweep_engine_test {

// The CSV line without its timing field (wall_s, the last but one; radiation is the last).
std::string without_timing(const std::string& line) {
  const std::size_t last = line.rfind(',');
  const std::size_t timing = line.rfind(',', last - 1);
  return line.substr(0, timing) + line.substr(last);
}

std::vector<std::string> threaded_rows(const scene::Scene& scene, const SweepRequest& request) {
  std::vector<std::string> rows;
  for (const SweepResult& r : sweep(scene, request).results) rows.push_back(without_timing(report::sweep_csv_line(r)));
  return rows;
}

std::vector<std::string> engine_rows(const scene::Scene& scene, const SweepRequest& request, const std::filesystem::path& dir,
                                     std::size_t* computed = nullptr) {
  distributed::Session serial(distributed::LaunchInfo{});
  distributed::FarmOptions farm;
  farm.output_directory = dir;
  farm.settings = "test";
  farm.threads = 2;
  farm.progress_on_terminal = false;
  const SweepOnEngine result = sweep_on_engine(serial, scene, request, farm, [](const SweepResult& r) { return report::sweep_csv_line(r); });
  if (computed) *computed = result.farm.computed;
  std::vector<std::string> rows;
  for (const std::string& line : result.records) rows.push_back(without_timing(line));
  return rows;
}

class SweepEngine : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("ffrf-sweep-engine-" + std::to_string(::getpid()) + "-" +
                                                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

SweepRequest short_quick_sweep() {
  SweepRequest request;
  request.grid = SweepGrid::quick;
  request.duration = 25.0;
  request.reference.max_levels = 2;
  request.jobs = 2;
  return request;
}

TEST_F(SweepEngine, RowsEqualTheThreadedSweepAndARerunResumesThemAll) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const SweepRequest request = short_quick_sweep();
  const std::vector<std::string> threaded = threaded_rows(scene, request);
  ASSERT_EQ(threaded.size(), sweep_grid(SweepGrid::quick).size());
  std::size_t computed = 0;
  EXPECT_EQ(engine_rows(scene, request, dir_, &computed), threaded);
  EXPECT_EQ(computed, threaded.size());
  EXPECT_EQ(engine_rows(scene, request, dir_, &computed), threaded);  // resumed from the journal
  EXPECT_EQ(computed, 0u);
}

TEST_F(SweepEngine, AShardEqualsTheThreadedShard) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  SweepRequest request = short_quick_sweep();
  request.shard = distributed::Shard{1, 3};
  const std::vector<std::string> threaded = threaded_rows(scene, request);
  EXPECT_EQ(engine_rows(scene, request, dir_), threaded);
  EXPECT_EQ(threaded.size(), 7u);  // ids 1, 4, ..., 19 of the 21
}

}  // namespace sweep_engine_test
}  // namespace ffrf::study
