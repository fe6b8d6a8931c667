// End-to-end tests of `ffrf baseline record|check`: the command-line behaviour — exit
// codes (0 pass, 4 regression, 2 bad input), the file written, the verdict naming the quantities
// that moved with their numbers, the model difference reported, bad input named with file, key and
// value. The physics of the check (E × 1.01 against √1.01, determinism) is tested on the study
// itself (tests/study/test_baseline.cpp); the CMake function by tests/app/baseline_project.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_baseline_test {

const std::string kCrane = source_file("cases/paper_floating_crane.toml");

// A short baseline of the reference crane on a coarse boom (past the 20 s wave ramp).
RunResult record(const TempDir& dir, const std::string& scene, const std::string& out, const std::string& extra = "") {
  return run_ffrf("baseline record '" + scene + "' -N 4 --duration 22 --out '" + out + "' " + extra, dir.path());
}

// The reference crane with E × 1.01.
fs::path stiffer_scene(const TempDir& dir) {
  std::string text = read_text(kCrane);
  const std::string from = "youngs_modulus = 2.1e11";
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, from.size(), "youngs_modulus = 2.121e11");
  write_text(dir / "stiffer.toml", text);
  return dir / "stiffer.toml";
}

const Json* deviation(const Json& check, const std::string& channel, const std::string& quantity) {
  for (const Json& d : check["deviations"].items) {
    if (d["channel"].text == channel && d["quantity"].text == quantity) return &d;
  }
  return nullptr;
}

TEST(CliBaseline, RecordThenCheckPassesAndAStifferBoomExitsFourNamingWhatMoved) {
  TempDir dir;
  const std::string base = (dir / "base.json").string();
  const RunResult rec = record(dir, kCrane, base);
  ASSERT_EQ(rec.exit_code, 0) << rec.err;
  EXPECT_NE(rec.out.find("wrote " + base), std::string::npos) << rec.out;
  const Json file = JsonParser(read_text(base)).parse();
  EXPECT_EQ(file["format"].text, "ffrf-baseline");
  EXPECT_EQ(file["format_version"].number, 2.0);
  EXPECT_EQ(file["model"]["elements"].number, 4.0);
  EXPECT_EQ(file["provenance"]["scene"]["path"].text, kCrane);

  const RunResult same = run_ffrf("baseline check '" + kCrane + "' '" + base + "'", dir.path());
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("verdict     PASS"), std::string::npos) << same.out;
  EXPECT_NE(same.out.find("unchanged since the baseline"), std::string::npos) << same.out;

  const fs::path stiffer = stiffer_scene(dir);
  const RunResult moved = run_ffrf("baseline check '" + stiffer.string() + "' '" + base + "'", dir.path());
  EXPECT_EQ(moved.exit_code, 4) << moved.err;
  EXPECT_NE(moved.err.find("regression"), std::string::npos) << moved.err;
  EXPECT_NE(moved.out.find("CHANGED since the baseline"), std::string::npos) << moved.out;
  EXPECT_NE(moved.out.find("verdict     FAIL"), std::string::npos) << moved.out;
  EXPECT_NE(moved.out.find("moved       boom: f1, f2, f3, f4, f5, f6; largest deviation 0.004988"), std::string::npos)
      << moved.out;
  EXPECT_NE(moved.out.find("cargo_heave_m: static"), std::string::npos) << moved.out;

  const RunResult json = run_ffrf("baseline check '" + stiffer.string() + "' '" + base + "' --json", dir.path());
  EXPECT_EQ(json.exit_code, 4);
  const Json check = JsonParser(json.out).parse();
  EXPECT_EQ(check["verdict"].text, "fail");
  EXPECT_TRUE(check["scene"]["changed"].flag);
  const Json* f1 = deviation(check, "boom", "f1");
  ASSERT_NE(f1, nullptr);
  EXPECT_FALSE(f1->operator[]("passed").flag);
  EXPECT_NEAR((*f1)["deviation"].number, std::sqrt(1.01) - 1.0, 1e-9);  // K ∝ E, M unchanged
  EXPECT_EQ((*f1)["tolerance"].number, 1e-6);
}

