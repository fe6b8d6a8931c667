// End-to-end: `ffrf check` and `ffrf modes` on bad scene files and bad command lines. Each bad
// input exits non-zero and its message names the file, the key (or option), the value and the
// valid range.
#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_test {

constexpr const char* kCantilever = R"([boom]
length = 10.0
youngs_modulus = 2.1e11
area = 0.01
second_moment = 8.333e-6
density = 7850.0
elements = 16
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

void expect_mentions(const std::string& text, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in:\n" << text;
}

TEST(CliCheck, ReferenceScenesAreValid) {
  TempDir dir;
  for (const char* scene : {"cases/cantilever.toml", "cases/paper_floating_crane.toml"}) {
    const RunResult r = run_ffrf("check " + source_file(scene), dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("OK"), std::string::npos) << r.out;
  }
}

struct BadScene {
  std::string line;      // the line of kCantilever to replace
  std::string key;       // dotted key expected in the message
  std::string written;   // the new "leaf = value" line
  std::string value;     // the value as it should be shown
  std::string range;     // expected valid range
};

class CliBadScene : public ::testing::TestWithParam<BadScene> {};

TEST_P(CliBadScene, CheckAndModesNameFileKeyValueAndRange) {
  const BadScene& bad = GetParam();
  TempDir dir;
  const fs::path scene = dir / "bad scene.toml";  // a space: the file name must survive quoting
  write_text(scene, replaced(kCantilever, bad.line, bad.written));
  for (const std::string command : {"check", "modes"}) {
    const RunResult r = run_ffrf(command + " '" + scene.string() + "'", dir.path());
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.err;
    expect_mentions(r.err, {scene.string(), bad.key + " = " + bad.value, "valid range " + bad.range});
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadScene,
    ::testing::Values(BadScene{"length = 10.0", "boom.length", "length = 0", "0", "[0.1, 1000] m"},
                      BadScene{"length = 10.0", "boom.length", "length = -10.0", "-10.0", "[0.1, 1000] m"},
                      BadScene{"youngs_modulus = 2.1e11", "boom.youngs_modulus", "youngs_modulus = -2.1e11",
                               "-2.1e11", "[1, 1500] GPa"},
                      BadScene{"area = 0.01", "boom.area", "area = 0.0", "0.0", "[1e-06, 100] m^2"},
                      BadScene{"second_moment = 8.333e-6", "boom.second_moment", "second_moment = 0", "0",
                               "[1e-14, 10000] m^4"},
                      BadScene{"density = 7850.0", "boom.density", "density = -7850", "-7850", "[100, 25000] kg/m^3"},
                      BadScene{"elements = 16", "boom.elements", "elements = 0", "0", "[1, 10000]"},
                      BadScene{"elements = 16", "boom.elements", "elements = -3", "-3", "[1, 10000]"},
                      BadScene{"length = 10.0", "boom.length", "length = \"10 kg\"", "\"10 kg\"", "[0.1, 1000] m"},
                      BadScene{"area = 0.01", "boom.area", "area = nan", "nan", "[1e-06, 100] m^2"}),
    [](const ::testing::TestParamInfo<BadScene>& param_info) {
      // Readable test names from the rewritten line, e.g. "length_m10_0" for "length = -10.0".
      std::string name;
      for (char c : param_info.param.written) {
        if (std::isalnum(static_cast<unsigned char>(c))) name += c;
        else if (c == '-') name += 'm';
        else if (c == '.') name += '_';
      }
      return name + "_" + std::to_string(param_info.index);
    });

TEST(CliCheck, ListsEveryProblemAtOnce) {
  TempDir dir;
  const fs::path scene = dir / "many.toml";
  write_text(scene, replaced(replaced(kCantilever, "length = 10.0", "lenght = 10.0"), "area = 0.01", "area = -1"));
  const RunResult r = run_ffrf("check " + scene.string(), dir.path());
  EXPECT_EQ(r.exit_code, 2);
  expect_mentions(r.err, {"boom.lenght = 10.0: unknown key; did you mean boom.length?", "boom.length: missing key",
                          "boom.area = -1", "3 problems"});
}

TEST(CliCheck, MalformedTomlGivesLineAndColumn) {
  TempDir dir;
  const fs::path scene = dir / "broken.toml";
  write_text(scene, std::string(kCantilever) + "boundary = \"clamped-free\n");
  for (const std::string command : {"check", "modes"}) {
    const RunResult r = run_ffrf(command + " " + scene.string(), dir.path());
    EXPECT_EQ(r.exit_code, 2) << command;
    expect_mentions(r.err, {scene.string() + ":8:", "malformed TOML"});
  }
}

TEST(CliCheck, UnknownBoundaryInTheSceneListsTheChoices) {
  TempDir dir;
  const fs::path scene = dir / "boundary.toml";
  write_text(scene, std::string(kCantilever) + "boundary = \"hinged\"\n");
  const RunResult r = run_ffrf("check " + scene.string(), dir.path());
  EXPECT_EQ(r.exit_code, 2);
  expect_mentions(r.err, {scene.string(), "boom.boundary = \"hinged\"", "clamped-free, free-free, pinned-pinned"});
}

TEST(CliCheck, MissingFile) {
  TempDir dir;
  const RunResult r = run_ffrf("check " + (dir / "nope.toml").string(), dir.path());
  EXPECT_EQ(r.exit_code, 2);
  expect_mentions(r.err, {(dir / "nope.toml").string(), "cannot open"});
}

TEST(CliModes, TooManyModesNamesTheDofCount) {
  TempDir dir;
  const RunResult r = run_ffrf("modes " + source_file("cases/cantilever.toml") + " --elements 64 --modes 500", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  expect_mentions(r.err, {"--modes 500", "192 free DOFs", "N = 64", "clamped-free", "valid range [1, 191]"});
}

TEST(CliModes, BadElementAndModeCounts) {
  TempDir dir;
  const std::string scene = source_file("cases/cantilever.toml");
  for (const std::string option : {"--elements 0", "--elements -2", "--modes 0"}) {
    const RunResult r = run_ffrf("modes " + scene + " " + option, dir.path());
    EXPECT_EQ(r.exit_code, 2) << option;
    expect_mentions(r.err, {option, "valid range [1, "});
  }
}

TEST(CliModes, UnknownBoundaryAndSolverListTheChoices) {
  TempDir dir;
  const std::string scene = source_file("cases/cantilever.toml");
  RunResult r = run_ffrf("modes " + scene + " --boundary clamped", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  expect_mentions(r.err, {"--boundary clamped", "clamped-free|free-free|pinned-pinned"});
  r = run_ffrf("modes " + scene + " --solver lapack", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  expect_mentions(r.err, {"--solver lapack", "arpack|dense|spectra"});
}

TEST(CliModes, UnknownOptionIsAnError) {
  TempDir dir;
  const RunResult r = run_ffrf("modes " + source_file("cases/cantilever.toml") + " --frobnicate", dir.path());
  EXPECT_NE(r.exit_code, 0);
  expect_mentions(r.err, {"--frobnicate"});
  EXPECT_NE(run_ffrf("", dir.path()).exit_code, 0);  // a subcommand is required
}

}  // namespace cli_test
}  // namespace ffrf::test
