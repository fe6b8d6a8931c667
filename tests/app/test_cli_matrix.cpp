// The command-line matrix, quick part (label cli): `run`, `baseline record`, `statics`, `rao` and `modes` on every
// kind of shipped scene, with every boom kind where the command takes --boom (tests/app/cli_matrix.hpp
// says what a complete output directory is). The studies that run many models (compare, sweep,
// stability, recommend, operability) are in test_cli_matrix_slow.cpp (label slow).
#include "cli_matrix.hpp"

namespace ffrf::test {
namespace cli_matrix_test {

std::vector<MatrixCell> quick_cells() {
  std::vector<MatrixCell> cells;
  // run and baseline record take --boom: every scene with each boom kind (a rigid boom leaves out the
  // tip-deflection charts: the hub scene, which has only those, then draws none).
  add_cells(cells, "run", true, "--duration 2");
  add_cells(cells, "baseline record", true, "--duration 2", {}, true);
  // statics takes --boom and writes statics.json: every scene with each boom kind.
  add_cells(cells, "statics", true, "");
  // rao takes --boom; a hub has no water and no waves, so the frequency domain refuses it (exit 2).
  add_cells(cells, "rao", true, "--periods 5:20:4", {"hub"});
  // modes solves the boom of the scene alone: no boom-model option, every scene once.
  add_cells(cells, "modes", false, "--modes 4");
  return cells;
}

class CliMatrix : public ::testing::TestWithParam<MatrixCell> {};

TEST_P(CliMatrix, ExitsZeroWithACompleteOutput) { run_matrix_cell(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Cells, CliMatrix, ::testing::ValuesIn(quick_cells()),
                         [](const ::testing::TestParamInfo<MatrixCell>& p) { return cell_name(p.param); });

// A gnuplot that answers the terminal query (the real one does) but fails on every script: the run
// keeps its results (exit 0, timeseries.csv, summary.json), each chart is named as failed with
// gnuplot's message and keeps its script, no PNG poses as drawn; the rigid boom's two tip charts are
// left out, not failed (nothing to draw, no script).
TEST(CliCharts, AChartGnuplotFailsOnCostsTheRunNoResults) {
  TempDir dir;
  fs::create_directories(dir / "bin");
  write_text(dir / "bin/gnuplot",
             "#!/bin/sh\n"
             "PATH=${PATH#*:}  # this directory removed: the real gnuplot\n"
             "if [ \"$1\" = -e ]; then exec gnuplot \"$@\"; fi\n"
             "echo \"\\\"$1\\\" line 1: a failure made by the test\" >&2\n"
             "exit 1\n");
  fs::permissions(dir / "bin/gnuplot", fs::perms::owner_all);
  const fs::path out = dir / "out";
  const RunResult run = run_ffrf("run '" + source_file("cases/paper_floating_crane.toml") + "' --boom rigid --duration 2 --out '" +
                                     out.string() + "'",
                                 dir.path(), "PATH='" + (dir / "bin").string() + "':\"$PATH\"");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  expect_complete_output(out, run);
  const Json charts = JsonParser(read_text(out / "summary.json")).parse()["charts"];
  EXPECT_TRUE(charts["drawn"].items.empty());
  ASSERT_EQ(charts["left_out"].items.size(), 2u);
  EXPECT_EQ(charts["left_out"][0]["chart"].text, "tip_transverse.png");
  EXPECT_EQ(charts["left_out"][1]["chart"].text, "tip_axial.png");
  std::vector<std::string> failed;
  for (const Json& c : charts["failed"].items) {
    failed.push_back(c["chart"].text);
    EXPECT_NE(c["reason"].text.find("a failure made by the test"), std::string::npos) << c["reason"].text;
    EXPECT_TRUE(fs::exists(out / (c["chart"].text.substr(0, c["chart"].text.size() - 4) + ".gp")));
  }
  EXPECT_EQ(failed, (std::vector<std::string>{"crane_heave.png", "crane_pitch.png", "cargo_heave.png", "cargo_pitch.png",
                                              "wire_tension.png", "boom_stress.png"}));
  EXPECT_GT(fs::file_size(out / "timeseries.csv"), 0u);
}

}  // namespace cli_matrix_test
}  // namespace ffrf::test
