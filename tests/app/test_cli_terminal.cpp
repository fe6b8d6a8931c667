// Every charting command run from an interactive terminal finishes without input (a chart must never hang a user's shell).
// The command runs under a pseudo-terminal (`script`), as a user's shell would start it, with a
// standard input that stays open and never delivers a byte: a child process that inherits the
// terminal and waits for a key press (gnuplot's pager did: "Press return for more:") would block
// until the time limit. Independent check: the process finishes, exits 0, and the charts exist.
// Where no pseudo-terminal can be opened (a container without /dev/pts) or `script` is missing, the
// tests skip and say why.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "../pseudo_terminal.hpp"
#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_terminal_test {

struct TerminalRun {
  bool finished = false;
  int exit_code = -1;
  std::string output;
};

// Runs `ffrf ARGS` inside `script -qec … /dev/null` with stdin an open, silent pipe; kills the
// process group after `limit`.
TerminalRun run_under_pseudo_terminal(const std::string& args, const fs::path& scratch, std::chrono::seconds limit) {
  const fs::path log = scratch / "terminal.txt";
  int silent_input[2];
  if (::pipe(silent_input) != 0) return {};
  const pid_t child = ::fork();
  if (child == 0) {
    ::setpgid(0, 0);
    ::dup2(silent_input[0], STDIN_FILENO);
    ::close(silent_input[0]);
    ::close(silent_input[1]);
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    const std::string command = std::string(FFRF_BINARY_DIR "/app/ffrf ") + args;
    ::execlp("script", "script", "-qec", command.c_str(), "/dev/null", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(silent_input[0]);  // the write end stays open: input never ends, never arrives
  TerminalRun run;
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(child, &status, WNOHANG) == child) {
      run.finished = true;
      run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (!run.finished) {
    ::kill(-child, SIGKILL);
    ::waitpid(child, &status, 0);
  }
  ::close(silent_input[1]);
  run.output = read_text(log);
  return run;
}

struct ChartingCommand {
  const char* name;
  std::string args;   // after the scene; --out DIR is appended
  const char* chart;  // a file the command must have written (relative to --out): a chart where it draws one
};

void PrintTo(const ChartingCommand& c, std::ostream* os) { *os << c.name << ' ' << c.args; }

class CliTerminal : public ::testing::TestWithParam<ChartingCommand> {};

TEST_P(CliTerminal, ChartingCommandFinishesUnderAPseudoTerminalWithoutInput) {
  if (const std::string reason = pseudo_terminal_unavailable_reason(); !reason.empty()) GTEST_SKIP() << reason;
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "the script program (util-linux) is not installed";
  TempDir dir;
  const ChartingCommand& c = GetParam();
  const fs::path out = dir / "out";
  const std::string scene = "'" + source_file("cases/paper_floating_crane.toml") + "'";
  const TerminalRun run = run_under_pseudo_terminal(
      std::string(c.name) + " " + scene + " " + c.args + " --out '" + out.string() + "'", dir.path(),
      std::chrono::seconds(240));
  ASSERT_TRUE(run.finished) << c.name << " waited for terminal input; its output so far:\n" << run.output;
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(out / c.chart)) << c.chart << " missing; output:\n" << run.output;
}

INSTANTIATE_TEST_SUITE_P(
    Commands, CliTerminal,
    ::testing::Values(ChartingCommand{"modes", "--modes 4", "mode_shapes.png"},
                      ChartingCommand{"run", "--elements 2 --duration 3", "cargo_heave.png"},
                      ChartingCommand{"compare", "--duration 25 --reference-levels 2", "cargo_heave.png"},
                      ChartingCommand{"sweep", "--quick --duration 25 --reference-levels 2 --jobs 2",
                                      "accuracy_speed.png"},
                      ChartingCommand{"stability", "--quick", "constraint_drift.png"},
                      ChartingCommand{"recommend", "--duration 25", "recommendation.md"},
                      ChartingCommand{"rao", "--periods 4:20:17 --check-time-domain --check-periods 10", "rao_hull.png"}),
    [](const ::testing::TestParamInfo<ChartingCommand>& p) { return std::string(p.param.name); });

}  // namespace cli_terminal_test
}  // namespace ffrf::test
