// The journal file of a farm: what it was made for (the header line) and the finished tasks, one
// line each, appended as they complete (docs/distributed.md §3). Every line ends with a checksum
// of its body, so that a line cut short by a kill (a torn last line) is recognised and ignored:
//   ffrf-journal  1  <study>  settings=<hex>  tasks=<N>  task-list=<hex>  shard=<i/n>  <checksum>
//   ok|failed  <index>  <key>  <record or message>  <wall_s>  <rank>  <checksum>
// Fields are tab-separated and escaped (text_fields.hpp); checksums are FNV-1a 64 in hexadecimal.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "distributed/outcome.hpp"
#include "distributed/shard.hpp"

namespace ffrf::distributed {

struct JournalHeader {
  std::string study;                // who made it, for people ("ffrf sweep cases/x.toml"); not compared
  std::uint64_t settings_hash = 0;  // everything besides the task list that results depend on
  std::size_t tasks = 0;            // length of the full task list
  std::uint64_t task_list_hash = 0; // task_list_hash() of the full list
  Shard shard;
};

// Why a journal with header `found` cannot serve a run with header `wanted`, in words; std::nullopt
// when it can (same settings, task list and shard).
std::optional<std::string> header_mismatch(const JournalHeader& found, const JournalHeader& wanted);

// "journal.tsv", or "journal-shard-<i>-of-<n>.tsv" for a shard (so shards may share a directory).
std::filesystem::path journal_path(const std::filesystem::path& directory, const Shard& shard);

std::string header_line(const JournalHeader& header);     // with its checksum and line end
std::string outcome_line(const TaskOutcome& outcome);     // with its checksum and line end

// A journal read back.
struct JournalContents {
  JournalHeader header;
  std::vector<TaskOutcome> outcomes;  // in the order they were journaled; resumed = true
  std::size_t intact_bytes = 0;       // the length of the complete, valid lines
  bool torn_tail = false;             // the last line was incomplete or damaged and is ignored
};

// Parses a journal's text. A bad last line (torn by a kill) is ignored; a bad line before the last,
// a record outside the header's task list or shard, or a task journaled twice with a success
// throws JournalError naming `source` and the line. A later record of a task supersedes an
// earlier failure (a retry). std::nullopt when not even the header line is complete.
std::optional<JournalContents> parse_journal(std::string_view text, const std::string& source);
// Reads and parses a file; JournalError when it cannot be read or has no complete header.
JournalContents read_journal(const std::filesystem::path& file);

}  // namespace ffrf::distributed
