// Compute threads of the process that schedules (rank 0, or the only process of a serial run):
// the scheduler hands them task positions and collects their outcomes; the threads never touch
// MPI, the journal or the outputs (MPI_THREAD_FUNNELED: only the main thread calls MPI).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include "distributed/outcome.hpp"

namespace ffrf::distributed {

class LocalWorkers {
 public:
  LocalWorkers(std::size_t threads, const std::vector<Task>& tasks, const WorkFunction& work, int rank);
  // Lets the tasks in progress finish (their outcomes are dropped), then joins the threads.
  ~LocalWorkers();
  LocalWorkers(const LocalWorkers&) = delete;
  LocalWorkers& operator=(const LocalWorkers&) = delete;

  std::size_t threads() const { return threads_.size(); }
  std::size_t idle() const { return threads_.size() - assigned_; }  // not counting uncollected outcomes
  std::size_t busy() const { return assigned_; }
  void submit(std::size_t position);  // requires idle() > 0
  // The outcomes finished since the last call; waits up to `wait` for one when none is ready.
  std::vector<TaskOutcome> collect(std::chrono::microseconds wait);

 private:
  void serve();
  const std::vector<Task>& tasks_;
  const WorkFunction& work_;
  const int rank_;
  std::size_t assigned_ = 0;  // submitted and not yet collected (scheduler's thread only)
  std::mutex mutex_;
  std::condition_variable task_ready_;
  std::condition_variable outcome_ready_;
  std::deque<std::size_t> queue_;
  std::vector<TaskOutcome> finished_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace ffrf::distributed
