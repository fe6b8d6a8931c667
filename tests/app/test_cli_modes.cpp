// End-to-end: what `ffrf modes` writes. --json and --out files and PNG charts (the JSON's
// frequencies are the analysis's: tests/study/test_modes.cpp checks them against Euler–Bernoulli
// and the published rotating cantilever); a failed run leaves no summary.json; the tables show an
// unstable mode by its growth rate, never NaN; the Campbell CSV has a row per spin with the
// documented columns; a prestress past the Euler load is reported as buckled; bad values exit 2
// naming the option and value.
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_modes_test {

bool is_png(const fs::path& path) {
  const std::string bytes = read_text(path);
  return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

// A number as text with round-trip precision.
std::string fmt_number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

Json modes_json(const std::string& args, const TempDir& dir) {
  const RunResult r = run_ffrf("modes " + args + " --json", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return JsonParser(r.out).parse();
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

// The spin-up beam (L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m², ρA = 1.2 kg/m), N = 32, clamped-free.
constexpr double spin_length = 10.0, spin_ei = 1.4e4, spin_rho_a = 1.2;
const double spin_scale = std::sqrt(spin_ei / (spin_rho_a * std::pow(spin_length, 4)));  // ω = ω̄ · scale [rad/s]
constexpr double beta1 = 1.875104069;

fs::path write_spin_scene(const TempDir& dir) {
  const fs::path path = dir / "spin_up_beam.toml";
  write_text(path,
             "[scene]\nname = \"spin-up beam\"\ndescription = \"test-local copy of the spin-up beam\"\n\n"
             "[boom]\nlength = 10.0\nyoungs_modulus = 7.0e10\narea = 4.0e-4\nsecond_moment = 2.0e-7\nmass_per_length = 1.2\n"
             "elements = 32\nboundary = \"clamped-free\"\n");
  return path;
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

TEST(CliModesSpin, TableShowsUnstableModesWithGrowthRateNeverNan) {
  TempDir dir;
  const RunResult r = run_ffrf("modes " + write_spin_scene(dir).string() + " --spin 30", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("unstable, growth rate"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("omega series [rad/s]"), std::string::npos);
}

TEST(CliModes, JsonListsTheModesAscending) {
  TempDir dir;
  const Json json = modes_json(source_file("cases/cantilever.toml") + " --elements 64", dir);
  EXPECT_EQ(json["elements"].number, 64);
  EXPECT_EQ(json["dof"].number, 192);
  EXPECT_EQ(json["solver"].text, "arpack");
  EXPECT_EQ(json["boundary"].text, "clamped-free");
  ASSERT_GE(json["modes"].items.size(), 4u);
  EXPECT_EQ(json["modes"][0]["kind"].text, "bending");
  for (std::size_t j = 1; j < json["frequencies_hz"].items.size(); ++j) {
    EXPECT_LT(json["frequencies_hz"][j - 1].number, json["frequencies_hz"][j].number);
    EXPECT_EQ(json["frequencies_hz"][j].number, json["modes"][j]["frequency_hz"].number);
  }
}

TEST(CliModesSpin, AxialForcePastTheEulerLoadIsReportedBuckled) {
  TempDir dir;
  const double critical = std::numbers::pi * std::numbers::pi * spin_ei / (4.0 * spin_length * spin_length);
  const RunResult r = run_ffrf("modes " + write_spin_scene(dir).string() + " --axial-force " + fmt_number(-1.2 * critical), dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("BUCKLED"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("buckled"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("unstable, growth rate"), std::string::npos) << r.out;
}

TEST(CliModesSpin, CampbellCsvMatchesPublishedRotatingCantilever) {
  TempDir dir;
  const fs::path out = dir / "campbell";
  // Five speeds 0 .. 4 Ω̄: rows at Ω̄ = 2 and 4 are exact grid points.
  const RunResult r = run_ffrf("modes " + write_spin_scene(dir).string() + " --spin-range 0:" +
                                   fmt_number(4.0 * spin_scale) + ":5 --out '" + out.string() + "'",
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(is_png(out / "campbell.png"));
  EXPECT_GT(fs::file_size(out / "campbell.gp"), 0u);
  std::istringstream csv(read_text(out / "campbell.csv"));
  std::string line;
  std::getline(csv, line);
  const auto header = split_csv_line(line);
  const auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    ADD_FAILURE() << "no column " << name;
    return std::size_t{0};
  };
  EXPECT_EQ(header[0], "spin_rad_per_s");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) rows.push_back(split_csv_line(line));
  ASSERT_EQ(rows.size(), 5u);
  const double published[] = {3.5160, 4.1373, 5.5850};  // ω̄_flap at Ω̄ = 0, 2, 4
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& row = rows[2 * k];
    const double spin_bar = 2.0 * static_cast<double>(k);
    EXPECT_NEAR(std::stod(row[0]) / spin_scale, spin_bar, 1e-9);
    const double expected = std::sqrt(published[k] * published[k] - spin_bar * spin_bar) * spin_scale;
    EXPECT_NEAR(std::stod(row[column("mode1_series_rad_per_s")]) / expected, 1.0, 1e-4) << "Omega_bar " << spin_bar;
    EXPECT_NEAR(std::stod(row[column("mode1_stiffened_rad_per_s")]) / expected, 1.0, 1e-4) << "Omega_bar " << spin_bar;
  }
  // At Ω̄ = 4 the unstiffened first mode diverges: no frequency, growth rate √(Ω² − ω₀²).
  const double omega0 = beta1 * beta1 * spin_scale, spin = 4.0 * spin_scale;
  EXPECT_EQ(rows[4][column("mode1_unstiffened_rad_per_s")], "");
  EXPECT_NEAR(std::stod(rows[4][column("mode1_unstiffened_growth_per_s")]) / std::sqrt(spin * spin - omega0 * omega0), 1.0, 1e-5);
  const Json summary = JsonParser(read_text(out / "summary.json")).parse();
  EXPECT_EQ(summary["campbell"].items.size(), 5u);
}

struct BadSpinInput {
  std::string args;
  std::string expected;  // in the message
};

class CliModesBadSpin : public ::testing::TestWithParam<BadSpinInput> {};

TEST_P(CliModesBadSpin, ExitsTwoNamingOptionAndValue) {
  TempDir dir;
  const RunResult r = run_ffrf("modes " + write_spin_scene(dir).string() + " " + GetParam().args, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(GetParam().expected), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    Values, CliModesBadSpin,
    ::testing::Values(BadSpinInput{"--spin -1", "--spin -1"}, BadSpinInput{"--spin nan", "--spin nan"},
                      BadSpinInput{"--spin 1x", "valid range [0, 1000] rad/s"},
                      BadSpinInput{"--spin 1e308", "valid range [0, 1000] rad/s"},
                      BadSpinInput{"--spin-range 0:1e308:3", "beyond 1000 rad/s"},
                      BadSpinInput{"--axial-force -1e300", "valid range [-1e+13, 1e+13] N"},
                      BadSpinInput{"--spin-range 1:2", "--spin-range 1:2: malformed"},
                      BadSpinInput{"--spin-range 0:10:1", "count n = 1"},
                      BadSpinInput{"--spin-range 5:2:4", "must exceed the first"},
                      BadSpinInput{"--spin-range 0:nan:3", "'nan' is not a finite number"},
                      BadSpinInput{"--spin-range -1:2:3", "is negative"},
                      BadSpinInput{"--spin 1 --spin-range 0:1:3", "exclude each other"},
                      BadSpinInput{"--spin 1 --boundary free-free", "need a held root"},
                      BadSpinInput{"--axial-force inf", "--axial-force inf"}));

}  // namespace cli_modes_test
}  // namespace ffrf::test
