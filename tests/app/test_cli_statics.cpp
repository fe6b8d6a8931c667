// `ffrf statics`: the static equilibrium on its own, on two scenes (the reference crane and the large
// crane with a modal boom). Its numbers are `ffrf run`'s static equilibrium (summary.json's keys) for
// the same model; the text names the offsets, the wire against the cargo's weight, the force balance
// and how it was reached; --out writes statics.json; a scene whose cargo hangs in the water fails by
// that name with the solver-failure exit code.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_harness.hpp"

namespace {

using namespace ffrf::test;

// Every number of run's static_equilibrium block equals statics' (the wall time aside).
void expect_same_statics(const std::string& scene, const std::string& model_options) {
  TempDir dir;
  const RunResult statics = run_ffrf("statics " + source_file(scene) + " " + model_options + " --json", dir.path());
  ASSERT_EQ(statics.exit_code, 0) << statics.err;
  const RunResult run = run_ffrf("run " + source_file(scene) + " " + model_options + " --duration 0.05 --json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json a = JsonParser(statics.out).parse();
  const Json b = JsonParser(run.out).parse();
  EXPECT_EQ(a["command"].text, "statics");
  EXPECT_EQ(a["model"].text, b["model"].text);
  const Json& mine = a["static_equilibrium"];
  const Json& theirs = b["static_equilibrium"];
  int compared = 0;
  for (const auto& [key, value] : mine.members) {
    if (key == "wall_time_s") continue;
    if (value.type == Json::Type::number) {
      EXPECT_EQ(value.number, theirs[key].number) << scene << ": " << key;
      ++compared;
    } else if (value.type == Json::Type::string) {
      EXPECT_EQ(value.text, theirs[key].text) << scene << ": " << key;
    }
  }
  EXPECT_GE(compared, 18) << scene;  // every number of the block (draft, trim, poses, tip, wire, joint, solver)
  // The wire carries the cargo's weight at rest.
  EXPECT_NEAR(mine["wire_tension_N"].number, a["cargo_weight_N"].number, 1e-7 * a["cargo_weight_N"].number);
}

TEST(CliStatics, ReferenceCraneEqualsTheRunsStaticEquilibrium) {
  expect_same_statics("cases/paper_floating_crane.toml", "");
}

TEST(CliStatics, LargeCraneWithAModalBoomEqualsTheRunsStaticEquilibrium) {
  expect_same_statics("cases/large_crane.toml", "--boom modal --modes 2");
}

TEST(CliStatics, TextReportAndOutputDirectory) {
  TempDir dir;
  const RunResult r = run_ffrf("statics " + source_file("cases/large_crane.toml") + " --out '" + (dir / "out").string() + "'",
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* line : {"static equilibrium (nodal N=16", "offsets   from the even keel", "draft", "trim",
                           "G2 at x", "against the cargo's weight", "root moment", "largest out-of-balance force",
                           "Newton from the rest pose", "wrote "}) {
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  }
  EXPECT_EQ(directory_entries(dir / "out"), std::vector<std::string>{"statics.json"});
  EXPECT_NO_THROW(JsonParser(read_text(dir / "out" / "statics.json")).parse());
}

TEST(CliStatics, CargoInTheWaterFailsByName) {
  TempDir dir;
  // The reference scene with a 120 m wire: the cargo's bottom would hang 16 m below still water.
  // The scene check refuses it before any solve (tests/study/test_statics.cpp has the solve's own
  // refusal by name).
  std::string scene = read_text(source_file("cases/paper_floating_crane.toml"));
  const std::string key = "unstretched_length = 20.0";
  scene.replace(scene.find(key), key.size(), "unstretched_length = 120.0");
  write_text(dir / "deep.toml", scene);
  const RunResult r = run_ffrf("statics '" + (dir / "deep.toml").string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;  // the scene check refuses it first (a scene problem)
  EXPECT_NE(r.err.find("in the water"), std::string::npos) << r.err;
}

}  // namespace
