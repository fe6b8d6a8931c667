// What `ffrf modes` reports: the text table with its header block, the JSON document (stdout
// with --json, summary.json with --out) and the CSV files (mode shapes, frequencies,
// convergence). Column names carry units (DESIGN.md §6).
#pragma once

#include <string>
#include <vector>

#include "app/modes_analysis.hpp"

namespace ffrf::app {

struct ModesContext {
  std::string scene_file;
  std::string scene_name;
};

std::string modes_table(const ModesResult& result, const ModesContext& context);
// `convergence` may be empty (not computed).
std::string modes_json(const ModesResult& result, const ModesContext& context,
                       const std::vector<ConvergencePoint>& convergence);
std::string frequencies_csv(const ModesResult& result);
// x_m, then modeJ_u_per_sqrtkg, modeJ_v_per_sqrtkg, modeJ_phi_rad_per_sqrtkg per mode, at the nodes.
std::string mode_shapes_csv(const ModesResult& result);
// x_m, then modeJ_v_per_sqrtkg per mode: the transverse shape v(x) between the nodes by the
// element's Hermite shape functions (8 points per element, at most 1000 intervals); for charts.
std::string sampled_shapes_csv(const ModesResult& result);
std::string convergence_csv(const std::vector<ConvergencePoint>& convergence);

}  // namespace ffrf::app
