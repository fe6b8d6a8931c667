// SIGINT and SIGTERM, so that Ctrl-C leaves no partial output: the handler records the request (solve::request_stop) and wakes
// a watcher thread through a pipe — both async-signal-safe. The computation stops at its next output
// time (solve::Interrupted unwinds: staging directories are removed on the way) and main returns
// 128 + the signal (130, 143). When it has not stopped within stop_grace_seconds, or a second
// signal comes, the watcher removes the uncommitted outputs itself and exits at once with that code.
#pragma once

namespace ffrf::app {

inline constexpr double stop_grace_seconds = 3.0;

void install_stop_handlers();
// The conventional exit code of a process stopped by `signal`: 128 + signal.
int stopped_exit_code(int signal);
// "SIGINT", "SIGTERM".
const char* signal_name(int signal);

}  // namespace ffrf::app
