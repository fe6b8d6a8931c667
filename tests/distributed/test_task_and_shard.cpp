// Tasks, keys, seeds, shards and the stable hash. Independent facts: the published FNV-1a 64 test
// vectors; shards partition a list (every task in exactly one shard of n); seeds come from keys
// alone (not from the position).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "distributed/shard.hpp"
#include "distributed/stable_hash.hpp"
#include "distributed/task.hpp"

namespace ffrf::distributed {
namespace {

TEST(StableHash, MatchesThePublishedFnv1a64TestVectors) {
  // Test vectors of the FNV reference code (Landon Curt Noll, "test_fnv.c", FNV-1a 64).
  EXPECT_EQ(stable_hash(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(stable_hash("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(stable_hash("foobar"), 0x85944171f73967e8ULL);
  EXPECT_EQ(hex(0xaf63dc4c8601ec8cULL), "af63dc4c8601ec8c");
}

TEST(StableHash, FieldsAreSeparated) {
  EXPECT_NE(StableHash().add_field("ab").add_field("c").value(), StableHash().add_field("a").add_field("bc").value());
}

TEST(Tasks, MakeTasksNumbersThemByPosition) {
  const std::vector<Task> tasks = make_tasks({"x", "y", "z"});
  ASSERT_EQ(tasks.size(), 3u);
  for (std::size_t i = 0; i < tasks.size(); ++i) EXPECT_EQ(tasks[i].index, i);
  EXPECT_EQ(tasks[2].key, "z");
  EXPECT_NO_THROW(validate_tasks(tasks));
}

TEST(Tasks, ValidationNamesTheDefect) {
  const auto message = [](const std::vector<Task>& tasks) {
    try {
      validate_tasks(tasks);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(make_tasks({"a", "b", "a"})).find("key 'a' names tasks 0 and 2"), std::string::npos);
  EXPECT_NE(message(make_tasks({"a", ""})).find("task 1 has an empty key"), std::string::npos);
  std::vector<Task> shifted = make_tasks({"a", "b"});
  shifted[1].index = 5;
  EXPECT_NE(message(shifted).find("position 1 has index 5"), std::string::npos);
  std::vector<Task> negative = make_tasks({"a"});
  negative[0].expected_cost = -1.0;
  EXPECT_NE(message(negative).find("valid range [0, inf)"), std::string::npos);
}

TEST(Tasks, TheSeedComesFromTheKeyAlone) {
  Task a{0, "Hs=2.5 Tp=9 seed=3", 0.0};
  Task b{17, "Hs=2.5 Tp=9 seed=3", 4.0};
  EXPECT_EQ(task_seed(a), task_seed(b));  // another position, same key: same randomness
  std::set<std::uint64_t> seeds;
  for (int i = 0; i < 10000; ++i) seeds.insert(task_seed(Task{0, "seed=" + std::to_string(i), 0.0}));
  EXPECT_EQ(seeds.size(), 10000u);  // no two keys of a realistic list share a seed
}

TEST(Tasks, TheListHashFollowsKeysAndOrder) {
  EXPECT_EQ(task_list_hash(make_tasks({"a", "b"})), task_list_hash(make_tasks({"a", "b"})));
  EXPECT_NE(task_list_hash(make_tasks({"a", "b"})), task_list_hash(make_tasks({"b", "a"})));
  EXPECT_NE(task_list_hash(make_tasks({"a", "b"})), task_list_hash(make_tasks({"a", "b", "c"})));
}

TEST(Shards, ParseAcceptsOnlyIndexSlashCount) {
  ASSERT_TRUE(parse_shard("2/5"));
  EXPECT_EQ(*parse_shard("2/5"), (Shard{2, 5}));
  EXPECT_EQ(to_string(Shard{2, 5}), "2/5");
  for (const char* bad : {"5/5", "1/0", "-1/3", "1/", "/3", "a/3", "1/3x", "13", "", "1//3"}) {
    EXPECT_FALSE(parse_shard(bad)) << bad;
  }
}

TEST(Shards, TheShardsOfNCoverTheListExactlyOnce) {
  std::vector<std::string> keys;
  for (int i = 0; i < 23; ++i) keys.push_back("task" + std::to_string(i));
  const std::vector<Task> tasks = make_tasks(keys);
  for (std::size_t n = 1; n <= 6; ++n) {
    std::vector<int> seen(tasks.size(), 0);
    for (std::size_t i = 0; i < n; ++i) {
      const std::vector<std::size_t> positions = shard_positions(tasks, Shard{i, n});
      EXPECT_TRUE(std::is_sorted(positions.begin(), positions.end()));
      EXPECT_GE(positions.size(), tasks.size() / n);  // balanced: sizes differ by at most one
      EXPECT_LE(positions.size(), tasks.size() / n + 1);
      for (std::size_t p : positions) ++seen[p];
    }
    for (int count : seen) EXPECT_EQ(count, 1) << n << " shards";
  }
}

}  // namespace
}  // namespace ffrf::distributed
