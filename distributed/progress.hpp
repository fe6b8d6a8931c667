// Progress of a farm on a terminal: tasks done of the total (how many resumed from the journal),
// failed, elapsed time and the estimated time to go, on one stderr line overwritten in place —
// only when stderr is a terminal; quiet otherwise (logs, pipes, batch jobs). The estimate is the
// elapsed time per task done in this run times the tasks left: with p workers busy, tasks finish p
// times as often, which the observed rate already contains. "Done" counts the finished tasks and,
// when the study reports it, the done part of the tasks in progress (a record's simulated time over
// its length), so the estimate exists before the first task finishes.
#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

namespace ffrf::distributed {

struct ProgressCounts {
  std::size_t total = 0;     // tasks of this run (the shard's)
  std::size_t resumed = 0;   // found in the journal at the start
  std::size_t computed = 0;  // finished in this run
  std::size_t failed = 0;    // of resumed + computed
};

// Seconds to go, from the rate of this run's completions plus `in_progress` tasks' worth of work done
// in the tasks being computed; std::nullopt while nothing is done.
std::optional<double> estimated_seconds_left(const ProgressCounts& counts, double elapsed_seconds,
                                             double in_progress = 0.0);
std::string format_duration(double seconds);  // "42s", "3m05s", "2h07m"
// "label: 12/40 done (3 resumed), 1 failed, elapsed 1m02s, ETA 2m10s" (then "; detail" when given)
std::string progress_line(const std::string& label, const ProgressCounts& counts, double elapsed_seconds,
                          const std::string& detail = {}, double in_progress = 0.0);

class ProgressMeter {
 public:
  // Shown when `terminal` (by default: stderr is a terminal).
  ProgressMeter(std::string label, ProgressCounts start, std::optional<bool> terminal = std::nullopt);
  ~ProgressMeter() { close(); }
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;
  void finished(bool ok);  // one more task computed
  void tick();             // redraws (at most every 0.25 s) so that the elapsed time moves
  void set_detail(std::string detail) { detail_ = std::move(detail); }  // the study's own count
  void set_in_progress(double tasks) { in_progress_ = tasks; }  // done part of the tasks being computed
  void close();            // last redraw and a line end
  const ProgressCounts& counts() const { return counts_; }

 private:
  void draw(bool force);
  std::string label_;
  std::string detail_;
  double in_progress_ = 0.0;
  ProgressCounts counts_;
  bool shown_;
  bool closed_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace ffrf::distributed
