// The journal: escaping round trips, appended lines read back, a torn last line ignored and cut
// off, a damaged middle line refused, a journal of another task list, settings or shard refused
// with the difference named, a second run on the same journal refused, a retry superseding a
// failure. Torn lines are made by hand (bytes cut off), as a kill during a write leaves them.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "child_process.hpp"
#include "distributed/errors.hpp"
#include "distributed/journal.hpp"
#include "distributed/text_fields.hpp"
#include "scratch_directory.hpp"

namespace ffrf::distributed {
namespace {

using test::read_text;
using test::ScratchDirectory;

TaskOutcome outcome(std::size_t index, bool ok, std::string text) {
  TaskOutcome o;
  o.index = index;
  o.key = "key-" + std::to_string(index);
  o.ok = ok;
  (ok ? o.record : o.error) = std::move(text);
  o.wall_seconds = 0.25;
  o.rank = 2;
  return o;
}

JournalHeader header(std::size_t tasks = 10, Shard shard = {}) { return {"unit test", 0x1234, tasks, 0xabcd, shard}; }

void append_bytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::app) << bytes;
}

std::string journal_error(const std::function<void()>& action) {
  try {
    action();
  } catch (const JournalError& error) {
    return error.what();
  }
  return "no JournalError";
}

TEST(TextFields, AnyByteSurvivesTheRoundTrip) {
  const std::string nasty = "tab\there, newline\nthere, back\\slash, cr\r, \\t literal";
  EXPECT_EQ(escape_field(nasty).find_first_of("\t\n\r"), std::string::npos);
  EXPECT_EQ(unescape_field(escape_field(nasty)), nasty);
  const auto fields = split_fields(join_fields({nasty, "", "x"}));
  ASSERT_TRUE(fields);
  EXPECT_EQ(*fields, (std::vector<std::string>{nasty, "", "x"}));
  EXPECT_FALSE(unescape_field("ends with \\"));
  EXPECT_FALSE(unescape_field("unknown \\q"));
}

TEST(Outcome, EncodeDecodeKeepsResultsAndMessages) {
  const TaskOutcome ok = outcome(3, true, "1,2,\"three\"\twith tab");
  const TaskOutcome failed = outcome(4, false, "solver failed\nat t = 2 s");
  for (const TaskOutcome& original : {ok, failed}) {
    const std::optional<TaskOutcome> back = decode_outcome(encode_outcome(original));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->index, original.index);
    EXPECT_EQ(back->key, original.key);
    EXPECT_EQ(back->ok, original.ok);
    EXPECT_EQ(back->record, original.record);
    EXPECT_EQ(back->error, original.error);
    EXPECT_EQ(back->rank, 2);
    EXPECT_DOUBLE_EQ(back->wall_seconds, 0.25);
  }
  EXPECT_FALSE(decode_outcome("ok\t1\tkey"));
  EXPECT_FALSE(decode_outcome("maybe\t1\tkey\trecord\t0.1\t0"));
}

TEST(Journal, AppendedOutcomesAreReadBackByTheNextRun) {
  ScratchDirectory dir;
  const auto file = dir / "journal.tsv";
  {
    Journal journal(file, header());
    EXPECT_TRUE(journal.previous().empty());
    journal.append(outcome(0, true, "a"));
    journal.append(outcome(7, false, "boom"));
    journal.append(outcome(2, true, "c\td"));
  }
  Journal again(file, header());
  ASSERT_EQ(again.previous().size(), 3u);
  EXPECT_EQ(again.previous()[1].index, 7u);
  EXPECT_EQ(again.previous()[1].error, "boom");
  EXPECT_EQ(again.previous()[2].record, "c\td");
  EXPECT_TRUE(again.previous()[0].resumed);
  EXPECT_FALSE(again.repaired_torn_tail());
}

