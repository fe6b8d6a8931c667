// Long calls with the GIL released, stopped by Ctrl-C (see bindings.hpp). Python runs its signal
// handlers on the main thread only, and only when that thread asks (PyErr_CheckSignals), so the
// work runs on a thread of its own while the calling thread waits for it in short slices, asking
// Python between them. When a handler raises (KeyboardInterrupt), the work is asked to stop the way
// the command line asks on SIGINT (solve::request_stop: the integrators stop at their next output
// time and unwind, farm tasks are abandoned, staging directories are removed), the calling thread
// waits for it to unwind, forgets the request and raises the handler's exception. Other threads
// than the main one have no signals to ask about: there the call simply waits.
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "python/bindings.hpp"
#include "solve/stop_request.hpp"

namespace ffrf::python {

void run_interruptible(const std::function<void()>& work) {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::exception_ptr failure;
  std::optional<py::error_already_set> interrupt;  // the handler's exception
  {
    py::gil_scoped_release released;
    std::thread worker([&] {
      try {
        work();
      } catch (...) {
        failure = std::current_exception();
      }
      const std::lock_guard lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock lock(mutex);
    while (!done) {
      finished.wait_for(lock, std::chrono::milliseconds(50));
      if (done || interrupt) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire held;
        if (PyErr_CheckSignals() != 0) {
          interrupt.emplace();  // fetches the exception the handler raised
          solve::request_stop(SIGINT);
        }
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (interrupt) {
    solve::clear_stop_request();
    throw *interrupt;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace ffrf::python
