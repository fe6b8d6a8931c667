// The task farm: the engine's entry point (docs/distributed.md). Every process calls run_farm
// with the same task list and work function. Rank 0 opens the journal, skips the tasks it already
// holds, hands the others out one at a time to whichever worker is free — its own compute threads
// and, under MPI, the other ranks — journals each outcome as it arrives and returns all outcomes in
// task order. Ranks > 0 compute what they are sent and return an empty result (root == false):
// they write nothing. A result therefore depends on the task list and the work function alone,
// never on the number of processes, the threads or the order of arrival.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "distributed/outcome.hpp"
#include "distributed/session.hpp"
#include "distributed/shard.hpp"

namespace ffrf::distributed {

struct FarmOptions {
  std::filesystem::path output_directory;  // holds the journal (journal_format.hpp); created if needed
  std::string study;     // for people: what made the journal, e.g. "ffrf sweep cases/x.toml --quick"
  std::string settings;  // everything besides the task keys that results depend on (scene text,
                         // options, program version): a journal made with other settings is refused
  Shard shard;           // run only this slice of the tasks (array jobs); 0/1 is all
  int threads = 0;       // compute threads on rank 0: 0 = one per core when alone, 1 beside other ranks
  bool retry_failed = false;  // recompute the tasks the journal holds as failed
  std::string progress_label = "tasks";
  // Called on rank 0's scheduling thread with every outcome of the run's tasks: first those resumed
  // from the journal, then each computed one once it is journaled (never an abandoned one). What it
  // returns is shown after the progress line's counts (e.g. "5/12 cells complete"); it may write
  // files of its own (partial results a user can watch) but must not throw.
  std::function<std::string(const TaskOutcome&)> on_outcome;
  std::optional<bool> progress_on_terminal;  // show progress (default: when stderr is a terminal)
  // Called on rank 0's scheduling thread before each redraw of the progress line: how much of the
  // tasks being computed by rank 0's threads is done, in tasks (two tasks half-way: 1.0). With it
  // the ETA moves before the first task finishes; without it (or for other ranks' tasks) the ETA
  // comes from finished tasks alone.
  std::function<double()> work_in_progress;
};

struct FarmResult {
  bool root = true;                   // false on ranks > 0: no outcomes, write nothing
  std::vector<TaskOutcome> outcomes;  // the shard's tasks in task order, every one computed or resumed
  std::size_t computed = 0;           // in this run
  std::size_t resumed = 0;            // taken from the journal
  std::size_t failed = 0;             // outcomes that are failures (computed or resumed)
  int processes = 1;                  // MPI ranks (1 when serial)
  std::size_t root_threads = 0;       // compute threads on rank 0
  std::string engine;                 // Session::description()
  std::filesystem::path journal;
  bool repaired_torn_tail = false;    // the journal's last line was torn (by a kill) and cut off
  double wall_seconds = 0.0;
};

// The workers that will compute tasks: rank 0's compute threads plus every other rank (for a cost
// estimate before the farm starts). Throws std::invalid_argument for negative threads.
std::size_t farm_workers(const Session& session, const FarmOptions& options);

// Throws std::invalid_argument for a bad task list (validate_tasks), JournalError when the journal
// cannot serve this run (another task list, settings or shard; damaged; in use; unwritable) and
// EngineError when MPI fails or the ranks disagree. A task that throws is a failed outcome, not an
// error. After an error the journal still holds every task finished before it.
FarmResult run_farm(Session& session, const std::vector<Task>& tasks, const WorkFunction& work,
                    const FarmOptions& options);

}  // namespace ffrf::distributed