TEST(Journal, ATornLastLineIsIgnoredAndCutOff) {
  ScratchDirectory dir;
  const auto file = dir / "journal.tsv";
  {
    Journal journal(file, header());
    journal.append(outcome(0, true, "a"));
    journal.append(outcome(1, true, "b"));
  }
  const std::string intact = read_text(file);
  const std::string next = outcome_line(outcome(2, true, "c"));
  append_bytes(file, next.substr(0, next.size() / 2));  // a kill in the middle of the write
  {
    Journal journal(file, header());
    EXPECT_TRUE(journal.repaired_torn_tail());
    ASSERT_EQ(journal.previous().size(), 2u);
    EXPECT_EQ(read_text(file), intact);  // the torn bytes are gone
    journal.append(outcome(2, true, "c"));
  }
  EXPECT_EQ(read_text(file), intact + next);
  // A complete last line whose checksum fails (bytes garbled on a crash) is also a torn tail.
  append_bytes(file, outcome_line(outcome(3, true, "d")).replace(5, 1, "X"));
  Journal journal(file, header());
  EXPECT_TRUE(journal.repaired_torn_tail());
  EXPECT_EQ(journal.previous().size(), 3u);
}

TEST(Journal, ADamagedLineBeforeTheLastIsRefused) {
  ScratchDirectory dir;
  const auto file = dir / "journal.tsv";
  std::string text = header_line(header()) + outcome_line(outcome(0, true, "a"));
  std::string damaged = outcome_line(outcome(1, true, "b"));
  damaged[damaged.size() / 2] ^= 1;
  text += damaged + outcome_line(outcome(2, true, "c"));
  std::ofstream(file, std::ios::binary) << text;
  const std::string message = journal_error([&] { Journal journal(file, header()); });
  EXPECT_NE(message.find("line 3 is damaged"), std::string::npos) << message;
}

TEST(Journal, AJournalOfAnotherTaskListSettingsOrShardIsRefused) {
  ScratchDirectory dir;
  const auto file = dir / "journal.tsv";
  { Journal journal(file, header()); }
  JournalHeader other_settings = header();
  other_settings.settings_hash = 0x9999;
  EXPECT_NE(journal_error([&] { Journal j(file, other_settings); }).find("made with other settings"), std::string::npos);
  JournalHeader other_list = header(11);
  EXPECT_NE(journal_error([&] { Journal j(file, other_list); }).find("another task list (10 tasks"), std::string::npos);
  EXPECT_NE(journal_error([&] { Journal j(file, header(10, Shard{1, 2})); }).find("made for shard 0/1"), std::string::npos);
  JournalHeader renamed = header();
  renamed.study = "another label";  // the label is for people: not compared
  EXPECT_NO_THROW(Journal j(file, renamed));
}

TEST(Journal, ASecondRunOnTheSameJournalIsRefusedWhileTheFirstLives) {
  ScratchDirectory dir;
  const auto file = dir / "journal.tsv";
  Journal first(file, header());
  EXPECT_NE(journal_error([&] { Journal second(file, header()); }).find("in use by another run"), std::string::npos);
}

TEST(Journal, AHeaderCutShortStartsAfresh) {
  ScratchDirectory dir;
  const auto file = dir / "journal.tsv";
  const std::string line = header_line(header());
  std::ofstream(file, std::ios::binary) << line.substr(0, 10);
  Journal journal(file, header());
  EXPECT_TRUE(journal.previous().empty());
  EXPECT_EQ(read_text(file), line);
}

TEST(Journal, ARetrySupersedesAFailureButASuccessIsNeverJournaledTwice) {
  ScratchDirectory dir;
  const auto file = dir / "journal.tsv";
  std::ofstream(file, std::ios::binary) << header_line(header()) << outcome_line(outcome(1, false, "boom"))
                                        << outcome_line(outcome(1, true, "fine"));
  const JournalContents contents = read_journal(file);
  ASSERT_EQ(contents.outcomes.size(), 1u);
  EXPECT_TRUE(contents.outcomes[0].ok);
  append_bytes(file, outcome_line(outcome(1, true, "again")));
  append_bytes(file, outcome_line(outcome(2, true, "x")));
  EXPECT_NE(journal_error([&] { read_journal(file); }).find("task 1 is journaled twice"), std::string::npos);
}

TEST(Journal, ARecordOutsideTheShardIsRefused) {
  ScratchDirectory dir;
  const auto file = dir / "journal.tsv";
  std::ofstream(file, std::ios::binary) << header_line(header(10, Shard{0, 2})) << outcome_line(outcome(3, true, "x"))
                                        << outcome_line(outcome(4, true, "y"));
  EXPECT_NE(journal_error([&] { read_journal(file); }).find("not in the journal's task list"), std::string::npos);
}

}  // namespace
}  // namespace ffrf::distributed
