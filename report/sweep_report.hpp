// The outputs of `ffrf sweep` from its CSV rows (report/sweep_csv.hpp; so that a merge of shard
// CSVs and an unsharded run produce the same files): the Pareto front of error vs wall time, the
// verdict against the tolerance (study/verdict.hpp), the accuracy–speed and mode-count charts (gnuplot
// data and scripts, report/sweep_charts.cpp), report.md and the text summary.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "report/output_directory.hpp"
#include "report/sweep_csv.hpp"
#include "study/sweep.hpp"
#include "study/verdict.hpp"

namespace ffrf::report {

// Indices (into rows) of the Pareto-optimal ok rows: no other row is both faster and more
// accurate (worst normalized RMS error); sorted by wall time.
std::vector<std::size_t> pareto_front(const std::vector<SweepRow>& rows);

// The best (smallest worst error) ok row of each model, in first-appearance order.
std::vector<const SweepRow*> best_per_model(const std::vector<SweepRow>& rows);

// What the sweep's outputs need besides its rows, recorded in the context's first lines as
// "<!-- key: value -->" (so a merge of shards has it too).
struct SweepFacts {
  double duration = 0.0;                // simulated time of every run [s]
  double tolerance = 0.01;              // of the verdict
  std::string reference;                // "reference (nodal N=16, rtol 1e-07)"
  double reference_wall_seconds = 0.0;  // its integration
  double reference_work = 0.0;          // RHS evaluations × state size
  double reference_change = NAN;        // its last level's change: errors below are not resolved
};

// Whether a row is an adaptive run at the model-choice rtol of τ (study::model_choice_rtol): only
// those may be named the cheapest, so that sweep, compare and recommend judge alike.
bool at_choice_rtol(const SweepRow& row, double tolerance);
// The verdict of the sweep: every row a measured configuration ("MODEL, SETTINGS").
std::vector<study::MeasuredModel> measured_rows(const std::vector<SweepRow>& rows, double tolerance);
study::Verdict sweep_verdict(const std::vector<SweepRow>& rows, const SweepFacts& facts);
// The headline and the models that fail at every setting.
std::string sweep_verdict_sentence(const std::vector<SweepRow>& rows, const SweepFacts& facts);

// Writes the chart data and scripts and draws accuracy_speed.png and mode_count.png.
void draw_sweep_charts(const StagedDirectory& out, const std::vector<SweepRow>& rows, const SweepFacts& facts);
// The label of a Pareto point on the chart: "#12 k=2+s cvode 1e-06" (id, model, integrator).
std::string pareto_label(const SweepRow& row);
// The Pareto points the accuracy–speed chart labels (pareto.dat: wall, worst, "label", id).
std::string pareto_data(const std::vector<SweepRow>& rows);

// report.md: `preamble` (scene, grid, reference and its convergence table), counts, the verdict, the
// Pareto table, the charts, the per-model best errors and the failures.
std::string sweep_markdown(const std::vector<SweepRow>& rows, const std::string& preamble);

// The preamble of report.md (kept as sweep_context.md, reused by a merge); its first lines record
// the facts: "<!-- duration_s: 40 -->", "<!-- tolerance: 0.01 -->", ...
std::string sweep_context(const std::string& scene_file, const scene::Scene& scene, study::SweepGrid grid, double duration,
                          const study::SweepStudy& study);
// The facts recorded in a context (defaults where absent).
SweepFacts context_facts(const std::string& context);
inline constexpr const char* sweep_context_file = "sweep_context.md";

// summary.json: the facts, the counts, the verdict (report/verdict_report.hpp) and the Pareto-optimal
// configurations with their speed-ups.
std::string sweep_json(const std::vector<SweepRow>& rows, const SweepFacts& facts);

// The Pareto table and the verdict as text (stdout).
std::string pareto_text(const std::vector<SweepRow>& rows, const SweepFacts& facts);

// Writes sweep.csv, the charts, the context, summary.json and report.md (the completeness marker) into `dir`,
// completely or not at all; throws std::runtime_error (a duplicate id: overlapping shards). Returns
// the console lines naming the charts not drawn (report/chart_notes.hpp; empty when all were).
std::string write_sweep_outputs(const std::string& dir, std::vector<SweepRow>& rows, const std::string& context);

}  // namespace ffrf::report
