// The command-line matrix, slow part (label slow): the studies that run many models — compare, sweep,
// stability, recommend, operability — on every kind of shipped scene, with short durations and the
// smallest grids (tests/app/cli_matrix.hpp says what a complete output directory is). None of these
// commands takes --boom: each runs the boom models itself (compare: rigid, nodal and modal against a
// converged reference; sweep: its grid; recommend: its candidates; operability: the cheapest model per
// cell), so each scene is one cell.
#include "cli_matrix.hpp"

namespace ffrf::test {
namespace {

std::vector<MatrixCell> slow_cells() {
  std::vector<MatrixCell> cells;
  add_cells(cells, "compare", false, "--duration 4 --reference-levels 2");
  add_cells(cells, "sweep", false, "--quick --duration 4 --reference-levels 2 --jobs 1");
  add_cells(cells, "stability", false, "--quick");
  add_cells(cells, "recommend", false, "--duration 4 --reference-levels 2");
  // Operability needs a sea to grade and a cargo on a wire: a hub has neither, and is refused (exit 2).
  // 200-s records: a shorter one holds too few wave cycles for a most probable maximum (a failed cell).
  add_cells(cells, "operability", false, "--hs 1:1:1 --tp 8:8:1 --seeds 1 --duration 200 --verify 0 --threads 1", {"hub"});
  return cells;
}

class CliMatrixSlow : public ::testing::TestWithParam<MatrixCell> {};

TEST_P(CliMatrixSlow, ExitsZeroWithACompleteOutput) { run_matrix_cell(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Cells, CliMatrixSlow, ::testing::ValuesIn(slow_cells()),
                         [](const ::testing::TestParamInfo<MatrixCell>& p) { return cell_name(p.param); });

}  // namespace
}  // namespace ffrf::test
