// SIGINT/SIGTERM handling (see stop_signals.hpp).
#include "app/stop_signals.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <thread>

#include "solve/stop_request.hpp"
#include "report/output_directory.hpp"

namespace ffrf::app {
namespace {

int wake_pipe[2] = {-1, -1};

extern "C" void on_stop_signal(int signal) {
  const int saved = errno;
  solve::request_stop(signal);
  const char byte = static_cast<char>(signal);
  [[maybe_unused]] const ssize_t ignored = ::write(wake_pipe[1], &byte, 1);
  errno = saved;
}

// Waits for the first signal, then for the computation to stop within the grace time.
void watch() {
  char byte = 0;
  while (::read(wake_pipe[0], &byte, 1) < 0 && errno == EINTR) {
  }
  pollfd wake{wake_pipe[0], POLLIN, 0};
  const int waited = ::poll(&wake, 1, static_cast<int>(stop_grace_seconds * 1000.0));
  const int signal = solve::stop_signal();
  std::fprintf(stderr, "ffrf: %s: %s; stopping at once, uncommitted output removed\n", signal_name(signal),
               waited > 0 ? "second signal" : "the computation did not reach a stopping point in time");
  report::remove_uncommitted_outputs();
  ::_exit(stopped_exit_code(signal));
}

}  // namespace

void install_stop_handlers() {
  if (::pipe2(wake_pipe, O_CLOEXEC) != 0) return;  // without the pipe: the default action (terminate)
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction previous {};
    // A signal the caller ignores (a background job's SIGINT) stays ignored, as shells expect.
    if (sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    sigaction(signal, &action, nullptr);
  }
  std::thread(watch).detach();
}

int stopped_exit_code(int signal) { return 128 + signal; }

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "signal";
  }
}

}  // namespace ffrf::app
