// Rank 0's line to the other ranks of an MPI job, and the loop those ranks run. The protocol
// (docs/distributed.md §2): every rank > 0 sends a hello (its settings and task-list hashes and
// shard) and waits; rank 0 checks every hello against its own, then sends task positions to idle
// ranks; a rank computes the task and sends back its outcome (outcome.hpp's text form); a stop
// message ends the loop. Every rank builds the task list itself, so only positions travel. Only
// the main thread of each process calls MPI. Built without MPI, connect_ranks returns nullptr.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "distributed/outcome.hpp"
#include "distributed/session.hpp"
#include "distributed/shard.hpp"

namespace ffrf::distributed {

// What all ranks must agree on before any task is handed out.
struct Handshake {
  std::uint64_t settings_hash = 0;
  std::uint64_t task_list_hash = 0;
  Shard shard;
};

class RankTransport {
 public:
  virtual ~RankTransport() = default;
  virtual std::size_t ranks() const = 0;  // the other ranks
  virtual std::size_t busy() const = 0;   // ranks computing a task
  // An idle rank, if any.
  virtual std::optional<int> idle_rank() const = 0;
  virtual void send_task(int rank, std::size_t position) = 0;
  // An outcome that has arrived (its sender is idle again), without waiting; std::nullopt if none.
  virtual std::optional<TaskOutcome> poll() = 0;
  // Ends every rank's loop (after a refused or failed run too: rank 0 reports, the others return
  // quietly). Waits for the outcomes of busy ranks first, and drops them.
  virtual void release() = 0;
};

// Rank 0: waits for the hello of every other rank; EngineError naming a rank whose hello differs
// (after releasing them all). nullptr in a single-process session.
std::unique_ptr<RankTransport> connect_ranks(Session& session, const Handshake& handshake);

// Ranks > 0: hello, then compute what rank 0 sends until it says stop. EngineError when an MPI
// call fails.
void serve_tasks(Session& session, const Handshake& handshake, const std::vector<Task>& tasks, const WorkFunction& work);

}  // namespace ffrf::distributed
