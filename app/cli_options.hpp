// The converged reference of `ffrf compare` and `ffrf sweep` (cases/reference_model.hpp): its
// command-line options, the window errors are measured over, the reference as a ModelRun (for the
// charts and statistics) and its convergence table for the reports.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "app/crane_run.hpp"
#include "app/json_writer.hpp"
#include "cases/reference_model.hpp"

namespace ffrf::app {

// Level i: nodal N = elements·2^i, CVODE rtol = rtol·10^(−i); stop when the worst normalized RMS
// change between two levels is below the bound, or after max_levels levels.
struct ReferenceOptions {
  int start_elements = 8;
  double start_rtol = 1e-6;
  double bound = 1e-3;
  int max_levels = 3;
};
void add_reference_options(CLI::App& sub, ReferenceOptions& options);
// The message naming a bad option, or nothing.
std::optional<std::string> reference_options_error(const ReferenceOptions& options);

// Errors are measured after the wave ramp; a run that ends within the ramp (or calm water) is
// measured over its whole length (like the statistics window of crane_series.hpp).
double error_window(const cases::Scene& scene, double duration);

// The reference for runs of `duration` seconds. A run that ends within the wave ramp has no
// window to check convergence on: then only the first level is run (reported as not converged).
// Throws coupling::SolverFailure.
cases::ConvergedReference compute_reference(const cases::Scene& scene, const ReferenceOptions& options, double duration);

// "reference (nodal N=32, rtol 1e-08)"
std::string reference_label(const cases::ConvergedReference& reference);
// The reference's run with statistics, as if it were one compared model (static = the t = 0 sample).
ModelRun reference_model_run(const cases::Scene& scene, const cases::ConvergedReference& reference);

// One sentence: converged or not, at which level, against which bound.
std::string reference_verdict(const cases::ConvergedReference& reference);
// The level table (elements, rtol, change, steps, wall time) as Markdown and as plain text.
std::string reference_levels_markdown(const cases::ConvergedReference& reference);
std::string reference_levels_text(const cases::ConvergedReference& reference);
// Writes the reference's keys (model, settings, levels, converged) into an open JSON object.
void write_reference_json(JsonWriter& json, const cases::ConvergedReference& reference);

}  // namespace ffrf::app
