// Shards for array jobs (`--shard i/n`): a deterministic slice of a task list, the tasks whose
// index is i modulo n, so that n independent jobs (e.g. a Slurm array) cover the list exactly
// once; their journals are merged afterwards (merge.hpp). Round-robin by index spreads a list
// ordered by cost (cheap models first, say) evenly over the shards.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "distributed/task.hpp"

namespace ffrf::distributed {

struct Shard {
  std::size_t index = 0;  // i in [0, count)
  std::size_t count = 1;  // n >= 1; 0/1 is the whole list
  bool whole() const { return count == 1; }
  bool operator==(const Shard&) const = default;
};

// "i/n" with 0 <= i < n; std::nullopt for anything else (the caller names the option).
std::optional<Shard> parse_shard(std::string_view text);
std::string to_string(const Shard& shard);  // "i/n"

bool in_shard(const Task& task, const Shard& shard);
// The positions (in the full list) of the shard's tasks, in task order.
std::vector<std::size_t> shard_positions(const std::vector<Task>& tasks, const Shard& shard);

}  // namespace ffrf::distributed
