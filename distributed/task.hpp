// A task of a farm: its position in the study's task list and a key that names it stably (e.g. the
// hash of its parameters, or "Hs=2.5 Tp=9 seed=3"). The key, not the position or the process
// that computes it, is what a resumed run matches against its journal and what a task's random
// seed comes from: a result depends on the task alone, never on the rank or the arrival order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ffrf::distributed {

struct Task {
  std::size_t index = 0;     // its position in the full task list (0-based)
  std::string key;           // unique in the list, non-empty
  double expected_cost = 0;  // optional hint (any unit): costlier tasks are handed out first
};

// Tasks 0..n-1 with these keys (no cost hints).
std::vector<Task> make_tasks(const std::vector<std::string>& keys);

// Throws std::invalid_argument naming the first defect: an index that is not its position, an
// empty key, a key that appears twice, a negative or non-finite cost hint.
void validate_tasks(const std::vector<Task>& tasks);

// The fingerprint of a task list: its length and its keys in order.
std::uint64_t task_list_hash(const std::vector<Task>& tasks);

// The seed a task's randomness must come from: a function of its key only.
std::uint64_t task_seed(const Task& task);

}  // namespace ffrf::distributed
