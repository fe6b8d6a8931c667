// Running a task and the text form of its outcome (see outcome.hpp).
#include "distributed/outcome.hpp"

#include "distributed/errors.hpp"

#include <fmt/format.h>

#include <chrono>
#include <charconv>
#include <exception>
#include <vector>

#include "distributed/text_fields.hpp"

namespace ffrf::distributed {
namespace {

template <class Number>
std::optional<Number> parse_number(const std::string& text) {
  Number value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

TaskOutcome run_task(const Task& task, const WorkFunction& work, int rank) {
  TaskOutcome outcome;
  outcome.index = task.index;
  outcome.key = task.key;
  outcome.rank = rank;
  const auto start = std::chrono::steady_clock::now();
  try {
    outcome.record = work(task);
    outcome.ok = true;
  } catch (const TaskAbandoned& stop) {
    outcome.abandoned = true;
    outcome.error = stop.what();
  } catch (const std::exception& error) {
    outcome.error = error.what();
  } catch (...) {
    outcome.error = "an exception that is not a std::exception";
  }
  outcome.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

std::string encode_outcome(const TaskOutcome& outcome) {
  return join_fields({outcome.ok ? "ok" : outcome.abandoned ? "abandoned" : "failed", std::to_string(outcome.index), outcome.key,
                      outcome.ok ? outcome.record : outcome.error, fmt::format("{:.6g}", outcome.wall_seconds),
                      std::to_string(outcome.rank)});
}

std::optional<TaskOutcome> decode_outcome(std::string_view line) {
  const std::optional<std::vector<std::string>> fields = split_fields(line);
  if (!fields || fields->size() != 6) return std::nullopt;
  const std::vector<std::string>& f = *fields;
  if (f[0] != "ok" && f[0] != "failed" && f[0] != "abandoned") return std::nullopt;
  const auto index = parse_number<std::size_t>(f[1]);
  const auto wall = parse_number<double>(f[4]);
  const auto rank = parse_number<int>(f[5]);
  if (!index || !wall || !rank || f[2].empty()) return std::nullopt;
  TaskOutcome outcome;
  outcome.ok = f[0] == "ok";
  outcome.abandoned = f[0] == "abandoned";
  outcome.index = *index;
  outcome.key = f[2];
  (outcome.ok ? outcome.record : outcome.error) = f[3];
  outcome.wall_seconds = *wall;
  outcome.rank = *rank;
  return outcome;
}

}  // namespace ffrf::distributed