TEST(CliBaseline, CheckWithAnotherModelReportsTheDifference) {
  TempDir dir;
  const std::string base = (dir / "base.json").string();
  ASSERT_EQ(record(dir, kCrane, base).exit_code, 0);
  const RunResult r = run_ffrf("baseline check '" + kCrane + "' '" + base + "' --boom modal -k 1 --no-static-modes", dir.path());
  EXPECT_NE(r.out.find("DIFFERS from the baseline's"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("boom model: baseline nodal, this run modal"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("model       modal k=1 (N=4)"), std::string::npos) << r.out;
  EXPECT_EQ(r.exit_code, 4) << "one mode without static modes misses the static deflection under the cargo";
}

TEST(CliBaseline, TolerancesFromTheCommandLineDecide) {
  TempDir dir;
  const std::string base = (dir / "base.json").string();
  ASSERT_EQ(record(dir, kCrane, base, "--outputs cargo_heave").exit_code, 0);
  const fs::path stiffer = stiffer_scene(dir);
  const std::string check = "baseline check '" + stiffer.string() + "' '" + base + "'";
  // The boom frequencies move by 0.4988 %, the coupled crane's modes by up to 0.52 % (the damping
  // ratio of its second boom mode) and the cargo by up to a few % of its motion: loose enough
  // tolerances pass, and each override is named in the JSON.
  RunResult r = run_ffrf(check + " --frequency-rtol 0.006 --rtol 0.1 --json", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  r = run_ffrf(check + " --tolerance frequencies=0.006 --tolerance cargo_heave_m=0.1 --tolerance wire_amplification=0.1",
               dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  r = run_ffrf(check + " --tolerance frequencies=0.004 --rtol 0.1", dir.path());
  EXPECT_EQ(r.exit_code, 4) << r.out;
}

TEST(CliBaseline, BadInputIsNamedWithExitTwo) {
  TempDir dir;
  const std::string base = (dir / "base.json").string();
  ASSERT_EQ(record(dir, kCrane, base).exit_code, 0);
  const std::string check = "baseline check '" + kCrane + "' ";

  RunResult r = run_ffrf(check + "'" + (dir / "missing.json").string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find((dir / "missing.json").string() + ": no such baseline file"), std::string::npos) << r.err;

  std::string text = read_text(base);
  text.replace(text.find("\"rtol\": 1e-06"), 13, "\"rtol\": \"tight\"");
  write_text(dir / "bad.json", text);
  r = run_ffrf(check + "'" + (dir / "bad.json").string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.json: model.rtol = \"tight\": not a number"), std::string::npos) << r.err;

  write_text(dir / "truncated.json", read_text(base).substr(0, 100));
  r = run_ffrf(check + "'" + (dir / "truncated.json").string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("truncated.json: not a JSON document"), std::string::npos) << r.err;

  r = run_ffrf(check + "'" + base + "' --tolerance hook_speed_m_per_s=1e-3", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--tolerance hook_speed_m_per_s=0.001: " + base + ": the baseline has no channel or quantity"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("wire_tension_N"), std::string::npos) << "the valid names are listed: " << r.err;

  r = run_ffrf(check + "'" + base + "' --tolerance wire_tension_N", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--tolerance wire_tension_N: not NAME=RELATIVE"), std::string::npos) << r.err;

  r = run_ffrf(check + "'" + base + "' --rtol -1", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--rtol -1: not a tolerance"), std::string::npos) << r.err;

  r = run_ffrf(check + "'" + base + "' --boom stiff", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--boom stiff: unknown boom model"), std::string::npos) << r.err;

  r = run_ffrf("baseline record '" + kCrane + "' --outputs hook_speed --out '" + (dir / "x.json").string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--outputs hook_speed: unknown output 'hook_speed'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.json")) << "nothing written on bad input";

  r = run_ffrf("baseline record '" + kCrane + "' --out '" + (dir / "no_dir" / "x.json").string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("the directory " + (dir / "no_dir").string() + " does not exist"), std::string::npos) << r.err;

  r = run_ffrf("baseline record '" + (dir / "none.toml").string() + "' --out '" + (dir / "x.json").string() + "'", dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir / "x.json"));
}

}  // namespace cli_baseline_test
}  // namespace ffrf::test
