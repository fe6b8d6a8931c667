// End-to-end tests of `ffrf recommend` and of `ffrf run`'s modelling warnings: what the
// command line does — the files and the JSON it writes, a run line that reproduces the chosen model,
// bad options named, the warnings on stderr with their numbers. The physics of the recommendation
// is tested on the study itself (tests/study/test_recommend.cpp).
#include <gtest/gtest.h>

#include <string>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace {

const std::string kCrane = source_file("cases/paper_floating_crane.toml");

const Json& candidate(const Json& j, const std::string& key) {
  return j["candidates"][static_cast<std::size_t>(j[key].number)];
}

TEST(CliRecommend, WritesTheDecisionAndARunLineThatReproducesTheChosenModel) {
  TempDir dir;
  const fs::path out = dir / "recommend";
  const RunResult r = run_ffrf("recommend '" + kCrane + "' --tolerance 1% --duration 40 --json --out '" + out.string() + "'",
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = JsonParser(r.out).parse();
  EXPECT_EQ(read_text(out / "recommendation.json"), r.out) << "--json prints recommendation.json";
  EXPECT_NE(read_text(out / "recommendation.md").find("## Decision"), std::string::npos);
  const Json& chosen = candidate(j, "chosen");
  EXPECT_EQ(chosen["status"].text, "passed");
  EXPECT_NE(j["decision"].text.find("Recommended"), std::string::npos);
  // The `ffrf run` line names the chosen model and runs.
  const std::string line = j["run_command"].text;
  EXPECT_NE(line.find("--boom " + chosen["boom"].text), std::string::npos) << line;
  EXPECT_NE(line.find("--stiffening " + chosen["stiffening"].text), std::string::npos) << line;
  const RunResult run = run_ffrf(line.substr(std::string("ffrf ").size()) + " --json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << line << "\n" << run.err;
  EXPECT_EQ(JsonParser(run.out).parse()["model"].text, chosen["model"].text);
}

TEST(CliRecommend, BadInputNamesTheOption) {
  TempDir dir;
  RunResult r = run_ffrf("recommend '" + kCrane + "' --tolerance 150%", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--tolerance 150%"), std::string::npos) << r.err;
  r = run_ffrf("recommend '" + kCrane + "' --outputs cargo_heave,hook_speed", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("hook_speed"), std::string::npos) << r.err;
}

// `ffrf run` warns when a model is below what the scene needs, with numbers that follow by hand, and
// notes quietly when it is far above. Reference scene: (ρA g L + m g) sin 60° / (π²EI/4L²) = 0.052;
// one clamped–free mode carries 12/(β1L)⁴ = 0.971 of the tip's static flexibility (misses 0.029);
// spin-up at 4 rad/s: Ω²/ω1² = 16/3.798² = 1.1.
TEST(CliRunWarnings, UnderModelledBoomsAreNamedWithTheirNumbersOverModelledQuietly) {
  TempDir dir;
  const auto warnings = [&](const std::string& args) { return run_ffrf("run " + args + " --duration 1", dir.path()); };
  const RunResult rigid = warnings("'" + kCrane + "' --boom rigid");
  EXPECT_EQ(rigid.exit_code, 0) << rigid.err;
  EXPECT_NE(rigid.err.find("warning: modelled below need: rigid boom"), std::string::npos) << rigid.err;

  const RunResult one_mode = warnings("'" + kCrane + "' --boom modal --modes 1 --no-static-modes");
  EXPECT_NE(one_mode.err.find("no static correction modes under the tip load: the 1 vibration modes miss 0.029"),
            std::string::npos) << one_mode.err;
  EXPECT_NE(one_mode.err.find("compression is 0.052 of its Euler load"), std::string::npos) << one_mode.err;

  const RunResult spin = warnings("'" + source_file("cases/spin_up_beam.toml") + "' --stiffening none");
  EXPECT_NE(spin.err.find("centrifugal stiffening off at high spin: Ω²/ω1² = 1.1 (the linear boom diverges)"),
            std::string::npos) << spin.err;

  const RunResult adequate = warnings("'" + kCrane + "' --boom modal --modes 2 --static-modes --stiffening static --json");
  EXPECT_EQ(adequate.exit_code, 0) << adequate.err;
  EXPECT_EQ(adequate.err.find("warning:"), std::string::npos) << adequate.err;
  const Json quiet = JsonParser(adequate.out).parse();
  EXPECT_TRUE(quiet["model_warnings"]["below"].items.empty());

  const RunResult fine_mesh = warnings("'" + kCrane + "' --elements 32 --stiffening static --json");
  EXPECT_EQ(fine_mesh.err.find("warning:"), std::string::npos) << fine_mesh.err;
  EXPECT_NE(fine_mesh.err.find("note: modelled above need: nodal N=32"), std::string::npos) << fine_mesh.err;
  const Json above = JsonParser(fine_mesh.out).parse();
  EXPECT_EQ(above["model_warnings"]["above"].items.size(), 1u);
  EXPECT_NEAR(above["model_warnings"]["tolerance"].number, 0.01, 1e-15);
}

}  // namespace
}  // namespace ffrf::test
