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

}  // namespace ffrf::distributed
