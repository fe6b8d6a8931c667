// Child processes for the engine's tests (see child_process.hpp).
#include "child_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace ffrf::test {

ChildProcess::ChildProcess(const ChildSpec& spec) {
  std::vector<char*> argv;
  for (const std::string& arg : spec.argv) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    ::setpgid(0, 0);
    const int input = ::open("/dev/null", O_RDONLY);
    ::dup2(input, STDIN_FILENO);
    const int out = ::open(spec.stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    const int err = spec.stderr_descriptor >= 0 ? spec.stderr_descriptor
                                                : ::open(spec.stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(err, STDERR_FILENO);
    for (const auto& [name, value] : spec.environment) ::setenv(name.c_str(), value.c_str(), 1);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  ::setpgid(pid_, pid_);  // also from the parent: no race with an early signal_group
}

ChildProcess::~ChildProcess() {
  if (reaped_) return;
  signal_group(SIGKILL);
  int status = 0;
  ::waitpid(pid_, &status, 0);
}

void ChildProcess::signal_group(int signal) const { ::kill(-pid_, signal); }

std::optional<ChildEnd> ChildProcess::wait(std::chrono::milliseconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (true) {
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      reaped_ = true;
      ChildEnd end;
      end.exited = WIFEXITED(status);
      end.exit_code = end.exited ? WEXITSTATUS(status) : -1;
      end.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      return end;
    }
    if (std::chrono::steady_clock::now() > deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

RunOutput run_child(ChildSpec spec, const std::filesystem::path& scratch, std::chrono::milliseconds limit) {
  if (spec.stdout_file.empty()) spec.stdout_file = scratch / "stdout.txt";
  if (spec.stderr_file.empty()) spec.stderr_file = scratch / "stderr.txt";
  RunOutput output;
  {
    ChildProcess child(spec);
    const std::optional<ChildEnd> end = child.wait(limit);
    if (end) {
      output.end = *end;
    } else {
      output.end.signal = SIGKILL;  // the destructor kills it
    }
  }
  output.out = read_text(spec.stdout_file);
  if (spec.stderr_descriptor < 0) output.err = read_text(spec.stderr_file);
  return output;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace ffrf::test
