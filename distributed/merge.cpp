// Merging shard journals (see merge.hpp).
#include "distributed/merge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "distributed/errors.hpp"

namespace ffrf::distributed {
namespace {

std::vector<std::filesystem::path> journal_files(const std::vector<std::filesystem::path>& sources) {
  std::vector<std::filesystem::path> files;
  for (const std::filesystem::path& source : sources) {
    if (!std::filesystem::is_directory(source)) {
      files.push_back(source);
      continue;
    }
    std::vector<std::filesystem::path> found;
    for (const auto& entry : std::filesystem::directory_iterator(source)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file() && name.rfind("journal", 0) == 0 && entry.path().extension() == ".tsv") {
        found.push_back(entry.path());
      }
    }
    if (found.empty()) throw JournalError(fmt::format("{}: holds no journal (journal*.tsv)", source.string()));
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

}  // namespace

MergedJournals merge_journals(const std::vector<std::filesystem::path>& sources) {
  MergedJournals merged;
  merged.journals = journal_files(sources);
  if (merged.journals.empty()) throw JournalError("merge: no journal given");
  std::vector<std::optional<TaskOutcome>> by_index;
  std::vector<std::size_t> source_of;  // which journal holds each task
  for (std::size_t j = 0; j < merged.journals.size(); ++j) {
    const std::filesystem::path& file = merged.journals[j];
    JournalContents contents = read_journal(file);
    if (j == 0) {
      merged.header = contents.header;
      merged.header.shard = Shard{};
      by_index.resize(merged.header.tasks);
      source_of.resize(merged.header.tasks);
    } else {
      JournalHeader same_shard = merged.header;
      same_shard.shard = contents.header.shard;
      if (const auto why = header_mismatch(contents.header, same_shard)) {
        throw JournalError(fmt::format("{} cannot be merged with {}: {}", file.string(), merged.journals[0].string(), *why));
      }
    }
    for (TaskOutcome& outcome : contents.outcomes) {
      const std::size_t i = outcome.index;
      if (by_index[i]) {
        throw JournalError(fmt::format("task {} ('{}') is in both {} and {} (overlapping shards?)", i, outcome.key,
                                       merged.journals[source_of[i]].string(), file.string()));
      }
      source_of[i] = j;
      by_index[i] = std::move(outcome);
    }
  }
  std::vector<std::size_t> missing;
  for (std::size_t i = 0; i < by_index.size(); ++i) {
    if (!by_index[i]) missing.push_back(i);
  }
  if (!missing.empty()) {
    std::string list;
    for (std::size_t k = 0; k < std::min<std::size_t>(missing.size(), 10); ++k) list += (k ? ", " : "") + std::to_string(missing[k]);
    if (missing.size() > 10) list += ", ...";
    throw JournalError(fmt::format("merge: {} of the {} tasks are in none of the {} journals (tasks {}): a shard "
                                   "missing or not finished? Run it (it resumes), then merge again",
                                   missing.size(), by_index.size(), merged.journals.size(), list));
  }
  for (auto& outcome : by_index) merged.outcomes.push_back(std::move(*outcome));
  return merged;
}

}  // namespace ffrf::distributed
