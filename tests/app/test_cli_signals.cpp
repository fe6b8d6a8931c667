// SIGINT and SIGTERM sent to a running `ffrf run --out DIR` (and `ffrf sweep --out DIR` on the engine's threads):
// the program stops at its next output time, exits with the conventional 128 + signal (130, 143)
// well within the watcher's grace time, says it was interrupted, and leaves nothing beside DIR — no
// DIR, no staging directory — and no old completeness marker inside an existing DIR.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>

#include <chrono>
#include <thread>

#include "cli_harness.hpp"

extern char** environ;

namespace ffrf::test {
namespace cli_signals_test {

using Clock = std::chrono::steady_clock;

struct Child {
  pid_t pid = -1;
  int status = 0;
  double seconds_after_signal = 0.0;
};

// Starts `ffrf args...` with stdin from /dev/null and stdout/stderr into files of `dir`.
pid_t start_ffrf(const std::vector<std::string>& args, const TempDir& dir) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, (dir / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, (dir / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const std::string program = FFRF_BINARY_DIR "/app/ffrf";
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  EXPECT_EQ(::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Waits until `file` contains `text` (the computation has started) or `limit` seconds pass.
bool wait_for(const fs::path& file, const std::string& text, double limit) {
  const auto end = Clock::now() + std::chrono::duration<double>(limit);
  while (Clock::now() < end) {
    if (read_text(file).find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Sends `signal` and waits (at most 20 s, then SIGKILL) for the child to end.
Child interrupt(pid_t pid, int signal) {
  Child child{pid};
  const auto sent = Clock::now();
  ::kill(pid, signal);
  while (::waitpid(pid, &child.status, WNOHANG) == 0) {
    if (Clock::now() - sent > std::chrono::seconds(20)) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &child.status, 0);
      ADD_FAILURE() << "ffrf did not stop within 20 s of the signal";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  child.seconds_after_signal = std::chrono::duration<double>(Clock::now() - sent).count();
  return child;
}

struct SignalCase {
  int signal;
  int exit_code;
  const char* name;
};

class CliSignals : public ::testing::TestWithParam<SignalCase> {};

TEST_P(CliSignals, RunStopsCleanlyAndLeavesNothingBesideOut) {
  const SignalCase& c = GetParam();
  TempDir dir;
  const fs::path parent = dir / "results";
  fs::create_directories(parent);
  const fs::path out = parent / "run out";
  // 40 000 s of the reference crane: minutes of work, interrupted within the first second.
  const pid_t pid = start_ffrf({"run", source_file("cases/paper_floating_crane.toml"), "--duration", "40000", "--out",
                                out.string()},
                               dir);
  ASSERT_TRUE(wait_for(dir / "stdout.txt", "static equilibrium", 20.0)) << read_text(dir / "stderr.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // into the integration
  const Child child = interrupt(pid, c.signal);
  ASSERT_TRUE(WIFEXITED(child.status)) << "ended by a signal instead of exiting";
  EXPECT_EQ(WEXITSTATUS(child.status), c.exit_code);
  EXPECT_LT(child.seconds_after_signal, 2.0) << "stopped at an output time, not by the watcher's forced exit";
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_NE(err.find(std::string("interrupted by ") + c.name + ": stopped"), std::string::npos) << err;
  EXPECT_TRUE(directory_entries(parent).empty()) << "left beside --out: " << directory_entries(parent).front();
}

TEST_P(CliSignals, SweepWithWorkerThreadsStopsCleanly) {
  const SignalCase& c = GetParam();
  TempDir dir;
  const fs::path out = dir / "sweep";
  fs::create_directories(out);
  write_text(out / "report.md", "an older, complete sweep\n");
  const pid_t pid = start_ffrf({"sweep", source_file("cases/paper_floating_crane.toml"), "--quick", "--duration", "300",
                                "--reference-levels", "1", "--jobs", "2", "--out", out.string()},
                               dir);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // the reference and the workers are running
  const Child child = interrupt(pid, c.signal);
  ASSERT_TRUE(WIFEXITED(child.status));
  EXPECT_EQ(WEXITSTATUS(child.status), c.exit_code) << read_text(dir / "stderr.txt");
  EXPECT_LT(child.seconds_after_signal, 2.0);
  EXPECT_NE(read_text(dir / "stderr.txt").find(std::string("ffrf sweep: interrupted by ") + c.name), std::string::npos);
  EXPECT_EQ(directory_entries(dir.path()), (std::vector<std::string>{"stderr.txt", "stdout.txt", "sweep"}));
  // The old marker no longer describes the directory; only the journal of finished configurations
  // (the engine's, kept for a rerun to resume) may be there.
  for (const std::string& entry : directory_entries(out)) EXPECT_EQ(entry, "journal.tsv") << "left in --out: " << entry;
}

INSTANTIATE_TEST_SUITE_P(Signals, CliSignals,
                         ::testing::Values(SignalCase{SIGINT, 130, "SIGINT"}, SignalCase{SIGTERM, 143, "SIGTERM"}),
                         [](const ::testing::TestParamInfo<SignalCase>& signal_info) { return std::string(signal_info.param.name); });

}  // namespace cli_signals_test
}  // namespace ffrf::test
