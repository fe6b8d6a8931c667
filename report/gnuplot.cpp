// Running gnuplot scripts: gnuplot runs without a shell, its standard input from /dev/null, so a
// charting command started from a terminal never waits for a key press.
#include "report/gnuplot.hpp"

#include <array>
#include <cerrno>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <mutex>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace ffrf::report {
namespace {

// Runs `program args…` in `directory` (empty: the current one) without a shell, its standard input
// from /dev/null (never the user's terminal: a pager there would wait for a key press that never
// comes), standard output and error captured together. Returns the exit status (−1 when it could
// not be started or was killed by a signal).
int run_captured(const std::vector<std::string>& argv, const std::filesystem::path& directory,
                 std::string& output) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return -1;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);
  if (!directory.empty()) posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (spawned != 0) {
    ::close(pipe_fds[0]);
    return -1;
  }
  std::array<char, 4096> buffer{};
  ssize_t n = 0;
  while ((n = ::read(pipe_fds[0], buffer.data(), buffer.size())) != 0) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    output.append(buffer.data(), static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

std::string png_terminal() {
  static std::mutex mutex;
  static std::string found;  // empty until gnuplot answered once
  const std::lock_guard lock(mutex);
  if (!found.empty()) return found;
  // GPVAL_TERMINALS is one line: no pager (`set terminal` pages its list on a terminal).
  std::string terminals;
  if (run_captured({"gnuplot", "-e", "print GPVAL_TERMINALS"}, {}, terminals) != 0) {
    throw std::runtime_error("gnuplot is needed for the charts of --out but could not be run "
                             "(install it: apt-get install gnuplot-nox)");
  }
  found = terminals.find("pngcairo") != std::string::npos ? "pngcairo" : "png";
  return found;
}

void run_gnuplot(const std::filesystem::path& directory, const std::string& script) {
  std::string output;
  if (run_captured({"gnuplot", script}, directory, output) != 0) throw std::runtime_error(fmt::format("gnuplot {} failed: {}", script, output));
}

void draw_chart(const StagedDirectory& out, const std::string& name, const std::string& script) {
  out.write(name + ".gp", script);
  const std::string png = name + ".png";
  try {
    run_gnuplot(out.staging(), name + ".gp");
    std::error_code error;
    if (std::filesystem::file_size(out.staging() / png, error) > 0 && !error) {
      out.record_chart({png, ChartRecord::Status::drawn, ""});
      return;
    }
    throw std::runtime_error(fmt::format("gnuplot {}.gp ran but wrote no {}", name, png));
  } catch (const std::runtime_error& failure) {
    std::error_code ignored;
    std::filesystem::remove(out.staging() / png, ignored);  // never a truncated chart posing as one
    std::string message = failure.what();
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    out.record_chart({png, ChartRecord::Status::failed, message});
  }
}

void leave_out_chart(const StagedDirectory& out, const std::string& name, const std::string& reason) {
  out.record_chart({name + ".png", ChartRecord::Status::left_out, reason});
}

std::string gnuplot_quoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

std::string gnuplot_lines(const std::string& first, const std::string& second) {
  std::string q = "\"";
  for (char c : first + (second.empty() ? "" : "\n" + second)) {
    if (c == '"' || c == '\\') q += '\\';
    q += c == '\n' ? std::string("\\n") : std::string(1, c);
  }
  return q + "\"";
}

}  // namespace ffrf::report
