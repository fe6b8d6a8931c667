// gnuplot scripts and their execution: gnuplot runs without a shell, its standard input from
// /dev/null, so a charting command started from a terminal never waits for a key press.
#include "app/gnuplot.hpp"

#include <array>
#include <cerrno>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace ffrf::app {
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

std::string header(const std::string& terminal, const std::string& output, const std::string& title) {
  return fmt::format(
      "# Drawn by `ffrf modes --out`; restyle and rerun with `gnuplot {0}.gp` in this directory.\n"
      "set terminal {1} size 1000,650 font ',11'\n"
      "set output '{0}.png'\n"
      "set datafile separator ','\n"
      "set key outside right\n"
      "set grid\n"
      "set title '{2}' noenhanced\n",
      output, terminal, title);
}

}  // namespace

std::string png_terminal() {
  // GPVAL_TERMINALS is one line: no pager (`set terminal` pages its list on a terminal).
  std::string terminals;
  if (run_captured({"gnuplot", "-e", "print GPVAL_TERMINALS"}, {}, terminals) != 0) {
    throw std::runtime_error("gnuplot is needed for the charts of --out but could not be run "
                             "(install it: apt-get install gnuplot-nox)");
  }
  return terminals.find("pngcairo") != std::string::npos ? "pngcairo" : "png";
}

void run_gnuplot(const std::filesystem::path& directory, const std::string& script) {
  std::string output;
  if (run_captured({"gnuplot", script}, directory, output) != 0) throw std::runtime_error(fmt::format("gnuplot {} failed: {}", script, output));
}

std::string mode_shapes_script(const ModesResult& r, const std::string& terminal) {
  std::string script = header(terminal, "mode_shapes",
                              fmt::format("Bending mode shapes, {} elements, {}", r.mesh.element_count,
                                          fem::to_string(r.boundary)));
  script += "set xlabel 'x [m]'\nset ylabel 'transverse v [1/sqrt(kg)] (M-normalized)'\nset xzeroaxis\n";
  std::vector<std::string> curves;
  for (std::size_t j = 0; j < r.modes.size(); ++j) {
    if (r.modes[j].kind != fem::ModeKind::bending) continue;
    // mode_shapes_sampled.csv: column 1 is x_m, then v of mode j+1 in column j + 2.
    curves.push_back(fmt::format("'mode_shapes_sampled.csv' skip 1 using 1:{} with lines lw 2 title 'bending {} ({:.4g} Hz)'",
                                 j + 2, r.modes[j].order, r.modes[j].angular_frequency / (2 * 3.14159265358979323846)));
  }
  if (curves.empty()) {
    script += "set label 'no bending modes among the computed modes' at graph 0.5, 0.5 center\n"
              "plot [0:1] [-1:1] NaN notitle\n";
  } else {
    script += "plot " + fmt::format("{}", fmt::join(curves, ", \\\n     ")) + "\n";
  }
  return script;
}

std::string convergence_script(const ModesResult& r, const std::string& terminal) {
  std::string script = header(terminal, "frequency_convergence",
                              fmt::format("Bending frequency error vs elements, {}, {} solver",
                                          fem::to_string(r.boundary), modal::to_string(r.solver)));
  script +=
      "set logscale xy\n"
      "set format y '10^{%L}'\n"
      "set xlabel 'elements N'\n"
      "set ylabel '|f_{FE} - f_{analytic}| / f_{analytic}'\n"
      "set xtics (2, 4, 8, 16, 32, 64, 128)\n"
      "plot for [k=1:4] 'frequency_convergence.csv' skip 1 using 1:(column(k+2) > 0 ? column(k+2) : NaN) \\\n"
      "       with linespoints pt 7 title sprintf('f%d', k), \\\n"
      "     'frequency_convergence.csv' skip 1 using 1:(column(3) > 0 ? 1e-3 * (4.0 / $1)**4 : NaN) \\\n"
      "       with lines dt 2 lc 'gray' title 'slope -4'\n";
  return script;
}

}  // namespace ffrf::app
