// `--set KEY=VALUE` on every command that reads a scene: a value out of range is refused by every
// one with the key, the value, the valid range and "(--set)", before any work; a run with values set
// is the run of the file with those lines written in it, bit for bit, and records them; a journal
// written with other values is not resumed.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_set_test {

const std::string kPaper = source_file("cases/paper_floating_crane.toml");
const std::string kAngleProblem = "boom.angle = 155 deg (--set): out of range (valid range (0, 90) deg)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(CliSet, EveryCommandRefusesABadValueWithKeyValueRangeAndOrigin) {
  TempDir dir;
  const std::string out = "'" + (dir / "out").string() + "'";
  const std::vector<std::string> commands{
      "check '" + kPaper + "'",
      "modes '" + kPaper + "'",
      "run '" + kPaper + "' --out " + out,
      "statics '" + kPaper + "'",
      "compare '" + kPaper + "' --out " + out,
      "sweep '" + kPaper + "' --out " + out,
      "stability '" + kPaper + "' --out " + out,
      "recommend '" + kPaper + "' --out " + out,
      "rao '" + kPaper + "' --out " + out,
      "operability '" + kPaper + "' --hs 1 --tp 8 --out " + out,
      "baseline record '" + kPaper + "' --out '" + (dir / "base.json").string() + "'",
      "baseline check '" + kPaper + "' '" + source_file("cases/baselines/paper_floating_crane.json") + "'",
  };
  for (const std::string& command : commands) {
    const RunResult r = run_ffrf(command + " --set 'boom.angle=155 deg'", dir.path());
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find(kPaper + ": " + kAngleProblem), std::string::npos) << command << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "out")) << command;
    EXPECT_FALSE(fs::exists(dir / "base.json")) << command;
  }
}

TEST(CliSet, NotKeyEqualsValueAndUnknownKeysAreNamed) {
  TempDir dir;
  RunResult r = run_ffrf("check '" + kPaper + "' --set boom.angle", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set boom.angle: not KEY=VALUE"), std::string::npos) << r.err;
  r = run_ffrf("check '" + kPaper + "' --set 'boom.angel=55 deg' --set hull.draft=5", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("boom.angel = 55 deg (--set): unknown key; did you mean boom.angle?"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("hull.draft = 5 (--set): not a scene key"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 problems"), std::string::npos) << r.err;
}

TEST(CliSet, ARunWithValuesSetIsTheRunOfTheEditedFile) {
  TempDir dir;
  const std::string edited = replaced(replaced(read_text(kPaper), "angle = \"60 deg\"", "angle = \"55 deg\""),
                                      "mass = 1.3e6 ", "mass = \"2400 t\" ");
  write_text(dir / "edited.toml", edited);
  const RunResult by_set = run_ffrf("run '" + kPaper + "' --set 'boom.angle=55 deg' --set 'cargo.mass=2400 t' --boom modal "
                                    "--duration 20 --out '" + (dir / "set").string() + "'",
                                    dir.path());
  ASSERT_EQ(by_set.exit_code, 0) << by_set.err;
  const RunResult by_file = run_ffrf("run '" + (dir / "edited.toml").string() + "' --boom modal --duration 20 --out '" +
                                         (dir / "file").string() + "'",
                                     dir.path());
  ASSERT_EQ(by_file.exit_code, 0) << by_file.err;
  EXPECT_EQ(read_text(dir / "set" / "timeseries.csv"), read_text(dir / "file" / "timeseries.csv"));
  const std::string summary = read_text(dir / "set" / "summary.json");
  EXPECT_NE(summary.find("\"scene_overrides\": [\n      \"boom.angle=55 deg\",\n      \"cargo.mass=2400 t\"\n    ]"),
            std::string::npos)
      << summary;
  EXPECT_EQ(read_text(dir / "file" / "summary.json").find("scene_overrides"), std::string::npos);
}

TEST(CliSet, AJournalOfOtherValuesIsNotResumed) {
  TempDir dir;
  const std::string out = (dir / "sweep").string();
  const RunResult first = run_ffrf("sweep '" + kPaper + "' --duration 4 --jobs 2 --set boom.elements=4 --out '" + out + "'",
                                   dir.path());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const RunResult other = run_ffrf("sweep '" + kPaper + "' --duration 4 --jobs 2 --set boom.elements=8 --out '" + out + "'",
                                   dir.path());
  EXPECT_EQ(other.exit_code, 2) << other.err;
  EXPECT_NE(other.err.find("journal"), std::string::npos) << other.err;
}

}  // namespace cli_set_test
}  // namespace ffrf::test
