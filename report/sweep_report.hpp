// The outputs of `ffrf sweep` from its CSV rows (report/sweep_csv.hpp; so that a merge of shard
// CSVs and an unsharded run produce the same files): the Pareto front of error vs wall time, the
// accuracy–speed and mode-count charts (gnuplot data and scripts), report.md and the text summary.
#pragma once

#include <string>
#include <vector>

#include "report/output_directory.hpp"
#include "report/sweep_csv.hpp"
#include "study/sweep.hpp"

namespace ffrf::report {

// Indices (into rows) of the Pareto-optimal ok rows: no other row is both faster and more
// accurate (worst normalized RMS error); sorted by wall time.
std::vector<std::size_t> pareto_front(const std::vector<SweepRow>& rows);

// Writes the chart data and scripts and draws accuracy_speed.png and mode_count.png.
void draw_sweep_charts(const StagedDirectory& out, const std::vector<SweepRow>& rows, const std::string& subtitle);

// report.md: `preamble` (scene, grid, reference and its convergence table), counts, the Pareto
// table, the charts, the per-model best errors and the failures.
std::string sweep_markdown(const std::vector<SweepRow>& rows, const std::string& preamble, double duration);

// The preamble of report.md (kept as sweep_context.md, reused by a merge); its first line records
// the duration: "<!-- duration_s: 40 -->".
std::string sweep_context(const std::string& scene_file, const scene::Scene& scene, study::SweepGrid grid, double duration,
                          const study::SweepStudy& study);
// The duration recorded in a context (0 when absent).
double context_duration(const std::string& context);
inline constexpr const char* sweep_context_file = "sweep_context.md";

// The Pareto table as text (stdout).
std::string pareto_text(const std::vector<SweepRow>& rows);

// Writes sweep.csv, the charts, the context and report.md (the completeness marker) into `dir`,
// completely or not at all; throws std::runtime_error (a duplicate id: overlapping shards).
void write_sweep_outputs(const std::string& dir, std::vector<SweepRow>& rows, const std::string& context, double duration);

}  // namespace ffrf::report
