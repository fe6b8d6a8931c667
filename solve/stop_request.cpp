// The stop request (see stop_request.hpp): one lock-free atomic, safe in a signal handler.
#include "solve/stop_request.hpp"

#include <atomic>

namespace ffrf::solve {
namespace {

std::atomic<int> requested_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the stop request is set from a signal handler");

}  // namespace

void request_stop(int signal) noexcept {
  int none = 0;
  requested_signal.compare_exchange_strong(none, signal);
}

int stop_signal() noexcept { return requested_signal.load(); }

void clear_stop_request() noexcept { requested_signal.store(0); }

void throw_if_stop_requested() {
  if (const int signal = stop_signal(); signal != 0) throw Interrupted{signal};
}

}  // namespace ffrf::solve
