// The dropped load (cases/dropped_load.toml) through the program: the commands that failed with
// CVODE's "Root found at and very near t" (CV_ILL_INPUT) — `run` on N = 8 with static stiffening at
// rtol 1e-6 and 1e-8, `compare` and `recommend` with default options — finish, and the wire events
// the root finder located agree with a second method: the sampled tension, which turns from zero
// to positive within one output interval of each located snap time.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_harness.hpp"

namespace cli_dropped_load_test {

using namespace ffrf::test;

std::vector<std::string> split_text(const std::string& text, char separator) {
  std::vector<std::string> parts(1);
  for (const char c : text) {
    if (c == separator) {
      parts.emplace_back();
    } else {
      parts.back() += c;
    }
  }
  return parts;
}

const std::string kScene = source_file("cases/dropped_load.toml");

TEST(CliDroppedLoad, RunLocatesEveryWireEventAtBothTolerances) {
  for (const char* tolerance : {"1e-6", "1e-8"}) {
    TempDir dir;
    const auto out = dir / "run";
    const RunResult r = run_ffrf("run '" + kScene + "' --elements 8 --stiffening static --rtol " + tolerance + " --atol " +
                                     tolerance + " --duration 1 --json --out '" + out.string() + "'",
                                 dir.path());
    ASSERT_EQ(r.exit_code, 0) << tolerance << "\n" << r.err;
    EXPECT_EQ(r.err.find("very near"), std::string::npos) << r.err;
    // Snap times from the located events; the sampled tension: zero while slack, positive once taut.
    std::vector<double> snaps;
    const Json json = JsonParser(r.out).parse();
    for (const Json& detection : json["detections"].items) {
      if (detection["kind"].text == "snap load") snaps.push_back(detection["time_s"].number);
    }
    ASSERT_GE(snaps.size(), 1u) << "the cargo falls onto the slack wire within 1 s";
    const std::vector<std::string> rows = split_text(read_text(out / "timeseries.csv"), '\n');
    const std::vector<std::string> header = split_text(rows.at(0), ',');
    std::size_t tension_column = 0;
    while (tension_column < header.size() && header[tension_column] != "wire_tension_N") ++tension_column;
    ASSERT_LT(tension_column, header.size());
    const double interval = 0.002;  // simulation.output_interval of the scene
    for (const double snap : snaps) {
      double tension_before = -1.0, tension_after = -1.0;
      for (std::size_t k = 1; k < rows.size(); ++k) {
        const std::vector<std::string> cells = split_text(rows[k], ',');
        if (cells.size() != header.size()) continue;
        const double t = std::stod(cells[0]);
        if (t <= snap - interval && t > snap - 2.0 * interval) tension_before = std::stod(cells[tension_column]);
        if (t >= snap + interval && t < snap + 2.0 * interval) tension_after = std::stod(cells[tension_column]);
      }
      EXPECT_EQ(tension_before, 0.0) << "slack one output interval before the located snap at t = " << snap;
      EXPECT_GT(tension_after, 0.0) << "taut one output interval after the located snap at t = " << snap;
    }
  }
}

TEST(CliDroppedLoad, CompareAndRecommendFinishWithDefaultOptions) {
  TempDir dir;
  const RunResult compare = run_ffrf("compare '" + kScene + "' --out '" + (dir / "compare").string() + "'", dir.path());
  EXPECT_EQ(compare.exit_code, 0) << compare.err;
  EXPECT_EQ(compare.err.find("very near"), std::string::npos) << compare.err;
  EXPECT_NE(compare.out.find("verdict"), std::string::npos) << compare.out;
  const RunResult recommend = run_ffrf("recommend '" + kScene + "' --out '" + (dir / "recommend").string() + "'", dir.path());
  EXPECT_EQ(recommend.exit_code, 0) << recommend.err;
  EXPECT_EQ(recommend.err.find("very near"), std::string::npos) << recommend.err;
}

}  // namespace cli_dropped_load_test
