// End-to-end tests of `ffrf rao`: the files written, the report's verdict of the
// time-domain check and its exit code when the check fails (a tolerance below the measured
// deviation), the CSV columns with units, the JSON summary. The physics is tested on the study
// itself (tests/study/test_rao.cpp, test_rao_time_domain.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_rao_test {

const std::string kCrane = source_file("cases/paper_floating_crane.toml");

TEST(CliRao, WritesEveryFileAndStatesThePassingVerdict) {
  TempDir dir;
  const fs::path out = dir / "rao";
  const RunResult r = run_ffrf("rao '" + kCrane + "' --periods 5:15:11 --check-time-domain --check-periods 10 --out '" +
                                   out.string() + "'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* file : {"rao_rigid.csv", "rao_nodal_N16.csv", "rao_modal_k2_static_N16.csv", "natural_modes.csv",
                           "time_domain_check.csv", "report.md", "summary.json", "rao_hull.png", "rao_cargo.png",
                           "rao_boom_wire.png", "rao_hull.gp"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  const std::string csv = read_text(out / "rao_nodal_N16.csv");
  EXPECT_EQ(csv.rfind("period_s,angular_frequency_rad_per_s,hull_surge_amplitude_m_per_m,hull_surge_phase_deg", 0), 0u);
  EXPECT_NE(csv.find("wire_tension_amplitude_N_per_m"), std::string::npos);
  const std::string report = read_text(out / "report.md");
  EXPECT_NE(report.find("**PASS**"), std::string::npos) << report;
  EXPECT_NE(report.find("Coupled natural modes"), std::string::npos);
  const Json summary = JsonParser(read_text(out / "summary.json")).parse();
  // header + 11 periods + the refinement's frequencies at the resonance peaks
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 12 + static_cast<long>(summary["models"][1]["added_frequencies"].number));
  EXPECT_EQ(summary["models"][1]["boom_elements"].number, 16.0);  // the scene's boom.elements
  EXPECT_EQ(summary["models"].items.size(), 3u);
  EXPECT_TRUE(summary["time_domain_check"][0]["passed"].flag);
  EXPECT_LT(summary["time_domain_check"][1]["worst_deviation"].number, 0.01);
}

TEST(CliRao, OneModelFromTheOptionsAndAFailedCheckExitsOne) {
  TempDir dir;
  const RunResult r = run_ffrf("rao '" + kCrane + "' --boom modal -k 2 --static-modes --frequencies 0.6283 --check-time-domain "
                                   "--check-periods 10 --tolerance 0.000001 --json", dir.path());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("the time-domain check failed: modal k=2+static (N=16)"), std::string::npos) << r.err;
  const Json summary = JsonParser(r.out).parse();
  ASSERT_EQ(summary["models"].items.size(), 1u);
  EXPECT_FALSE(summary["time_domain_check"][0]["passed"].flag);
}

