// Shard selection and parsing (see shard.hpp).
#include "distributed/shard.hpp"

#include <charconv>

namespace ffrf::distributed {

std::optional<Shard> parse_shard(std::string_view text) {
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  Shard shard;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const auto [index_end, index_error] = std::from_chars(begin, begin + slash, shard.index);
  const auto [count_end, count_error] = std::from_chars(begin + slash + 1, end, shard.count);
  if (index_error != std::errc() || count_error != std::errc()) return std::nullopt;
  if (index_end != begin + slash || count_end != end || slash == 0) return std::nullopt;
  if (shard.count < 1 || shard.index >= shard.count) return std::nullopt;
  return shard;
}

std::string to_string(const Shard& shard) { return std::to_string(shard.index) + "/" + std::to_string(shard.count); }

bool in_shard(const Task& task, const Shard& shard) { return task.index % shard.count == shard.index; }

std::vector<std::size_t> shard_positions(const std::vector<Task>& tasks, const Shard& shard) {
  std::vector<std::size_t> positions;
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    if (in_shard(tasks[i], shard)) positions.push_back(i);
  }
  return positions;
}

}  // namespace ffrf::distributed
