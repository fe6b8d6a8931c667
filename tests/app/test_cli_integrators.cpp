// The integrator options on the command line (docs/integrators.md): --formulation/--solver name the
// same pairs as --integrator (the old names keep working: the same run, byte for byte); a pair that
// is not implemented, or both ways at once, is bad input naming the valid pairs; a work limit ends a
// run with the named failure and the options of its remedy.
#include <gtest/gtest.h>

#include <string>

#include "cli_harness.hpp"

namespace cli_integrators_test {

using namespace ffrf::test;

const std::string kCrane = source_file("cases/paper_floating_crane.toml");

TEST(CliIntegrators, FormulationAndSolverNameTheSamePairsAsTheOldNames) {
  TempDir dir;
  const RunResult by_name = run_ffrf("run '" + kCrane + "' --integrator ida --elements 2 --duration 2 --out '" +
                                         (dir / "name").string() + "'",
                                     dir.path());
  ASSERT_EQ(by_name.exit_code, 0) << by_name.err;
  const RunResult by_pair = run_ffrf("run '" + kCrane + "' --formulation index2 --solver bdf --elements 2 --duration 2 --out '" +
                                         (dir / "pair").string() + "'",
                                     dir.path());
  ASSERT_EQ(by_pair.exit_code, 0) << by_pair.err;
  EXPECT_EQ(read_text(dir / "name" / "timeseries.csv"), read_text(dir / "pair" / "timeseries.csv"));
  EXPECT_NE(by_pair.out.find("integrator  ida,"), std::string::npos) << by_pair.out;
}

TEST(CliIntegrators, AnInvalidPairIsRefusedWithTheValidOnes) {
  TempDir dir;
  const RunResult r = run_ffrf("run '" + kCrane + "' --formulation index2 --solver explicit-rk --out '" + (dir / "out").string() + "'",
                               dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--solver explicit-rk: not an implemented integrator with the formulation index2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("minimal × explicit-rk (arkode)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  const RunResult both = run_ffrf("run '" + kCrane + "' --integrator ida --solver bdf --out '" + (dir / "out").string() + "'",
                                  dir.path());
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--integrator ida: names a formulation and a solver: give either the integrator or the formulation"), std::string::npos) << both.err;
}

TEST(CliIntegrators, AWorkLimitEndsTheRunNamingTheFailureAndTheOptions) {
  TempDir dir;
  // Two elements: explicit RK's steps (~5 ms at the stability limit, ~10 per output interval) are not
  // the stiff-boom stop of tests/app/test_cli_explicit_work.cpp, but 120 s need ~20 000 of them.
  const RunResult r = run_ffrf("run '" + kCrane + "' --solver explicit-rk --elements 2 --max-steps 5000 --out '" +
                                   (dir / "out").string() + "'",
                               dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("solver failure (too much work)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("step limit of 5000 steps"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("options: --max-steps, --max-wall-time"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace cli_integrators_test
