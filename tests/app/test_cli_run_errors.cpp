// End-to-end: bad input to `ffrf run` and `ffrf compare` — a missing body or key, a zero or
// negative mass, length or stiffness, a boom angle outside (0°, 90°), a hull that would sink, an
// unknown integrator or boom model, bad numbers, a deck under water at rest — exits 2 with a message
// naming the problem; a solver failure (explicit Runge–Kutta beyond its stability limit) exits 3
// naming the failure. Neither leaves a summary.json (the completeness marker) in --out.
#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_run_errors_test {

const std::string kScene = source_file("cases/paper_floating_crane.toml");

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The reference scene without the lines from `first` up to (not including) `end`.
std::string without(const std::string& first, const std::string& end) {
  const std::string text = read_text(kScene);
  const auto a = text.find(first), b = text.find(end, a);
  EXPECT_NE(a, std::string::npos) << first;
  return a == std::string::npos ? text : text.substr(0, a) + text.substr(b);
}

void expect_mentions(const std::string& text, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in:\n" << text;
}

struct BadCase {
  std::string name;
  std::string scene_text;          // empty: the reference scene
  std::string options;             // extra command-line options
  int exit_code;                   // 2 bad input, 3 solver failure
  std::vector<std::string> words;  // what the message on stderr must name
  bool compare = true;             // also drive `ffrf compare` (it has no --boom/--elements)
};

std::ostream& operator<<(std::ostream& out, const BadCase& c) { return out << c.name; }

class CliRunBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(CliRunBadInput, NamedErrorNonZeroExitAndNoSummary) {
  const BadCase& bad = GetParam();
  TempDir dir;
  fs::path scene = kScene;
  if (!bad.scene_text.empty()) {
    scene = dir / "bad crane.toml";
    write_text(scene, bad.scene_text);
  }
  for (const std::string command : {"run", "compare"}) {
    if (command == "compare" && !bad.compare) continue;
    const fs::path out = dir / (command + " out");
    const std::string duration = bad.options.find("--duration") == std::string::npos ? " --duration 2 " : " ";
    const RunResult r = run_ffrf(command + " '" + scene.string() + "'" + duration + bad.options + " --out '" +
                                     out.string() + "'",
                                 dir.path());
    EXPECT_EQ(r.exit_code, bad.exit_code) << command << "\n" << r.err;
    expect_mentions(r.err, bad.words);
    EXPECT_FALSE(fs::exists(out / "summary.json")) << command;
    EXPECT_FALSE(fs::exists(out / "timeseries.csv")) << command;
  }
}

std::vector<BadCase> bad_cases() {
  const std::string text = read_text(kScene);
  return {
      {"missing_body", without("[cargo]", "[wire]"), "", 2, {"missing section [cargo]"}},
      {"missing_key", replaced(text, "stiffness = 2.0e8", "# no stiffness"), "", 2, {"wire.stiffness", "missing key"}},
      {"zero_mass", replaced(text, "mass = 1.3e6 ", "mass = 0.0 "), "", 2, {"cargo.mass = 0.0", "valid range [0.001, 100000] t"}},
      {"negative_length", replaced(text, "length = 90.0 ", "length = -90.0 "), "", 2,
       {"hull.length = -90.0", "valid range [1, 1000] m"}},
      {"zero_stiffness", replaced(text, "stiffness = 2.0e8 ", "stiffness = 0 "), "", 2,
       {"wire.stiffness = 0", "valid range [1, 1e+12] N/m"}},
      {"boom_angle_95_deg", replaced(text, "angle = \"60 deg\"", "angle = \"95 deg\""), "", 2,
       {"boom.angle = \"95 deg\"", "valid range (0, 90)"}},
      {"hull_would_sink", replaced(text, "mass = 12.6e6 ", "mass = 1e9 "), "", 2, {"hull.mass", "sink"}},
      {"not_a_crane", read_text(source_file("cases/cantilever.toml")), "", 2, {"not a crane scene", "[hull]"}},
      {"unknown_integrator", "", "--integrator rk4", 2, {"--integrator rk4", "ida", "cvode"}},
      {"unknown_boom", "", "--boom elastic", 2, {"--boom elastic", "rigid|nodal|modal"}, false},
      {"zero_elements", "", "--elements 0", 2, {"--elements 0", "valid range [1, 10000]"}, false},
      {"too_many_modes", "", "--boom modal --elements 2 --modes 6", 2, {"--modes 6", "valid range [1, 5]"}, false},
      {"zero_rtol", "", "--rtol 0", 2, {"--rtol 0", "valid range [1e-12, 0.1]"}},
      {"atol_above_one", "", "--atol 1.5", 2, {"--atol 1.5", "valid range [1e-12, 0.1]"}},
      {"negative_duration", "", "--duration -1", 2, {"--duration -1", "valid range"}},
      {"generalized_alpha_without_step", "", "--integrator generalized-alpha", 2, {"generalized-alpha", "--step"}},
      // 14 000 t of cargo on the 95 m outreach still floats (the sink check passes), but no trim
      // balances its moment: the bow deck would go under. Named before KINSOL is tried.
      {"deck_under_water", replaced(text, "mass = 1.3e6 ", "mass = 14.0e6 "), "", 2,
       {"cargo.mass = 14.0e6", "the deck would be under water at rest"}},
      // Tolerances below what the integrators resolve are refused before they crawl.
      {"ida_too_much_accuracy", "", "--integrator ida --rtol 1e-20 --atol 1e-20", 2,
       {"--rtol 1e-20", "valid range [1e-12, 0.1]"}},
      // A solver failure: explicit Runge–Kutta far beyond its stability limit.
      {"explicit_instability", "", "--integrator arkode --step 0.05 --elements 2", 3,
       {"solver failure (explicit instability)", "ARKODE"}, false},
  };
}

INSTANTIATE_TEST_SUITE_P(Cases, CliRunBadInput, ::testing::ValuesIn(bad_cases()),
                         [](const ::testing::TestParamInfo<BadCase>& case_info) { return case_info.param.name; });

TEST(CliRunBadInput, SolverFailureRemovesTheOldCompletenessMarker) {
  TempDir dir;
  const fs::path out = dir / "out";
  ASSERT_EQ(run_ffrf("run " + kScene + " --elements 2 --duration 1 --out '" + out.string() + "'", dir.path()).exit_code, 0);
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  const RunResult r =
      run_ffrf("run " + kScene + " --integrator arkode --step 0.05 --elements 2 --out '" + out.string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_FALSE(fs::exists(out / "summary.json")) << "the old results no longer pose as this run's";
}

}  // namespace cli_run_errors_test
}  // namespace ffrf::test