// A [bem] hull: the files' A(ω), B(ω), X(ω); rigid, nodal and modal side by side with the
// charts, and the time-domain check (convolution radiation) within 1 % — the physics is asserted in
// tests/study/test_rao_bem.cpp; here the command's files, report and exit code.
TEST(CliRao, ABemSceneGivesTheFilesRaosAndPassesItsTimeDomainCheck) {
  TempDir dir;
  const fs::path out = dir / "rao";
  const RunResult r = run_ffrf("rao '" + source_file("cases/bem_barge_crane.toml") +
                                   "' --periods 4:20:17 --check-time-domain --check-wave-height 0.02 --out '" + out.string() + "'",
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The scene's boom.elements = 12, as `ffrf run` builds it.
  for (const char* file : {"rao_rigid.csv", "rao_nodal_N12.csv", "rao_modal_k2_static_N12.csv", "time_domain_check.csv",
                           "report.md", "rao_hull.png", "rao_cargo.png", "rao_boom_wire.png", "resonance_peaks.csv"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  const std::string report = read_text(out / "report.md");
  EXPECT_NE(report.find("**PASS**"), std::string::npos) << report;
  EXPECT_NE(report.find("barge.1"), std::string::npos) << report;
  EXPECT_NE(report.find("RAO (model's radiation)"), std::string::npos) << report;
  const Json summary = JsonParser(read_text(out / "summary.json")).parse();
  EXPECT_EQ(summary["models"][1]["boom_elements"].number, 12.0);
  EXPECT_EQ(summary["models"][2]["boom_elements"].number, 12.0);
  ASSERT_EQ(summary["time_domain_check"].items.size(), 3u);
  for (std::size_t m = 0; m < 3; ++m) EXPECT_LT(summary["time_domain_check"][m]["worst_deviation"].number, 0.01);
}

// Periods beyond the files' band: a named error (scene file, key, file, value, valid range), exit 2,
// nothing written — no silent extrapolation of BEM data.
TEST(CliRao, ABemSceneRefusesPeriodsOutsideItsFiles) {
  TempDir dir;
  const RunResult r = run_ffrf("rao '" + source_file("cases/bem_barge_crane.toml") + "' --periods 0.5:10:5 --out '" +
                                   (dir.path() / "rao").string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bem.radiation_file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(period 0.5 s)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("valid range 0.0418879 … 6.98132 rad/s"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "rao"));
}

// An irregular-sea scene: the frequency domain takes its components one at a time (a regular wave
// replaces the sea), so the RAOs equal those of the same crane in a regular wave.
TEST(CliRao, AnIrregularSceneGivesTheRegularScenesRaos) {
  TempDir dir;
  const RunResult irregular = run_ffrf("rao '" + source_file("cases/irregular_sea_crane.toml") +
                                           "' --boom rigid --frequencies 0.6283 --json", dir.path());
  const RunResult regular = run_ffrf("rao '" + kCrane + "' --boom rigid --frequencies 0.6283 --json", dir.path());
  ASSERT_EQ(irregular.exit_code, 0) << irregular.err;
  ASSERT_EQ(regular.exit_code, 0) << regular.err;
  const Json a = JsonParser(irregular.out).parse();
  const Json b = JsonParser(regular.out).parse();
  for (const char* output : {"hull_heave", "hull_pitch", "cargo_heave"}) {
    const double irregular_amplitude = a["models"][0]["rao"][output]["amplitude"][0].number;
    EXPECT_GT(irregular_amplitude, 0.0) << output;
    EXPECT_NEAR(irregular_amplitude, b["models"][0]["rao"][output]["amplitude"][0].number, 1e-9 * irregular_amplitude)
        << output;
  }
}

// The resonance peaks refined, the natural periods marked on the charts, and a sea spectrum given on
// the command line: drawn on the charts' second axis, its significant responses in the report.
TEST(CliRao, MarksTheNaturalPeriodsAndOverlaysTheSea) {
  TempDir dir;
  const fs::path out = dir / "rao";
  const RunResult r = run_ffrf("rao '" + kCrane + "' --boom rigid --spectrum jonswap:1.5:9 --out '" + out.string() + "'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("significant responses in JONSWAP Hs 1.5 m, Tp 9 s, γ 3.3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frequencies added"), std::string::npos) << r.out;
  const Json summary = JsonParser(read_text(out / "summary.json")).parse();
  const std::string script = read_text(out / "rao_cargo.gp");
  int marked = 0;
  for (const auto& mode : summary["models"][0]["natural_modes"].items) {
    const double period = mode["period_s"].number, zeta = mode["damping_ratio"].number;
    if (period < 3.0 || period > 30.0 || zeta <= 0.0 || zeta >= std::sqrt(0.5)) continue;
    char number[32];
    std::snprintf(number, sizeof number, "%.4g", period);
    const std::string label = mode["dominant"].text + " " + number + " s";
    EXPECT_NE(script.find(label), std::string::npos) << label << "\n" << script;
    ++marked;
  }
  EXPECT_GE(marked, 3);
  EXPECT_NE(script.find("'sea_spectrum.csv' skip 1 using 1:3 axes x1y2"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "sea_spectrum.csv"));
  EXPECT_TRUE(fs::exists(out / "resonance_peaks.csv"));
  EXPECT_GT(summary["models"][0]["significant_response"]["cargo_heave"]["value"].number, 0.0);
  EXPECT_GT(summary["models"][0]["added_frequencies"].number, 0.0);
  EXPECT_NE(read_text(out / "report.md").find("## In the sea"), std::string::npos);
  const RunResult bad = run_ffrf("rao '" + kCrane + "' --spectrum jonswap:1.5", dir.path());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--spectrum jonswap:1.5: malformed"), std::string::npos) << bad.err;
}

}  // namespace cli_rao_test
}  // namespace ffrf::test
