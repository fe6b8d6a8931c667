// Joining the journals of the shards of one farm (array jobs, `--merge`): the outcomes of every
// task of the list, in task order, from the journals alone (no scene or task list needed). The
// journals must come from the same settings and task list (their headers say so), no task may be
// in two of them (overlapping shards), and every task must be in one (a shard missing or not
// finished): otherwise JournalError says which.
#pragma once

#include <filesystem>
#include <vector>

#include "distributed/journal_format.hpp"

namespace ffrf::distributed {

struct MergedJournals {
  JournalHeader header;                     // the shared header, shard 0/1
  std::vector<TaskOutcome> outcomes;        // every task of the list, in task order
  std::vector<std::filesystem::path> journals;  // the files read
};

// `sources`: journal files, or directories whose journal*.tsv files are all taken.
MergedJournals merge_journals(const std::vector<std::filesystem::path>& sources);

}  // namespace ffrf::distributed
