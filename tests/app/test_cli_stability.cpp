// `ffrf stability --quick` end to end: what the command writes (report.md embedding every chart that
// exists, summary.json with one object per experiment that applies to the scene, each cell with its
// status and, for a failure, its kind and time, never NaN text) and bad input exiting 2. The physics
// of each experiment is tested on the study itself (tests/study/test_stability.cpp).
#include <regex>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_stability_test {

TEST(CliStability, DroppedLoadWritesTheReportAndEveryApplicableSection) {
  TempDir dir;
  const fs::path out = dir / "out";
  const RunResult r = run_ffrf("stability '" + source_file("cases/dropped_load.toml") + "' --quick --out '" + out.string() + "'",
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = read_text(out / "report.md");
  const Json summary = JsonParser(read_text(out / "summary.json")).parse();
  EXPECT_EQ(summary["command"].text, "stability");
  EXPECT_TRUE(summary["quick"].flag);
  // A fixed hub with a cargo: explicit steps, drift, wire and buckling; no spin, no BDF-order (damped boom).
  std::vector<std::string> keys;
  for (const auto& [key, section] : summary["sections"].members) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"explicit", "drift", "wire", "buckling"}));
  for (const auto& [key, section] : summary["sections"].members) {
    EXPECT_NE(report.find(section["title"].text), std::string::npos) << key;
    for (const Json& chart : section["charts"].items) {
      EXPECT_TRUE(fs::exists(out / chart.text)) << chart.text;
      EXPECT_NE(report.find("(" + chart.text + ")"), std::string::npos) << chart.text;
    }
    for (const Json& cell : section["cells"].items) {
      EXPECT_FALSE(cell["status"].text.empty()) << key;
      if (!cell["ok"].flag && cell["status"].text == "snap load") {
        EXPECT_GE(cell["time_s"].number, 0.0);
      }
    }
  }
  const std::regex not_a_number("\\b(nan|inf)\\b", std::regex::icase);
  EXPECT_FALSE(std::regex_search(read_text(out / "summary.json"), not_a_number));
  EXPECT_FALSE(std::regex_search(report, not_a_number));
  // The drift chart floors rounding noise at 1e-14 of the boom length (120 m here: 1.2e-12 m) and says so
  // on its axis, instead of spanning the decades of exact zeros' neighbours.
  const std::string drift = read_text(out / "constraint_drift.gp");
  EXPECT_NE(drift.find("floor = 1.2e-12"), std::string::npos) << drift;
  EXPECT_NE(drift.find("1e-14 L: rounding, drawn at that floor"), std::string::npos) << drift;
  EXPECT_NE(drift.find("floored($2)"), std::string::npos) << drift;
}

TEST(CliStability, BadInputExitsTwoNamingTheProblem) {
  TempDir dir;
  const RunResult unknown = run_ffrf("stability '" + source_file("cases/spin_up_beam.toml") + "' --fast", dir.path());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--fast"), std::string::npos) << unknown.err;
  const RunResult missing = run_ffrf("stability '" + (dir / "no_such_scene.toml").string() + "'", dir.path());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no_such_scene.toml"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace cli_stability_test
}  // namespace ffrf::test
