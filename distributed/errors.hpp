// The errors of the distributed engine, by kind, so that a program can map each to its own exit
// code and remedy: a journal that cannot be used (written for other tasks, damaged, in use by
// another run, unwritable), and a failure of the engine itself (an MPI call that failed, ranks that
// disagree on the task list, a launcher this build cannot serve). A task that throws is neither:
// it becomes a failed outcome (outcome.hpp) and the run goes on.
#pragma once

#include <stdexcept>
#include <string>

namespace ffrf::distributed {

class JournalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class EngineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown by a work function that gives a task up because the program was asked to stop (SIGINT,
// SIGTERM: a Ctrl-C, a batch system's time limit): the task is neither a result nor a failure. The
// farm journals nothing for it, hands out nothing more, awaits the tasks in progress (journaling
// those that finish) and rethrows it, so that a rerun computes the task again.
class TaskAbandoned : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ffrf::distributed
