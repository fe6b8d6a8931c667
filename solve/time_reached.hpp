// How far the run on this thread has come, for a progress display on another thread (a farm's ETA
// inside a long record): while a TimeReachedSink is alive on a thread, every output time an
// integrator reaches on that thread is stored (relaxed) in its atomic. Thread-local, so that the
// integrators' signatures and settings stay as they are and runs on other threads are not seen.
#pragma once

#include <atomic>

namespace ffrf::solve {

class TimeReachedSink {
 public:
  explicit TimeReachedSink(std::atomic<double>* time_reached);  // nullptr: nothing stored
  ~TimeReachedSink();
  TimeReachedSink(const TimeReachedSink&) = delete;
  TimeReachedSink& operator=(const TimeReachedSink&) = delete;

 private:
  std::atomic<double>* previous_;
};

// Stores t in this thread's sink, if any (called by the integrators' output loops).
void store_time_reached(double t) noexcept;

}  // namespace ffrf::solve
