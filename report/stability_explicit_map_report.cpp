// Tables and charts of the explicit stability map (see stability_explicit_map_report.hpp).
#include "report/stability_explicit_map_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "report/gnuplot.hpp"

namespace ffrf::report {
namespace {

using study::ExplicitStabilityMap;
using study::ExplicitStabilityRow;

// A finite number, or an empty CSV cell / "-" in a table (never NaN or inf in the outputs).
std::string cell(double value, const char* format = "{:.6g}") {
  return std::isfinite(value) ? fmt::format(fmt::runtime(format), value) : "";
}
std::string shown(double value, const char* format = "{:.4g}") {
  return std::isfinite(value) ? fmt::format(fmt::runtime(format), value) : "-";
}
double ratio(double measured, double theory) { return std::isfinite(theory) && theory > 0.0 ? measured / theory : NAN; }

std::string script_header(const std::string& name, const std::string& terminal, const std::string& title, int height) {
  return fmt::format(
      "# Drawn by `ffrf stability`; restyle and rerun with `gnuplot {0}.gp` in this directory.\n"
      "set terminal {1} size 1000,{3} font ',11'\n"
      "set output '{0}.png'\n"
      "set datafile separator ','\n"
      "set key below horizontal Left reverse\n"
      "set grid\n"
      "set title {2} noenhanced\n",
      name, terminal, gnuplot_quoted(title), height);
}

// Largest stable step against ω_max (boom models only), with β_I/ω and the damped boom bound.
std::string frequency_chart(const ExplicitStabilityMap& map, const std::string& terminal, std::string& data) {
  std::vector<const ExplicitStabilityRow*> rows;
  for (const ExplicitStabilityRow& row : map.rows) {
    if (row.ok() && row.highest_frequency > 0.0) rows.push_back(&row);
  }
  std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->highest_frequency < b->highest_frequency; });
  data = "omega_max_rad_per_s,h_stable_s,h_theory_boom_damped_s,h_theory_jacobian_s,kind\n";
  for (const ExplicitStabilityRow* row : rows) {
    data += fmt::format("{:.8g},{:.8g},{:.8g},{:.8g},{}\n", row->highest_frequency, row->measured.stable_step,
                        row->boom_damped_step, row->jacobian_step, scene::to_string(row->choice.kind));
  }
  std::string script = script_header("stable_step_vs_frequency", terminal,
                                     "Largest stable ERK step vs the boom's highest frequency, " + map.scene_name, 650);
  script += "set logscale xy\nset format y '%.0e'\n";
  script += "set xlabel 'highest angular frequency of the boom coordinates ω_{max} [rad/s]'\n";
  script += "set ylabel 'largest stable fixed step h [s]'\n";
  script += fmt::format("beta_i = {:.10g}\n", map.imaginary_axis_boundary);
  if (rows.empty()) {
    script += "set label 'no elastic boom model was measured' at graph 0.5, 0.5 center\nplot [1:10] [1:10] NaN notitle\n";
    return script;
  }
  script += "plot beta_i / x with lines lw 2 dt 2 lc rgb '#555555' title 'β_I/ω_{max} (undamped boom)', \\\n"
            "     'stable_step_vs_frequency.csv' skip 1 using 1:3 with linespoints lw 1 pt 6 lc rgb '#1f77b4' "
            "title 'boom bound with its damping', \\\n"
            "     '' skip 1 using 1:4 with points pt 2 ps 1.5 lc rgb '#ff7f0e' title 'linearized crane (Jacobian)', \\\n"
            "     '' skip 1 using 1:(strcol(5) eq 'nodal' ? $2 : NaN) with points pt 7 ps 1.3 lc rgb '#2ca02c' "
            "title 'measured, nodal', \\\n"
            "     '' skip 1 using 1:(strcol(5) eq 'modal' ? $2 : NaN) with points pt 5 ps 1.3 lc rgb '#9467bd' "
            "title 'measured, modal'\n";
  return script;
}

