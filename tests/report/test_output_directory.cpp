// Output directories (report/output_directory.hpp) when the file system refuses: the error names
// the user's path, never the staging path, and the operating system's reason; nothing is left
// beside the target; a stop request (SIGINT/SIGTERM) keeps commit() from posing an interrupted run
// as complete.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "solve/stop_request.hpp"
#include "report/output_directory.hpp"

namespace {

using namespace ffrf;
namespace fs = std::filesystem;

class Scratch {
 public:
  Scratch() : root_(fs::temp_directory_path() / ("ffrf-output-test-" + std::to_string(::getpid()) + "-" +
                                                 ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  ~Scratch() { fs::remove_all(root_); }
  const fs::path& root() const { return root_; }
  // Everything in the scratch directory, as "name name ..." (to show what was left).
  std::string listing() const {
    std::string names;
    for (const auto& entry : fs::directory_iterator(root_)) names += entry.path().filename().string() + " ";
    return names;
  }

 private:
  fs::path root_;
};

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const report::OutputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no OutputError";
  return {};
}

TEST(OutputDirectory, NoSpaceLeftNamesTheUsersPathAndTheReason) {
  // /dev/full answers every write with ENOSPC: a staged file linked to it is a full disk.
  Scratch scratch;
  const fs::path target = scratch.root() / "out";
  {
    report::StagedDirectory out(target, "summary.json");
    fs::create_symlink("/dev/full", out.staging() / "timeseries.csv");
    const std::string message = error_of([&] { out.write("timeseries.csv", std::string(1 << 16, 'x')); });
    EXPECT_NE(message.find((target / "timeseries.csv").string()), std::string::npos) << message;
    EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
    EXPECT_EQ(message.find(".partial-"), std::string::npos) << "the staging path is not the user's: " << message;
  }
  EXPECT_EQ(scratch.listing(), "") << "nothing beside the target";
}

TEST(OutputDirectory, ParentThatIsAFileNamesTheReason) {
  Scratch scratch;
  std::ofstream(scratch.root() / "file") << "x";
  const fs::path target = scratch.root() / "file" / "sub" / "out";
  const std::string message = error_of([&] { report::StagedDirectory out(target, "summary.json"); });
  EXPECT_NE(message.find(target.string()), std::string::npos) << message;
  EXPECT_NE(message.find("Not a directory"), std::string::npos) << message;
  EXPECT_EQ(scratch.listing(), "file ");
}

TEST(OutputDirectory, TargetThatIsAFileIsRefused) {
  Scratch scratch;
  std::ofstream(scratch.root() / "out") << "x";
  const std::string message = error_of([&] { report::StagedDirectory out(scratch.root() / "out", "summary.json"); });
  EXPECT_NE(message.find("exists and is not a directory"), std::string::npos) << message;
  EXPECT_EQ(scratch.listing(), "out ");
}

TEST(OutputDirectory, EmptyPathIsRefused) {
  EXPECT_NE(error_of([] { report::StagedDirectory out("", "summary.json"); }).find("an empty path"), std::string::npos);
}

TEST(OutputDirectory, CreatedParentsGoAgainWithoutCommitAndStayWithIt) {
  Scratch scratch;
  const fs::path target = scratch.root() / "a" / "b" / "out";
  { report::StagedDirectory out(target, "summary.json"); }
  EXPECT_EQ(scratch.listing(), "") << "the parents a/b it created are removed";
  report::check_output_directory(target, "summary.json");
  EXPECT_EQ(scratch.listing(), "") << "the check leaves nothing either";
  {
    report::StagedDirectory out(target, "summary.json");
    out.write("summary.json", "{}\n");
    out.commit();
  }
  EXPECT_TRUE(fs::exists(target / "summary.json"));
}

TEST(OutputDirectory, UncommittedOutputsCanBeRemovedAtOnce) {
  Scratch scratch;
  report::StagedDirectory out(scratch.root() / "new" / "out", "summary.json");
  out.write("data.csv", "1\n");
  report::remove_uncommitted_outputs();  // what the signal watcher does before exiting
  EXPECT_EQ(scratch.listing(), "");
}

TEST(OutputDirectoryDeathTest, StopRequestKeepsAnInterruptedRunFromCommitting) {
  // In a child process: the stop request is process-wide and cannot be withdrawn.
  Scratch scratch;
  const fs::path target = scratch.root() / "out";
  EXPECT_EXIT(
      {
        int signal = 0;
        try {
          report::StagedDirectory out(target, "summary.json");
          out.write("summary.json", "{}\n");
          solve::request_stop(2);
          out.commit();
        } catch (const solve::Interrupted& stop) {
          signal = stop.signal;
        }
        std::exit(signal == 2 && !fs::exists(target) ? 42 : 1);
      },
      ::testing::ExitedWithCode(42), "");
  EXPECT_EQ(scratch.listing(), "") << "the staging directory went with the unwinding";
}

}  // namespace
