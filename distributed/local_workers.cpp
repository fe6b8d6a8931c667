// Compute threads fed by the scheduler (see local_workers.hpp).
#include "distributed/local_workers.hpp"

namespace ffrf::distributed {

LocalWorkers::LocalWorkers(std::size_t threads, const std::vector<Task>& tasks, const WorkFunction& work, int rank)
    : tasks_(tasks), work_(work), rank_(rank) {
  threads_.reserve(threads);
  for (std::size_t i = 0; i < threads; ++i) threads_.emplace_back([this] { serve(); });
}

LocalWorkers::~LocalWorkers() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  task_ready_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void LocalWorkers::submit(std::size_t position) {
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(position);
  }
  ++assigned_;
  task_ready_.notify_one();
}

std::vector<TaskOutcome> LocalWorkers::collect(std::chrono::microseconds wait) {
  std::unique_lock lock(mutex_);
  if (finished_.empty() && wait.count() > 0) outcome_ready_.wait_for(lock, wait, [this] { return !finished_.empty(); });
  std::vector<TaskOutcome> outcomes;
  outcomes.swap(finished_);
  assigned_ -= outcomes.size();
  return outcomes;
}

void LocalWorkers::serve() {
  while (true) {
    std::size_t position = 0;
    {
      std::unique_lock lock(mutex_);
      task_ready_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      position = queue_.front();
      queue_.pop_front();
    }
    TaskOutcome outcome = run_task(tasks_[position], work_, rank_);
    {
      std::lock_guard lock(mutex_);
      finished_.push_back(std::move(outcome));
    }
    outcome_ready_.notify_one();
  }
}

}  // namespace ffrf::distributed
