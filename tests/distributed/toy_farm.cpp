// The toy farm: a program on the distributed engine for its tests and benchmark. Task i estimates
// π by Monte Carlo from samples·(1 + 7i mod 5) points (so tasks cost 1 to 5 units, mixed), its
// random numbers drawn from a Mersenne twister seeded by the task's key. It writes table.csv
// (results only, in task order) and timing.csv (wall time and rank per task) into --out when every
// task is done; `--merge` builds the same table from shard journals. Knobs for the tests: a task
// that fails every k-th, a trace of which process computed what, a rank that dies, a rank that
// builds another task list.
//   toy_farm --out DIR [--tasks N] [--samples S] [--task-floor-ms M] [--threads T] [--shard i/n] [--settings TEXT]
//            [--fail-every K] [--trace DIR] [--lose-rank-after I] [--skew-rank R] [--retry-failed]
//   toy_farm --merge JOURNAL_OR_DIR... --out DIR
// Exit 0 when the table is written, 2 for bad input or a journal that cannot serve, 3 for an
// engine failure.
#include <fcntl.h>
#include <fmt/format.h>

#include <random>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <filesystem>
#include <chrono>
#include <optional>
#include <thread>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "distributed/atomic_file.hpp"
#include "distributed/errors.hpp"
#include "distributed/farm.hpp"
#include "distributed/merge.hpp"
#include "distributed/session.hpp"

