// Journal lines, their checksums and the parsing of a journal (see journal_format.hpp).
#include "distributed/journal_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <sstream>

#include "distributed/errors.hpp"
#include "distributed/stable_hash.hpp"
#include "distributed/text_fields.hpp"

namespace ffrf::distributed {
namespace {

constexpr const char* magic = "ffrf-journal";
constexpr const char* format_version = "1";

std::string with_checksum(const std::string& body) { return body + '\t' + hex(stable_hash(body)) + '\n'; }

// The body of a complete line whose checksum holds; std::nullopt otherwise.
std::optional<std::string_view> verified_body(std::string_view line) {
  const std::size_t tab = line.rfind('\t');
  if (tab == std::string_view::npos) return std::nullopt;
  const std::string_view body = line.substr(0, tab);
  if (line.substr(tab + 1) != hex(stable_hash(body))) return std::nullopt;
  return body;
}

std::optional<std::uint64_t> parse_hex(std::string_view text) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, 16);
  if (error != std::errc() || end != text.data() + text.size() || text.size() != 16) return std::nullopt;
  return value;
}

// "name=value" -> value, when the field has that name.
std::optional<std::string_view> named(std::string_view field, std::string_view name) {
  if (field.size() <= name.size() || field.substr(0, name.size()) != name || field[name.size()] != '=') return std::nullopt;
  return field.substr(name.size() + 1);
}

std::optional<JournalHeader> parse_header(std::string_view body) {
  const std::optional<std::vector<std::string>> fields = split_fields(body);
  if (!fields || fields->size() != 7 || (*fields)[0] != magic || (*fields)[1] != format_version) return std::nullopt;
  const std::vector<std::string>& f = *fields;
  JournalHeader header;
  header.study = f[2];
  const auto settings = named(f[3], "settings");
  const auto tasks = named(f[4], "tasks");
  const auto list = named(f[5], "task-list");
  const auto shard_text = named(f[6], "shard");
  if (!settings || !tasks || !list || !shard_text) return std::nullopt;
  const auto settings_hash = parse_hex(*settings);
  const auto list_hash = parse_hex(*list);
  const auto shard = parse_shard(*shard_text);
  const auto [end, error] = std::from_chars(tasks->data(), tasks->data() + tasks->size(), header.tasks);
  if (!settings_hash || !list_hash || !shard || error != std::errc() || end != tasks->data() + tasks->size()) {
    return std::nullopt;
  }
  header.settings_hash = *settings_hash;
  header.task_list_hash = *list_hash;
  header.shard = *shard;
  return header;
}

}  // namespace

std::optional<std::string> header_mismatch(const JournalHeader& found, const JournalHeader& wanted) {
  if (found.settings_hash != wanted.settings_hash) {
    return fmt::format("it was made with other settings (settings hash {}, this run {})", hex(found.settings_hash),
                       hex(wanted.settings_hash));
  }
  if (found.tasks != wanted.tasks || found.task_list_hash != wanted.task_list_hash) {
    return fmt::format("it was made for another task list ({} tasks, hash {}; this run {} tasks, hash {})", found.tasks,
                       hex(found.task_list_hash), wanted.tasks, hex(wanted.task_list_hash));
  }
  if (!(found.shard == wanted.shard)) {
    return fmt::format("it was made for shard {} (this run: shard {})", to_string(found.shard), to_string(wanted.shard));
  }
  return std::nullopt;
}

std::filesystem::path journal_path(const std::filesystem::path& directory, const Shard& shard) {
  if (shard.whole()) return directory / "journal.tsv";
  return directory / fmt::format("journal-shard-{}-of-{}.tsv", shard.index, shard.count);
}

std::string header_line(const JournalHeader& header) {
  return with_checksum(join_fields({magic, format_version, header.study, "settings=" + hex(header.settings_hash),
                                    "tasks=" + std::to_string(header.tasks), "task-list=" + hex(header.task_list_hash),
                                    "shard=" + to_string(header.shard)}));
}

std::string outcome_line(const TaskOutcome& outcome) { return with_checksum(encode_outcome(outcome)); }

std::optional<JournalContents> parse_journal(std::string_view text, const std::string& source) {
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string_view::npos) return std::nullopt;
  const std::optional<std::string_view> header_body = verified_body(text.substr(0, header_end));
  const std::optional<JournalHeader> header = header_body ? parse_header(*header_body) : std::nullopt;
  if (!header) {
    throw JournalError(fmt::format("{}: line 1 is not an ffrf journal header (format {})", source, format_version));
  }
  JournalContents contents;
  contents.header = *header;
  contents.intact_bytes = header_end + 1;
  std::map<std::size_t, std::size_t> line_of_index;  // task index -> its line (1-based)
  std::size_t start = header_end + 1;
  for (std::size_t line_number = 2; start < text.size(); ++line_number) {
    const std::size_t end = text.find('\n', start);
    const bool last = end == std::string_view::npos || end + 1 == text.size();
    const std::string_view line = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    const std::optional<std::string_view> body = end == std::string_view::npos ? std::nullopt : verified_body(line);
    std::optional<TaskOutcome> outcome = body ? decode_outcome(*body) : std::nullopt;
    if (outcome && outcome->abandoned) outcome.reset();  // never journaled: the line was altered
    if (!outcome) {
      if (last) {
        contents.torn_tail = true;
        break;
      }
      throw JournalError(fmt::format("{}: line {} is damaged (checksum or format) and is not the last line: the journal "
                                     "was altered; move it away to start afresh",
                                     source, line_number));
    }
    if (outcome->index >= header->tasks || outcome->index % header->shard.count != header->shard.index) {
      throw JournalError(fmt::format("{}: line {} records task {}, which is not in the journal's task list of {} (shard {})",
                                     source, line_number, outcome->index, header->tasks, to_string(header->shard)));
    }
    outcome->resumed = true;
    const auto [where, inserted] = line_of_index.emplace(outcome->index, line_number);
    if (inserted) {
      contents.outcomes.push_back(std::move(*outcome));
    } else {
      auto previous = std::find_if(contents.outcomes.begin(), contents.outcomes.end(),
                                   [&](const TaskOutcome& o) { return o.index == outcome->index; });
      if (previous->ok || previous->key != outcome->key) {
        throw JournalError(fmt::format("{}: task {} is journaled twice (lines {} and {}): did two runs write into this "
                                       "journal at once?",
                                       source, outcome->index, where->second, line_number));
      }
      *previous = std::move(*outcome);  // a retry of a failed task supersedes the failure
      where->second = line_number;
    }
    contents.intact_bytes = end + 1;
    start = end + 1;
  }
  return contents;
}

JournalContents read_journal(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw JournalError(fmt::format("{}: cannot be read", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  std::optional<JournalContents> contents = parse_journal(text.str(), file.string());
  if (!contents) throw JournalError(fmt::format("{}: not a journal (no complete header line)", file.string()));
  return std::move(*contents);
}

}  // namespace ffrf::distributed
