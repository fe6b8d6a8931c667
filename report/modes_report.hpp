// What `ffrf modes` reports: the text table with its header block, the JSON document (stdout
// with --json, summary.json with --out), the CSV files (mode shapes, frequencies, convergence) and
// the charts. Column names carry units (`frequency_hz`; docs/architecture.md, "Conventions").
#pragma once

#include <string>
#include <vector>

#include "study/modes.hpp"

namespace ffrf::report {

struct ModesContext {
  std::string scene_file;
  std::string scene_name;
};

std::string modes_table(const study::ModesResult& result, const ModesContext& context);
// `convergence` may be empty (not computed).
std::string modes_json(const study::ModesResult& result, const ModesContext& context,
                       const std::vector<study::ConvergencePoint>& convergence);
std::string frequencies_csv(const study::ModesResult& result);
// x_m, then modeJ_u_per_sqrtkg, modeJ_v_per_sqrtkg, modeJ_phi_rad_per_sqrtkg per mode, at the nodes.
std::string mode_shapes_csv(const study::ModesResult& result);
// x_m, then modeJ_v_per_sqrtkg per mode: the transverse shape v(x) between the nodes by the
// element's Hermite shape functions (8 points per element, at most 1000 intervals); for charts.
std::string sampled_shapes_csv(const study::ModesResult& result);
// A pinned boom's modes as the crane supports it (study/supported_boom.hpp): supported_boom.csv.
std::string supported_boom_csv(const study::SupportedBoomModes& supported);
std::string convergence_csv(const std::vector<study::ConvergencePoint>& convergence);

// Charts (gnuplot scripts): the transverse shape v(x) of each bending mode, from
// mode_shapes_sampled.csv; the relative error of f1..f4 against N on log–log axes, from
// frequency_convergence.csv.
std::string mode_shapes_script(const study::ModesResult& result, const std::string& terminal);
std::string convergence_script(const study::ModesResult& result, const std::string& terminal);

}  // namespace ffrf::report
