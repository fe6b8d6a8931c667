// The six time-history charts of `ffrf run` and `ffrf compare` (crane heave and pitch, cargo heave
// and pitch like the paper's Figs. 8–11, wire tension, boom tip deflection) as gnuplot scripts
// over one or more time-series CSV files (one curve per model).
#pragma once

#include <string>
#include <vector>

#include "report/output_directory.hpp"

namespace ffrf::report {

struct ChartSource {
  std::string csv;    // file name in the output directory
  std::string label;  // curve title ("nodal N=16")
};

// The chart names (script NAME.gp draws NAME.png).
std::vector<std::string> crane_chart_names();

// The gnuplot script of one chart; `command` names the program that drew it ("ffrf run --out").
std::string crane_chart_script(const std::string& name, const std::vector<ChartSource>& sources,
                               const std::string& terminal, const std::string& subtitle, const std::string& command);

// Writes every chart's script into the staging directory and runs gnuplot on it (the CSV files
// must be written first); throws std::runtime_error when gnuplot is missing or fails.
void draw_crane_charts(const StagedDirectory& out, const std::vector<ChartSource>& sources, const std::string& subtitle,
                       const std::string& command);

}  // namespace ffrf::report
