// The journal a farm's rank 0 appends to as tasks finish (format: journal_format.hpp). Opening it
// creates it with the run's header, or reads an existing one back for resumption: its header
// must match the run's (else JournalError naming the difference), a torn last line is cut off,
// and the file is locked so that a second run on the same directory is refused while the first
// lives. append() returns once the line is on disk (write + fsync): a kill after it loses nothing.
#pragma once

#include <filesystem>
#include <vector>

#include "distributed/journal_format.hpp"

namespace ffrf::distributed {

class Journal {
 public:
  Journal(std::filesystem::path file, const JournalHeader& header);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  const std::filesystem::path& file() const { return file_; }
  // The tasks journaled by earlier runs (a failure superseded by a later retry is not among them).
  const std::vector<TaskOutcome>& previous() const { return previous_; }
  bool repaired_torn_tail() const { return repaired_; }

  // Writes one line and flushes it to disk; JournalError (with the system's reason) on failure.
  void append(const TaskOutcome& outcome);

 private:
  void write_all(const std::string& bytes);
  std::filesystem::path file_;
  int fd_ = -1;
  std::vector<TaskOutcome> previous_;
  bool repaired_ = false;
};

}  // namespace ffrf::distributed
