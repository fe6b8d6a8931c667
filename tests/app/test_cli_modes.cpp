// End-to-end: `ffrf modes` results. The cantilever's bending frequencies from --json against the
// Euler–Bernoulli values computed here; free–free rigid modes; --out files and PNG charts; a
// failed run leaves no summary.json.
#include <cmath>
#include <numbers>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace {

Json modes_json(const std::string& args, const TempDir& dir) {
  const RunResult r = run_ffrf("modes " + args + " --json", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return JsonParser(r.out).parse();
}

// f = (βL)² / (2π L²) · √(EI / ρA) for the cantilever of cases/cantilever.toml.
double cantilever_frequency(double beta_l) {
  const double length = 10.0, youngs_modulus = 2.1e11, area = 0.01, second_moment = 8.333e-6, density = 7850.0;
  return beta_l * beta_l / (2.0 * std::numbers::pi * length * length) *
         std::sqrt(youngs_modulus * second_moment / (density * area));
}

TEST(CliModes, CantileverBendingFrequenciesMatchEulerBernoulli) {
  TempDir dir;
  const Json json = modes_json(source_file("cases/cantilever.toml") + " --elements 64", dir);
  EXPECT_EQ(json["elements"].number, 64);
  EXPECT_EQ(json["dof"].number, 192);
  EXPECT_EQ(json["solver"].text, "arpack");
  EXPECT_EQ(json["boundary"].text, "clamped-free");
  const double beta_l[] = {1.875104069, 4.694091133, 7.854757438, 10.995540735};
  const Json& modes = json["modes"];
  ASSERT_GE(modes.items.size(), 4u);
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_EQ(modes[j]["kind"].text, "bending");
    EXPECT_EQ(modes[j]["order"].number, static_cast<double>(j + 1));
    const double expected = cantilever_frequency(beta_l[j]);
    EXPECT_NEAR(modes[j]["frequency_hz"].number / expected, 1.0, 1e-6) << "f" << j + 1;
    EXPECT_NEAR(json["frequencies_hz"][j].number, modes[j]["frequency_hz"].number, 0.0);
  }
  for (std::size_t j = 1; j < json["frequencies_hz"].items.size(); ++j) {
    EXPECT_LT(json["frequencies_hz"][j - 1].number, json["frequencies_hz"][j].number);  // ascending
  }
  EXPECT_GE(json["timings_s"]["solve"].number, 0.0);
  EXPECT_GT(json["solver_stats"]["converged"].number, 0.0);
}

TEST(CliModes, FreeFreeFindsThreeRigidModesWithANegativeShift) {
  TempDir dir;
  const Json json = modes_json(source_file("cases/cantilever.toml") + " --elements 64 --boundary free-free", dir);
  EXPECT_LT(json["shift_rad2_per_s2"].number, 0.0);
  EXPECT_TRUE(json["warnings"].items.empty());
  const Json& modes = json["modes"];
  ASSERT_GE(modes.items.size(), 4u);
  for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(modes[j]["kind"].text, "rigid");
  EXPECT_EQ(modes[3]["kind"].text, "bending");
  EXPECT_NEAR(modes[3]["frequency_hz"].number / cantilever_frequency(4.730040745), 1.0, 1e-6);
}

bool is_png(const fs::path& path) {
  const std::string bytes = read_text(path);
  return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

TEST(CliModes, OutWritesCsvJsonAndPngCharts) {
  TempDir dir;
  const fs::path out = dir / "modes out";
  const RunResult r = run_ffrf("modes " + source_file("cases/cantilever.toml") + " --out '" + out.string() + "'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"modes.csv", "mode_shapes_sampled.csv", "frequencies.csv", "frequency_convergence.csv", "summary.json",
                           "mode_shapes.gp", "frequency_convergence.gp"}) {
    EXPECT_GT(fs::file_size(out / name), 0u) << name;
  }
  EXPECT_TRUE(is_png(out / "mode_shapes.png"));
  EXPECT_TRUE(is_png(out / "frequency_convergence.png"));
  EXPECT_EQ(read_text(out / "modes.csv").rfind("x_m,mode1_u_per_sqrtkg,mode1_v_per_sqrtkg,", 0), 0u);
  const Json summary = JsonParser(read_text(out / "summary.json")).parse();
  EXPECT_EQ(summary["convergence"].items.size(), 7u);  // N = 2 ... 128
  EXPECT_EQ(summary["elements"].number, 16);
  // Nothing else is left beside the output directory (no staging directory).
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 3);  // the output directory, stdout.txt, stderr.txt
}

TEST(CliModes, FailedRunLeavesNoSummary) {
  TempDir dir;
  const fs::path out = dir / "out";
  fs::create_directories(out);
  write_text(out / "summary.json", "{}\n");  // a previous run's marker
  // Valid input, but the dense solver refuses 7500 DOFs: the run fails after --out was set up.
  const RunResult r = run_ffrf(
      "modes " + source_file("cases/cantilever.toml") + " --elements 2500 --solver dense --out " + out.string(),
      dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("dense"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(out / "modes.csv"));
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 3);  // out, stdout.txt, stderr.txt: no staging directory left behind
}

}  // namespace
}  // namespace ffrf::test
