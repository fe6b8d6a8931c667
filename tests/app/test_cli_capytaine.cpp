// End-to-end: a crane on the Capytaine barge (cases/capytaine_barge_crane.toml, the NetCDF fixture of
// tests/hydro/data) runs and gives RAOs. The estimated A∞ is stated before the work (a warning) and in
// the run's provenance; the RAO's long-wave limit checks the dataset's excitation against the box
// hull's own restoring (two independent sources: the BEM forces and the pressure integration).
#include <gtest/gtest.h>

#include <string>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_capytaine_test {

const std::string kScene = source_file("cases/capytaine_barge_crane.toml");

TEST(CliCapytaine, ACraneOnTheCapytaineHullRunsAndSaysHowAInfinityWasObtained) {
  TempDir dir;
  const fs::path out = dir / "run";
  const RunResult r = run_ffrf("run '" + kScene + "' --duration 10 --out '" + out.string() + "'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string all = r.out + r.err;
  EXPECT_NE(all.find("bem.capytaine_file"), std::string::npos) << all;
  EXPECT_NE(all.find("A∞ estimated by Kramers–Kronig from B(ω)"), std::string::npos) << all;
  EXPECT_NE(r.out.find("A∞ estimated (kramers-kronig)"), std::string::npos) << r.out;
  const Json summary = JsonParser(read_text(out / "summary.json")).parse();
  EXPECT_EQ(summary["provenance"]["bem_format"].text, "capytaine");
  EXPECT_EQ(summary["provenance"]["infinite_frequency_added_mass"].text, "estimated: kramers-kronig");
  EXPECT_EQ(summary["provenance"]["excitation"].text, "bem");
}

// At a 100 s wave (kL = 0.04) the barge follows the surface: hull heave RAO 1 within 1 %, from the
// dataset's Froude–Krylov + diffraction force against the box's hydrostatic restoring ρgLB.
TEST(CliCapytaine, RaosOnTheCapytaineHullReachTheLongWaveLimit) {
  TempDir dir;
  const RunResult r = run_ffrf("rao '" + kScene + "' --boom rigid --frequencies 0.0628319,0.785398 --json", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json summary = JsonParser(r.out).parse();
  const Json& rao = summary["models"][0]["rao"];
  EXPECT_NEAR(rao["hull_heave"]["amplitude"][0].number, 1.0, 0.01);
  EXPECT_GT(rao["hull_heave"]["amplitude"][1].number, 0.0);
  EXPECT_GT(rao["hull_pitch"]["amplitude"][1].number, 0.0);
}

// Periods beyond the dataset's frequencies: the error names the key that gave the file.
TEST(CliCapytaine, PeriodsOutsideTheDatasetAreNamedAtItsKey) {
  TempDir dir;
  const RunResult r = run_ffrf("rao '" + kScene + "' --periods 1:10:4 --json", dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bem.capytaine_file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("valid range 0.01 … 4 rad/s"), std::string::npos) << r.err;
}

}  // namespace cli_capytaine_test
}  // namespace ffrf::test
