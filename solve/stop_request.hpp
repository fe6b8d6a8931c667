// A request to stop, from outside the computation (SIGINT, SIGTERM): the signal handler records it
// (async-signal-safe), and the integrators' output loops (before each sample) and the output
// directory's commit (report/output_directory.hpp) end the work by throwing Interrupted. Interrupted
// is deliberately not a std::exception: no `catch (const std::exception&)` that turns a failure
// into a result (a sweep row, a stability cell) can swallow it; it unwinds to the program's main.
#pragma once

namespace ffrf::solve {

// Records the signal (the first one wins); safe to call from a signal handler.
void request_stop(int signal) noexcept;
// The signal that asked to stop, 0 when none.
int stop_signal() noexcept;
inline bool stop_requested() noexcept { return stop_signal() != 0; }
// Forgets the request once the stop is handled, for a front end that lives on (the Python module).
void clear_stop_request() noexcept;

struct Interrupted {
  int signal;  // SIGINT, SIGTERM
};

// Throws Interrupted when a stop was requested.
void throw_if_stop_requested();

}  // namespace ffrf::solve