namespace {

using namespace ffrf::distributed;

struct ToyOptions {
  std::string out;
  std::size_t tasks = 24;
  std::size_t samples = 20000;
  int threads = 0;
  std::string shard = "0/1";
  std::string settings;
  std::size_t fail_every = 0;
  std::string trace;
  long lose_rank_after = -1;
  int skew_rank = -1;
  bool retry_failed = false;
  std::vector<std::string> merge;
  int task_floor_ms = 0;  // every task lasts at least this long (sleeping: no CPU)
};

std::size_t task_samples(std::size_t index, std::size_t samples) { return samples * (1 + (7 * index) % 5); }

// "samples,inside,pi_estimate": the π estimate 4·inside/samples.
std::string estimate_pi(const Task& task, std::size_t samples) {
  std::mt19937_64 stream(task_seed(task));  // the engine's task seed: the same draws on any process
  const auto uniform = [&stream] { return static_cast<double>(stream() >> 11) * 0x1.0p-53; };  // [0, 1)
  std::size_t inside = 0;
  for (std::uint64_t k = 0; k < samples; ++k) {
    const double x = uniform();
    const double y = uniform();
    inside += x * x + y * y < 1.0 ? 1 : 0;
  }
  return fmt::format("{},{},{:.17g}", samples, inside, 4.0 * static_cast<double>(inside) / static_cast<double>(samples));
}

void trace(const std::string& directory, std::size_t index) {
  const std::string file = fmt::format("{}/trace-{}.txt", directory, static_cast<long>(::getpid()));
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot append to " + file);
  const std::string line = std::to_string(index) + "\n";
  const bool written = ::write(fd, line.data(), line.size()) == static_cast<ssize_t>(line.size());
  ::close(fd);
  if (!written) throw std::runtime_error("cannot append to " + file);
}

std::string csv_quoted(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string results_table(const std::vector<TaskOutcome>& outcomes) {
  std::string table = "index,key,status,samples,inside,pi_estimate,message\n";
  for (const TaskOutcome& o : outcomes) {
    table += fmt::format("{},{},{},{},{}\n", o.index, o.key, o.ok ? "ok" : "failed", o.ok ? o.record : ",,",
                         o.ok ? "" : csv_quoted(o.error));
  }
  return table;
}

std::string timing_table(const std::vector<TaskOutcome>& outcomes) {
  std::string table = "index,rank,wall_s,resumed\n";
  for (const TaskOutcome& o : outcomes) table += fmt::format("{},{},{:.6g},{}\n", o.index, o.rank, o.wall_seconds, o.resumed);
  return table;
}

void write_tables(const std::string& out, const std::vector<TaskOutcome>& outcomes) {
  write_file_atomically(out + "/timing.csv", timing_table(outcomes));
  write_file_atomically(out + "/table.csv", results_table(outcomes));  // last: the completeness marker
}

int merge(const ToyOptions& options) {
  std::vector<std::filesystem::path> sources(options.merge.begin(), options.merge.end());
  const MergedJournals merged = merge_journals(sources);
  write_tables(options.out, merged.outcomes);
  fmt::print("merged {} tasks from {} journals into {}\n", merged.outcomes.size(), merged.journals.size(), options.out);
  return 0;
}

int run(Session& session, const ToyOptions& options) {
  const std::optional<Shard> shard = parse_shard(options.shard);
  if (!shard) {
    fmt::print(stderr, "toy_farm: error: --shard {}: not a shard i/n with 0 <= i < n\n", options.shard);
    return 2;
  }
  if (!options.trace.empty()) std::filesystem::create_directories(options.trace);
  std::vector<std::string> keys;
  const std::size_t count = options.tasks + (session.rank() == options.skew_rank ? 1 : 0);
  for (std::size_t i = 0; i < count; ++i) keys.push_back(fmt::format("pi-{}-samples-{}", i, task_samples(i, options.samples)));
  const std::vector<Task> tasks = make_tasks(keys);
  const int rank = session.rank();
  const WorkFunction work = [&](const Task& task) {
    if (!options.trace.empty()) trace(options.trace, task.index);
    if (rank != 0 && options.lose_rank_after >= 0 && task.index >= static_cast<std::size_t>(options.lose_rank_after)) {
      std::raise(SIGKILL);  // a rank lost mid-run
    }
    if (options.fail_every > 0 && (task.index + 1) % options.fail_every == 0) {
      throw std::runtime_error(fmt::format("toy failure: task {} rejects its samples", task.index));
    }
    const auto start = std::chrono::steady_clock::now();
    std::string record = estimate_pi(task, task_samples(task.index, options.samples));
    std::this_thread::sleep_until(start + std::chrono::milliseconds(options.task_floor_ms));
    return record;
  };
  FarmOptions farm;
  farm.output_directory = options.out;
  farm.study = "toy_farm";
  farm.settings = fmt::format("toy pi farm 1; samples {}; fail every {}; {}", options.samples, options.fail_every, options.settings);
  farm.shard = *shard;
  farm.threads = options.threads;
  farm.retry_failed = options.retry_failed;
  farm.progress_label = "toy farm";
  const FarmResult result = run_farm(session, tasks, work, farm);
  if (!result.root) return 0;
  write_tables(options.out, result.outcomes);
  fmt::print("engine: {}\ntasks {} computed {} resumed {} failed {} root_threads {} torn_tail_repaired {} wall_s {:.3f}\n",
             result.engine, result.outcomes.size(), result.computed, result.resumed, result.failed, result.root_threads,
             result.repaired_torn_tail, result.wall_seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  ToyOptions options;
  CLI::App app("Monte-Carlo pi on the distributed engine (test and benchmark program)");
  app.add_option("--out", options.out, "Output directory (journal, table.csv, timing.csv)")->required();
  app.add_option("--tasks", options.tasks, "Number of tasks");
  app.add_option("--samples", options.samples, "Samples of the cheapest task");
  app.add_option("--threads", options.threads, "Compute threads on rank 0 (0: automatic)");
  app.add_option("--shard", options.shard, "Run the shard i/n");
  app.add_option("--settings", options.settings, "Extra settings text (changes the journal's settings hash)");
  app.add_option("--fail-every", options.fail_every, "Task i fails when (i + 1) % K == 0");
  app.add_option("--trace", options.trace, "Append each computed task's index to DIR/trace-<pid>.txt");
  app.add_option("--lose-rank-after", options.lose_rank_after, "A rank > 0 kills itself on a task >= I");
  app.add_option("--skew-rank", options.skew_rank, "This rank builds one task more than the others");
  app.add_flag("--retry-failed", options.retry_failed, "Recompute tasks journaled as failed");
  app.add_option("--task-floor-ms", options.task_floor_ms,
                 "Every task lasts at least this many ms (sleeping): a kill test's run cannot finish first");
  app.add_option("--merge", options.merge, "Merge these shard journals (files or directories) into --out");
  CLI11_PARSE(app, argc, argv);
  // The session outlives the error handlers below, so that a message is printed before a broken
  // MPI session aborts the job.
  std::optional<Session> session;
  try {
    if (options.merge.empty()) session.emplace();
  } catch (const EngineError& error) {
    fmt::print(stderr, "toy_farm: engine error: {}\n", error.what());
    return 3;
  }
  try {
    return options.merge.empty() ? run(*session, options) : merge(options);
  } catch (const JournalError& error) {
    fmt::print(stderr, "toy_farm: journal error: {}\n", error.what());
    return 2;
  } catch (const EngineError& error) {
    fmt::print(stderr, "toy_farm: engine error: {}\n", error.what());
    return 3;
  } catch (const std::exception& error) {
    fmt::print(stderr, "toy_farm: error: {}\n", error.what());
    return 2;
  }
}
