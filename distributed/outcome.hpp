// What became of a task: its result record (the study's serialised result, opaque to the engine)
// or, when the work function threw, the failure message; plus how long it took and on which rank,
// kept apart from the result because they differ from run to run. The text form (one line of
// escaped tab-separated fields, text_fields.hpp) is both a journal line's body and the message a
// rank sends to rank 0:
//   ok|failed|abandoned  index  key  record-or-message  wall_s  rank   (abandoned: rank messages only)
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "distributed/task.hpp"

namespace ffrf::distributed {

// The study's work: the result of one task as one record (e.g. a CSV row, a JSON object, a
// serialised struct). It must depend on the task alone (take random seeds from task_seed), may be
// called from any thread of any process, and reports a failure by throwing.
using WorkFunction = std::function<std::string(const Task& task)>;

struct TaskOutcome {
  std::size_t index = 0;
  std::string key;
  bool ok = false;
  std::string record;  // the work function's result, when ok
  std::string error;   // the exception's message, when not ok
  // Timing and provenance: not results (they change from run to run).
  double wall_seconds = 0.0;
  int rank = 0;          // the process that computed it
  bool resumed = false;  // read back from the journal rather than computed in this run
  bool abandoned = false;  // the work function threw TaskAbandoned (errors.hpp): never journaled
};

// Calls work(task), timing it; an exception becomes a failed outcome with its message.
TaskOutcome run_task(const Task& task, const WorkFunction& work, int rank);

std::string encode_outcome(const TaskOutcome& outcome);  // one line, without its line end
// std::nullopt when the line is not a well-formed outcome.
std::optional<TaskOutcome> decode_outcome(std::string_view line);

}  // namespace ffrf::distributed
