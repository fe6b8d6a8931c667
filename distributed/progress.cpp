// Terminal progress line (see progress.hpp).
#include "distributed/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ffrf::distributed {

std::optional<double> estimated_seconds_left(const ProgressCounts& counts, double elapsed_seconds, double in_progress) {
  const double worked = static_cast<double>(counts.computed) + std::max(in_progress, 0.0);
  if (!(worked > 0.0)) return std::nullopt;
  const std::size_t done = counts.resumed + counts.computed;
  const double left = static_cast<double>(counts.total > done ? counts.total - done : 0) - std::max(in_progress, 0.0);
  return elapsed_seconds / worked * std::max(left, 0.0);
}

std::string format_duration(double seconds) {
  const long total = std::lround(std::max(seconds, 0.0));
  if (total < 60) return fmt::format("{}s", total);
  if (total < 3600) return fmt::format("{}m{:02}s", total / 60, total % 60);
  return fmt::format("{}h{:02}m", total / 3600, (total % 3600) / 60);
}

std::string progress_line(const std::string& label, const ProgressCounts& counts, double elapsed_seconds,
                          const std::string& detail, double in_progress) {
  std::string line = fmt::format("{}: {}/{} done", label, counts.resumed + counts.computed, counts.total);
  if (counts.resumed > 0) line += fmt::format(" ({} resumed)", counts.resumed);
  line += fmt::format(", {} failed, elapsed {}", counts.failed, format_duration(elapsed_seconds));
  const std::optional<double> left = estimated_seconds_left(counts, elapsed_seconds, in_progress);
  line += left ? ", ETA " + format_duration(*left) : std::string(", ETA ?");
  if (!detail.empty()) line += "; " + detail;
  return line;
}

ProgressMeter::ProgressMeter(std::string label, ProgressCounts start, std::optional<bool> terminal)
    : label_(std::move(label)), counts_(start), shown_(terminal.value_or(::isatty(STDERR_FILENO) != 0)) {
  draw(true);
}

void ProgressMeter::finished(bool ok) {
  ++counts_.computed;
  if (!ok) ++counts_.failed;
  draw(false);
}

void ProgressMeter::tick() { draw(false); }

void ProgressMeter::close() {
  if (closed_) return;
  draw(true);
  if (shown_) std::fputc('\n', stderr);
  closed_ = true;
}

void ProgressMeter::draw(bool force) {
  if (!shown_ || closed_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_draw_ < std::chrono::milliseconds(250)) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  fmt::print(stderr, "\r\033[K{}", progress_line(label_, counts_, elapsed, detail_, in_progress_));
  std::fflush(stderr);
}

}  // namespace ffrf::distributed
