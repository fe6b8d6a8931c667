// What `ffrf modes --spin / --axial-force / --spin-range` reports: the text tables, the JSON
// documents (stdout with --json, summary.json with --out), the CSV files (prestressed_frequencies.csv,
// campbell.csv; column names carry units) and the gnuplot script of the Campbell diagram
// (campbell.png: frequencies against spin, the 1×Ω excitation line and the ω = 0 axis; divergent
// modes drawn below the axis at minus their growth rate). Unstable modes (ω² < 0) are shown as
// "unstable, growth rate x 1/s", never as NaN.
#pragma once

#include <string>

#include "study/campbell.hpp"
#include "report/modes_report.hpp"

namespace ffrf::report {

std::string spin_modes_table(const study::SpinModesResult& result, const ModesContext& context);
std::string spin_modes_json(const study::SpinModesResult& result, const ModesContext& context);
std::string spin_modes_csv(const study::SpinModesResult& result);

std::string campbell_table(const study::CampbellResult& result, const ModesContext& context);
std::string campbell_json(const study::CampbellResult& result, const ModesContext& context);
// spin_rad_per_s, then per bending mode j: modeJ_{stiffened,unstiffened,series}_rad_per_s (empty when
// unstable or missing) and modeJ_{stiffened,unstiffened,series}_growth_per_s (0 when stable).
std::string campbell_csv(const study::CampbellResult& result);
std::string campbell_script(const study::CampbellResult& result, const std::string& terminal);

}  // namespace ffrf::report
