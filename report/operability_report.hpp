// The outputs of `ffrf operability` (study/operability.hpp): operability.csv (one row per cell: its
// status — ok, failed, not_physical — the statistics, the utilisation of every criterion, the
// governing one, pass/fail, the verification with the converged model, the cell's sea: steepness,
// band, components, repeat period and independent wave cycles; timing columns are the ones named
// `*_s`, last), report.md (the warnings, the operability table per heading, the cells' details, the
// sea of each cell, the model choice and what it saved), summary.json and the operability chart
// (report/operability_chart.hpp).
#pragma once

#include <string>

#include "report/output_directory.hpp"
#include "study/operability.hpp"

namespace ffrf::report {

struct OperabilityContext {
  std::string scene_file;
  std::string command;   // the command line that made it
  double duration = 0.0; // of each record [s]
  int seeds = 0;
  double peak_enhancement = 3.3;
  double tolerance = 0.01;
  std::string sea;       // what the records are: "irregular (JONSWAP γ = 3.3)" or the stand-in
};

// OperabilityContext::sea of a request: "irregular, JONSWAP γ = 3.3, long-crested, ...".
std::string operability_sea_text(const study::OperabilityRequest& request);

std::string operability_csv(const study::OperabilityStudy& study);
std::string operability_markdown(const study::OperabilityStudy& study, const OperabilityContext& context);
std::string operability_json(const study::OperabilityStudy& study, const OperabilityContext& context);

// What the model choice saved on the verified cells: converged over recommended.
struct ModelSavings {
  std::size_t cells = 0;            // verified cells with both runs ok
  std::size_t agreeing = 0;         // same pass/fail and governing criterion
  double largest_difference = 0.0;  // of the governing utilisation, |u_rec − u_conv| / u_conv
  double work_ratio = 0.0;          // Σ converged work / Σ recommended work
  double wall_ratio = 0.0;          // Σ converged wall / Σ recommended wall (timing)
};
ModelSavings model_savings(const study::OperabilityStudy& study);

// The text summary for stdout: counts, the table per heading, the savings.
std::string operability_text(const study::OperabilityStudy& study);

// Writes operability.csv, the chart, summary.json and report.md (the marker) into dir, whole or not at all.
// Returns the console lines naming a chart not drawn (report/chart_notes.hpp; empty when it was).
std::string write_operability_outputs(const std::string& dir, const study::OperabilityStudy& study,
                               const OperabilityContext& context);

}  // namespace ffrf::report
