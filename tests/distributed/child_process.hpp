// Test helper: runs a program (the toy farm, alone or under mpirun) as a child in its own process
// group, stdin from /dev/null, stdout and stderr to files (or stderr to a given descriptor, e.g. a
// pseudo-terminal), with extra environment variables; waits for it or signals its whole group.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ffrf::test {

struct ChildSpec {
  std::vector<std::string> argv;
  std::vector<std::pair<std::string, std::string>> environment;  // added to the parent's
  std::filesystem::path stdout_file;
  std::filesystem::path stderr_file;
  int stderr_descriptor = -1;  // used instead of stderr_file when >= 0
};

struct ChildEnd {
  bool exited = false;  // normally, with exit_code
  int exit_code = -1;
  int signal = 0;       // the signal that ended it, when !exited
};

class ChildProcess {
 public:
  explicit ChildProcess(const ChildSpec& spec);
  ~ChildProcess();  // kills the group if still running
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  void signal_group(int signal) const;
  // Waits up to `limit`; std::nullopt when still running then.
  std::optional<ChildEnd> wait(std::chrono::milliseconds limit);

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
};

struct RunOutput {
  ChildEnd end;
  std::string out;
  std::string err;
};

// Runs to the end (killed after `limit`, reported as signal SIGKILL) and reads its output back.
RunOutput run_child(ChildSpec spec, const std::filesystem::path& scratch, std::chrono::milliseconds limit);

std::string read_text(const std::filesystem::path& path);

}  // namespace ffrf::test
