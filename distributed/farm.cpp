// The scheduler of the task farm (see farm.hpp): rank 0's main thread hands out tasks, polls for
// outcomes and journals them; compute threads and other ranks do the work.
#include "distributed/farm.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <exception>
#include <thread>

#include "distributed/errors.hpp"
#include "distributed/journal.hpp"
#include "distributed/local_workers.hpp"
#include "distributed/progress.hpp"
#include "distributed/rank_transport.hpp"
#include "distributed/stable_hash.hpp"

namespace ffrf::distributed {
namespace {

std::size_t compute_threads(const Session& session, const FarmOptions& options) {
  if (options.threads < 0) {
    throw std::invalid_argument(fmt::format("farm: {} compute threads (valid range [0, inf), 0: automatic)", options.threads));
  }
  if (session.size() > 1 && !session.threads_beside_mpi()) return 0;  // the main thread must stay with MPI
  if (options.threads > 0) return static_cast<std::size_t>(options.threads);
  if (session.size() > 1) return 1;
  return std::max(1u, std::thread::hardware_concurrency());
}

// The shard's tasks not in the journal (or failed there, when retried), costliest first.
std::deque<std::size_t> pending_tasks(const std::vector<Task>& tasks, const std::vector<std::size_t>& positions,
                                      const std::vector<std::optional<TaskOutcome>>& known) {
  std::vector<std::size_t> pending;
  for (std::size_t position : positions) {
    if (!known[position]) pending.push_back(position);
  }
  std::stable_sort(pending.begin(), pending.end(),
                   [&](std::size_t a, std::size_t b) { return tasks[a].expected_cost > tasks[b].expected_cost; });
  return {pending.begin(), pending.end()};
}

}  // namespace

std::size_t farm_workers(const Session& session, const FarmOptions& options) {
  return compute_threads(session, options) + static_cast<std::size_t>(session.size() - 1);
}

FarmResult run_farm(Session& session, const std::vector<Task>& tasks, const WorkFunction& work,
                    const FarmOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  validate_tasks(tasks);  // every rank checks its arguments the same way before any message
  const std::size_t root_threads = compute_threads(session, options);
  const Handshake handshake{stable_hash(options.settings), task_list_hash(tasks), options.shard};
  FarmResult result;
  result.processes = session.size();
  result.engine = session.description();
  if (!session.is_root()) {
    serve_tasks(session, handshake, tasks, work);
    result.root = false;
    return result;
  }
  const std::unique_ptr<RankTransport> ranks = connect_ranks(session, handshake);
  std::optional<Journal> journal;
  try {
    journal.emplace(journal_path(options.output_directory, options.shard),
                    JournalHeader{options.study, handshake.settings_hash, tasks.size(), handshake.task_list_hash,
                                  options.shard});
  } catch (...) {
    if (ranks) ranks->release();
    throw;
  }
  result.journal = journal->file();
  result.repaired_torn_tail = journal->repaired_torn_tail();

  std::vector<std::optional<TaskOutcome>> known(tasks.size());
  for (const TaskOutcome& outcome : journal->previous()) {
    if (outcome.key != tasks[outcome.index].key) {
      if (ranks) ranks->release();
      throw JournalError(fmt::format("{}: task {} is journaled with key '{}' but this run's task {} is '{}'",
                                     journal->file().string(), outcome.index, outcome.key, outcome.index,
                                     tasks[outcome.index].key));
    }
    if (outcome.ok || !options.retry_failed) known[outcome.index] = outcome;
  }
  const std::vector<std::size_t> positions = shard_positions(tasks, options.shard);
  std::deque<std::size_t> pending = pending_tasks(tasks, positions, known);
  result.resumed = positions.size() - pending.size();
  result.root_threads = root_threads;

  std::size_t resumed_failures = 0;
  for (std::size_t position : positions) resumed_failures += known[position] && !known[position]->ok ? 1 : 0;
  ProgressMeter progress(options.progress_label, ProgressCounts{positions.size(), result.resumed, 0, resumed_failures},
                         options.progress_on_terminal);
  if (options.on_outcome) {
    for (std::size_t position : positions) {
      if (known[position]) progress.set_detail(options.on_outcome(*known[position]));
    }
  }
  std::exception_ptr failure;  // a journal that cannot be written: stop handing out, then report
  std::optional<std::string> abandoned;  // a task given up on a stop request: hand out nothing more
  const auto record = [&](TaskOutcome outcome) {
    if (outcome.abandoned) {
      if (!abandoned) abandoned = outcome.error;
      pending.clear();
      return;
    }
    if (!failure) {
      try {
        journal->append(outcome);
      } catch (...) {
        failure = std::current_exception();
        pending.clear();
      }
    }
    if (options.on_outcome) progress.set_detail(options.on_outcome(outcome));
    progress.finished(outcome.ok);
    ++result.computed;
    known[outcome.index] = std::move(outcome);
  };
  {
    LocalWorkers local(pending.empty() ? 0 : result.root_threads, tasks, work, session.rank());
    // With other ranks, poll them every 20 µs to 2 ms (the longer the quieter they are); alone,
    // sleep until a local outcome arrives or the progress line is due.
    const std::chrono::microseconds quickest{20}, slowest_poll{2000}, alone{250000};
    std::chrono::microseconds poll_wait = quickest;
    while (true) {
      while (!pending.empty() && local.idle() > 0) {
        local.submit(pending.front());
        pending.pop_front();
      }
      while (ranks && !pending.empty()) {
        const std::optional<int> idle = ranks->idle_rank();
        if (!idle) break;
        ranks->send_task(*idle, pending.front());
        pending.pop_front();
      }
      if (pending.empty() && local.busy() == 0 && (!ranks || ranks->busy() == 0)) break;
      bool arrived = false;
      while (ranks) {
        std::optional<TaskOutcome> outcome = ranks->poll();
        if (!outcome) break;
        record(std::move(*outcome));
        arrived = true;
      }
      poll_wait = arrived ? quickest : std::min(2 * poll_wait, slowest_poll);
      const std::chrono::microseconds wait = arrived ? std::chrono::microseconds(0) : ranks ? poll_wait : alone;
      for (TaskOutcome& outcome : local.collect(wait)) record(std::move(outcome));
      if (options.work_in_progress) progress.set_in_progress(options.work_in_progress());
      progress.tick();
    }
  }
  if (ranks) ranks->release();
  progress.close();
  if (failure) std::rethrow_exception(failure);
  if (abandoned) throw TaskAbandoned(*abandoned);

  for (std::size_t position : positions) {
    TaskOutcome& outcome = *known[position];
    result.failed += outcome.ok ? 0 : 1;
    result.outcomes.push_back(std::move(outcome));
  }
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::distributed
