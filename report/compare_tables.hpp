// The Markdown tables of compare's report.md (study/compare.hpp): the verdict table, the error tables
// per output (total, static, dynamic, in normalized and absolute form; pitch in degrees), the static
// equilibrium, the wire rope and the solver costs with the speed-ups.
#pragma once

#include <string>

#include "scene/scene.hpp"
#include "study/compare.hpp"

namespace ffrf::report {

// One row per model: DOFs, worst error and output, its static and dynamic parts, pass/fail, wall
// time, the speed-ups in wall time and solver work.
std::string verdict_table(const study::Comparison& comparison);

enum class ErrorKind {
  total,           // normalized RMS of x − x_ref (the verdict's), with the DAF error and the worst
  static_part,     // |x_s − x_ref_s| / S
  dynamic_part,    // RMS(d − d_ref) / S
  static_offset,   // x_s − x_ref_s in the output's unit
  dynamic_max,     // max |d − d_ref| in the output's unit
  total_max,       // max |x − x_ref| in the output's unit
};
// One row per model, one column per output channel (pitch in degrees where absolute).
std::string error_table(const study::Comparison& comparison, ErrorKind kind);

std::string static_table(const scene::Scene& scene, const study::Comparison& comparison);
std::string wire_table(const study::Comparison& comparison);
std::string cost_table(const study::Comparison& comparison);
// One row per model: its peak boom stress by mode displacement and by mode acceleration against the
// reference's (normalized RMS error of the history, error of the largest value), the recovery its
// channels report marked.
std::string stress_recovery_table(const study::Comparison& comparison);

}  // namespace ffrf::report
