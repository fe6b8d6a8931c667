// Task lists, their validation and fingerprint, and task seeds (see task.hpp).
#include "distributed/task.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "distributed/stable_hash.hpp"

namespace ffrf::distributed {

std::vector<Task> make_tasks(const std::vector<std::string>& keys) {
  std::vector<Task> tasks;
  tasks.reserve(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) tasks.push_back(Task{i, keys[i], 0.0});
  return tasks;
}

void validate_tasks(const std::vector<Task>& tasks) {
  std::unordered_map<std::string, std::size_t> first_position;
  first_position.reserve(tasks.size());
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const Task& task = tasks[i];
    if (task.index != i) {
      throw std::invalid_argument(fmt::format("task list: the task at position {} has index {} (must be {})", i, task.index, i));
    }
    if (task.key.empty()) throw std::invalid_argument(fmt::format("task list: task {} has an empty key", i));
    if (!(task.expected_cost >= 0.0) || !std::isfinite(task.expected_cost)) {
      throw std::invalid_argument(fmt::format("task list: task {} ({}) has expected cost {} (valid range [0, inf))", i,
                                              task.key, task.expected_cost));
    }
    const auto [where, inserted] = first_position.emplace(task.key, i);
    if (!inserted) {
      throw std::invalid_argument(
          fmt::format("task list: key '{}' names tasks {} and {} (keys must be unique)", task.key, where->second, i));
    }
  }
}

std::uint64_t task_list_hash(const std::vector<Task>& tasks) {
  StableHash hash;
  hash.add_field(std::to_string(tasks.size()));
  for (const Task& task : tasks) hash.add_field(task.key);
  return hash.value();
}

std::uint64_t task_seed(const Task& task) {
  // FNV-1a of the key, then MurmurHash3's 64-bit finaliser (Appleby) so that keys that differ in
  // one character give seeds that differ in about half their bits.
  std::uint64_t z = stable_hash(task.key);
  z = (z ^ (z >> 33)) * 0xff51afd7ed558ccdULL;
  z = (z ^ (z >> 33)) * 0xc4ceb9fe1a85ec53ULL;
  return z ^ (z >> 33);
}

}  // namespace ffrf::distributed
