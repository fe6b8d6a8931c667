// Benchmark of the generalized eigen solve K φ = ω² M φ for the 6 lowest modes of a clamped-free
// steel beam (10 m, N elements, 3N DOFs): ARPACK shift-invert, Spectra shift-invert and the dense
// reference (dense only while n <= 1500). Each timed call includes the factorization of K − σM.
// Two tolerances: 0 (each solver's "machine precision": ε for ARPACK, 1e-14 for Spectra) and a
// common 1e-10. After Google Benchmark's own output, prints one table per tolerance with the
// times and the ratios ARPACK/dense and ARPACK/Spectra (dense does not depend on the tolerance).
#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

#include "fem/assembly.hpp"
#include "modal/eigen_solver.hpp"

namespace {

using ffrf::modal::EigenSolverKind;

constexpr int kModes = 6;
constexpr int kDenseMaxDofs = 1500;
constexpr int kElementCounts[] = {10, 30, 100, 300, 1000, 3000, 10000};
constexpr double kTolerances[] = {0.0, 1e-10};
constexpr EigenSolverKind kSolvers[] = {EigenSolverKind::arpack, EigenSolverKind::spectra, EigenSolverKind::dense};

ffrf::fem::FreeMatrices clamped_free_beam(int element_count) {
  const ffrf::fem::BeamMesh mesh{10.0, element_count, {2.1e11, 0.01, 8.333e-6, 78.5}};
  return ffrf::fem::assemble_free(mesh, ffrf::fem::Boundary::clamped_free);
}

void solve_beam_modes(benchmark::State& state, EigenSolverKind kind, int element_count, double tolerance) {
  const auto beam = clamped_free_beam(element_count);
  const ffrf::modal::EigenRequest request{.nev = kModes, .tolerance = tolerance};
  ffrf::modal::EigenStats stats;
  for (auto _ : state) {
    const auto pairs = ffrf::modal::solve_generalized(beam.stiffness, beam.mass, request, kind);
    benchmark::DoNotOptimize(pairs.eigenvalues.data());
    stats = pairs.stats;
  }
  state.SetLabel(std::string(to_string(kind)));
  state.counters["elements"] = element_count;
  state.counters["tolerance"] = tolerance;
  state.counters["dofs"] = static_cast<double>(beam.stiffness.rows());
  state.counters["op_applications"] = stats.operator_applications;
}

// Collects the wall time per solve [ms] of each (solver, N, tolerance) while the console
// reporter prints.
class TableCollector : public benchmark::ConsoleReporter {
 public:
  // Colours only on a terminal, so that a redirected log stays plain text.
  TableCollector() : ConsoleReporter(isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular) {}

  using Key = std::tuple<std::string, int, double>;
  std::map<Key, double> milliseconds;

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred || run.run_type != Run::RT_Iteration) continue;
      const auto elements = run.counters.find("elements");
      const auto tolerance = run.counters.find("tolerance");
      if (elements == run.counters.end() || tolerance == run.counters.end()) continue;
      const Key key{run.report_label, static_cast<int>(elements->second.value), tolerance->second.value};
      const double time = run.GetAdjustedRealTime();  // in run.time_unit = milliseconds
      const auto [it, inserted] = milliseconds.emplace(key, time);
      if (!inserted) it->second = std::min(it->second, time);
    }
  }

  std::string cell(const Key& key) const {
    const auto it = milliseconds.find(key);
    return it == milliseconds.end() ? std::string("—") : fmt::format("{:.3f}", it->second);
  }
  std::string ratio(const Key& numerator, const Key& denominator) const {
    const auto top = milliseconds.find(numerator);
    const auto bottom = milliseconds.find(denominator);
    if (top == milliseconds.end() || bottom == milliseconds.end()) return "—";
    return fmt::format("{:.3f}", top->second / bottom->second);
  }
};

void print_table(const TableCollector& table, double tolerance) {
  fmt::print("\nEigen solve, {} lowest modes of the clamped-free beam, tolerance {}, wall time per solve [ms]\n\n",
             kModes, tolerance == 0.0 ? std::string("0 (ARPACK ε, Spectra 1e-14)") : fmt::format("{:g}", tolerance));
  fmt::print("| N elements | n DOFs | ARPACK [ms] | Spectra [ms] | dense [ms] | ARPACK/dense | ARPACK/Spectra |\n");
  fmt::print("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const int elements : kElementCounts) {
    const TableCollector::Key arpack{"arpack", elements, tolerance};
    const TableCollector::Key spectra{"spectra", elements, tolerance};
    const TableCollector::Key dense{"dense", elements, 0.0};
    fmt::print("| {} | {} | {} | {} | {} | {} | {} |\n", elements, 3 * elements, table.cell(arpack),
               table.cell(spectra), table.cell(dense), table.ratio(arpack, dense), table.ratio(arpack, spectra));
  }
}

}  // namespace

int main(int argc, char** argv) {
  for (const double tolerance : kTolerances) {
    for (const EigenSolverKind kind : kSolvers) {
      if (kind == EigenSolverKind::dense && tolerance != 0.0) continue;  // dense has no tolerance
      for (const int elements : kElementCounts) {
        if (kind == EigenSolverKind::dense && 3 * elements > kDenseMaxDofs) continue;
        const std::string name = fmt::format("eigen_6_modes/{}/tol:{:g}/N:{}", to_string(kind), tolerance, elements);
        benchmark::RegisterBenchmark(name.c_str(), solve_beam_modes, kind, elements, tolerance)
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  TableCollector table;
  benchmark::RunSpecifiedBenchmarks(&table);
  benchmark::Shutdown();
  for (const double tolerance : kTolerances) print_table(table, tolerance);
  return 0;
}
