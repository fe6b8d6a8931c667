// Output that is complete or absent: files are written into a staging directory next to the
// target and moved into place by commit(), the completeness marker (summary.json) last. Creating
// a StagedDirectory removes the target's old marker (its files are about to be replaced); without
// commit() — an error, an exception, an interrupt — the staging directory is removed, and so are
// the parent directories it had to create: nothing is left beside the target. A stop request
// (SIGINT/SIGTERM, solve/stop_request.hpp) makes commit() throw solve::Interrupted instead of
// committing. Every failure is an OutputError naming the user's path (never the staging path) and
// the operating system's reason ("Permission denied", "No space left on device").
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ffrf::report {

// An output directory or file that cannot be created or written: "--out DIR: cannot ...: REASON".
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What became of one chart of an output directory (its PNG file name): drawn, left out because it
// had nothing to draw (the reason says why), or failed (gnuplot's message; its script is kept so the
// user can rerun it). A chart never costs a command its results: the data are written either way.
struct ChartRecord {
  enum class Status { drawn, left_out, failed };
  std::string png;
  Status status = Status::drawn;
  std::string reason;  // left out or failed: why
};

class StagedDirectory {
 public:
  // Creates the staging directory (and the target's missing parents) and removes target/marker.
  StagedDirectory(std::filesystem::path target, std::string marker);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  const std::filesystem::path& staging() const { return staging_; }
  const std::filesystem::path& target() const { return target_; }
  // Writes a file into the staging directory; throws OutputError on failure.
  void write(std::string_view name, std::string_view content) const;
  // Moves everything into the target (created if needed), the marker last; throws OutputError, or
  // solve::Interrupted when a stop was requested (nothing is committed then).
  void commit();
  // The charts drawn (or not) into this directory, in order (report/gnuplot.hpp's draw_chart and
  // leave_out_chart record them; the commands name the ones not drawn in their reports).
  void record_chart(ChartRecord record) const { charts_.push_back(std::move(record)); }
  const std::vector<ChartRecord>& charts() const { return charts_; }

 private:
  [[noreturn]] void fail(const std::string& what, const std::error_code& reason) const;

  std::filesystem::path target_;
  std::filesystem::path staging_;
  std::string marker_;
  std::vector<std::filesystem::path> created_parents_;  // deepest first; removed again without commit
  bool committed_ = false;
  mutable std::vector<ChartRecord> charts_;  // a log of what was written, not the directory's identity
};

// Checks that DIR can take the output of a command that writes it only at the end (creates and
// removes a staging directory); throws OutputError. Removes DIR's old marker, like StagedDirectory.
void check_output_directory(const std::filesystem::path& target, const std::string& marker);

// Removes every staging directory (and created parent) not yet committed or removed: for a program
// that must exit at once (a second SIGINT, or a stop that the computation did not honour in time).
// Not async-signal-safe: call it from a normal thread.
void remove_uncommitted_outputs() noexcept;

}  // namespace ffrf::report