// Model × step grid: cells inferred from each model's measured bracket (stable below h_stable,
// unstable above h_unstable), the trial runs themselves, and the theoretical boundary.
std::string map_chart(const ExplicitStabilityMap& map, const std::string& terminal, std::string& cells,
                      std::string& trials, std::string& theory) {
  double lo = INFINITY, hi = 0.0;
  for (const ExplicitStabilityRow& row : map.rows) {
    if (!row.ok()) continue;
    lo = std::min(lo, row.measured.stable_step);
    hi = std::max(hi, row.measured.unstable_step);
  }
  cells = "model_index,step_s,stable\n";
  trials = "model_index,step_s,stable\n";
  theory = "model_index,h_theory_jacobian_s,h_theory_boom_damped_s\n";
  std::vector<std::string> tics;
  for (std::size_t i = 0; i < map.rows.size(); ++i) {
    const ExplicitStabilityRow& row = map.rows[i];
    tics.push_back(fmt::format("{} {}", gnuplot_quoted(row.label), i));
    if (!row.ok()) continue;
    constexpr int per_decade = 6;
    for (double h = lo / 4.0; h <= 4.0 * hi; h *= std::pow(10.0, 1.0 / per_decade)) {
      if (h <= row.measured.stable_step || h >= row.measured.unstable_step) {
        cells += fmt::format("{},{:.6g},{}\n", i, h, h <= row.measured.stable_step ? 1 : 0);
      }
    }
    for (const solve::StabilityTrial& trial : row.measured.trial_log) {
      trials += fmt::format("{},{:.8g},{}\n", i, trial.step, trial.stable ? 1 : 0);
    }
    theory += fmt::format("{},{:.8g},{}\n", i, row.jacobian_step, cell(row.boom_damped_step, "{:.8g}"));
  }
  const int height = std::max(500, 60 + 28 * static_cast<int>(map.rows.size()));
  std::string script = script_header("stability_map", terminal,
                                     "Explicit RK stability map (cells from the measured bracket, dots: trial runs), " +
                                         map.scene_name, height);
  script += "set logscale x\nset format x '%.0e'\nset grid noytics\n";
  script += "set xlabel 'fixed step h [s]'\n";
  script += fmt::format("set ytics ({})\nset yrange [-0.7:{}]\n", fmt::join(tics, ", "), static_cast<double>(map.rows.size()) - 0.3);
  if (!std::isfinite(lo)) {
    script += "set label 'no model was measured' at graph 0.5, 0.5 center\nplot [1:10] NaN notitle\n";
    return script;
  }
  script += "plot 'stability_map_cells.csv' skip 1 using 2:1:($3 > 0 ? 0x2ca02c : 0xd62728) with points pt 5 ps 2.2 "
            "lc rgb variable notitle, \\\n"
            "     NaN with points pt 5 ps 2 lc rgb '#2ca02c' title 'stable', \\\n"
            "     NaN with points pt 5 ps 2 lc rgb '#d62728' title 'unstable', \\\n"
            "     'stability_map_trials.csv' skip 1 using 2:1 with points pt 7 ps 0.6 lc rgb 'black' title 'trial run', \\\n"
            "     'stability_map_theory.csv' skip 1 using 2:1 with points lw 2 pt 2 ps 2 lc rgb '#ff7f0e' "
            "title 'theory: linearized crane', \\\n"
            "     '' skip 1 using 3:1 with points pt 6 ps 1.5 lc rgb '#1f77b4' title 'theory: damped boom'\n";
  return script;
}


}  // namespace

std::string explicit_stability_csv(const ExplicitStabilityMap& map) {
  std::string csv =
      "model,kind,elements,modes,static_modes,elastic_dof,omega_max_rad_per_s,h_theory_boom_undamped_s,"
      "h_theory_boom_damped_s,h_theory_jacobian_s,h_stable_s,h_unstable_s,measured_over_jacobian,"
      "measured_over_boom_damped,measured_over_boom_undamped,limiting_part,trials,rhs_evaluations,window_steps,wall_s,"
      "status\n";
  for (const ExplicitStabilityRow& r : map.rows) {
    const bool ok = r.ok();
    const double h = ok ? r.measured.stable_step : NAN;
    std::string status = ok ? "ok" : r.failure;
    std::replace(status.begin(), status.end(), '"', '\'');
    csv += fmt::format("\"{}\",{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{:.4g},\"{}\"\n", r.label,
                       scene::to_string(r.choice.kind), r.choice.elements,
                       r.choice.kind == scene::BoomKind::modal ? r.choice.modes : 0,
                       r.choice.kind == scene::BoomKind::modal && r.choice.static_modes ? 1 : 0, r.elastic_dof,
                       cell(r.highest_frequency > 0.0 ? r.highest_frequency : NAN), cell(r.boom_undamped_step),
                       cell(r.boom_damped_step), cell(r.jacobian_step), cell(h),
                       cell(ok ? r.measured.unstable_step : NAN), cell(ratio(h, r.jacobian_step), "{:.4f}"),
                       cell(ratio(h, r.boom_damped_step), "{:.4f}"), cell(ratio(h, r.boom_undamped_step), "{:.4f}"),
                       ok ? r.limiting_part() : "", r.measured.trials, r.measured.rhs_evaluations,
                       r.measured.window_steps, r.wall_seconds, status);
  }
  return csv;
}

std::string explicit_stability_markdown(const ExplicitStabilityMap& map) {
  std::string md = fmt::format(
      "| model | elastic DOF | ω_max [rad/s] | β_I/ω_max [s] | damped boom [s] | Jacobian [s] | measured h [s] | "
      "measured / Jacobian | measured / damped boom | measured / β_I/ω_max | limited by | trials | RHS |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n");
  for (const ExplicitStabilityRow& r : map.rows) {
    if (!r.ok()) {
      std::string empty;
      for (int column = 0; column < 10; ++column) empty += " - |";
      md += fmt::format("| {} | {} | failed: {} |{}\n", r.label, r.elastic_dof, r.failure, empty);
      continue;
    }
    const double h = r.measured.stable_step;
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.label, r.elastic_dof,
                      shown(r.highest_frequency > 0.0 ? r.highest_frequency : NAN), shown(r.boom_undamped_step),
                      shown(r.boom_damped_step), shown(r.jacobian_step), shown(h),
                      shown(ratio(h, r.jacobian_step), "{:.3f}"), shown(ratio(h, r.boom_damped_step), "{:.3f}"),
                      shown(ratio(h, r.boom_undamped_step), "{:.3f}"), r.limiting_part(), r.measured.trials,
                      r.measured.rhs_evaluations);
  }
  return md;
}

void write_explicit_stability_map(const StagedDirectory& out, const ExplicitStabilityMap& map) {
  out.write("explicit_stability.csv", explicit_stability_csv(map));
  const std::string terminal = png_terminal();
  std::string data, cells, trials, theory;
  const std::string frequency_script = frequency_chart(map, terminal, data);
  out.write("stable_step_vs_frequency.csv", data);
  const std::string map_script = map_chart(map, terminal, cells, trials, theory);
  out.write("stability_map_cells.csv", cells);
  out.write("stability_map_trials.csv", trials);
  out.write("stability_map_theory.csv", theory);
  draw_chart(out, "stable_step_vs_frequency", frequency_script);
  draw_chart(out, "stability_map", map_script);
}

}  // namespace ffrf::report
