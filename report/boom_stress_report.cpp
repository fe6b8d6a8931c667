// Reports of the stresses along the boom (see boom_stress_report.hpp).
#include "report/boom_stress_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>

#include "report/gnuplot.hpp"

namespace ffrf::report {
namespace {

constexpr double per_megapascal = 1e-6;

std::string allowable_text(const scene::Scene& scene, double utilisation) {
  if (!scene.boom.allowable_stress) return "no allowable stress given (boom.allowable_stress)";
  return fmt::format("utilisation {:.3f} of {:.0f} MPa", utilisation, *scene.boom.allowable_stress * per_megapascal);
}

}  // namespace

std::string stress_recovery_name(const scene::BoomChoice& choice) {
  switch (choice.kind) {
    case scene::BoomKind::rigid: return "quasi-static (rigid boom, by mode acceleration)";
    case scene::BoomKind::nodal: return "the nodal displacements";
    case scene::BoomKind::modal:
      return choice.stress_recovery == multibody::StressRecovery::mode_acceleration ? "mode acceleration" : "mode displacement";
  }
  return "?";
}

std::string boom_stress_static_line(const scene::Scene& scene, const multibody::CraneOutputs& o) {
  return fmt::format("  stress    peak fibre stress {:.4g} MPa at x = {:.4g} m (fibres at ±{:.3g} m), {}\n", o.boom_peak_stress * per_megapascal,
                     o.boom_peak_stress_position, scene.boom.fibre_distance, allowable_text(scene, o.boom_stress_utilisation));
}

std::string boom_stress_text(const scene::Scene& scene, const study::ModelRun& run) {
  const multibody::BoomStressEnvelope& e = run.result.boom_stress;
  if (e.empty()) return {};
  const double peak = e.at_peak.peak;
  const double utilisation = scene.boom.allowable_stress ? peak / *scene.boom.allowable_stress : 0.0;
  return fmt::format("boom stress peak fibre stress {:.4g} MPa at x = {:.4g} m, t = {:.4g} s (at rest {:.4g} MPa); {}; by {}\n",
                     peak * per_megapascal, e.at_peak.peak_position, e.peak_time,
                     run.static_outputs().boom_peak_stress * per_megapascal, allowable_text(scene, utilisation),
                     stress_recovery_name(run.choice));
}

Json boom_stress_json(const scene::Scene& scene, const study::ModelRun& run) {
  const multibody::BoomStressEnvelope& e = run.result.boom_stress;
  Json json{{"recovery", stress_recovery_name(run.choice)}, {"fibre_distance_m", scene.boom.fibre_distance}};
  json["allowable_stress_MPa"] = scene.boom.allowable_stress ? Json(*scene.boom.allowable_stress * per_megapascal) : Json(nullptr);
  json["static_peak_MPa"] = run.static_outputs().boom_peak_stress * per_megapascal;
  if (e.empty()) return json;
  json["sections"] = e.position.size();
  json["peak_MPa"] = e.at_peak.peak * per_megapascal;
  json["peak_position_m"] = e.at_peak.peak_position;
  json["peak_time_s"] = e.peak_time;
  json["utilisation"] = scene.boom.allowable_stress ? Json(e.at_peak.peak / *scene.boom.allowable_stress) : Json(nullptr);
  return json;
}

std::string boom_stress_csv(const multibody::BoomStressEnvelope& e) {
  std::string csv =
      "x_m,axial_min_N,axial_max_N,moment_min_Nm,moment_max_Nm,stress_min_MPa,stress_max_MPa,peak_axial_N,peak_moment_Nm,"
      "peak_top_MPa,peak_bottom_MPa\n";
  for (Eigen::Index s = 0; s < e.position.size(); ++s) {
    csv += fmt::format("{:.10g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", e.position(s),
                       e.axial_min(s), e.axial_max(s), e.moment_min(s), e.moment_max(s), e.stress_min(s) * per_megapascal,
                       e.stress_max(s) * per_megapascal, e.at_peak.forces.axial_force(s), e.at_peak.forces.bending_moment(s),
                       e.at_peak.top(s) * per_megapascal, e.at_peak.bottom(s) * per_megapascal);
  }
  return csv;
}

void draw_boom_stress_chart(const StagedDirectory& out, const std::vector<StressChartSource>& sources, const scene::Scene& scene,
                            const std::string& subtitle, const std::string& command) {
  if (sources.empty()) {
    leave_out_chart(out, "boom_stress", "no run recovered stresses along the boom");
    return;
  }
  constexpr std::array palette{"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#17becf", "#e377c2"};
  std::vector<std::string> plots;
  std::size_t colour = 0;
  for (const StressChartSource& s : sources) {
    // The most tensile fibre drawn solid (the reference long-dashed), the most compressive dashed (dotted).
    const std::string style =
        s.reference ? "lw 3 lc rgb 'black'" : fmt::format("lw 2 lc rgb '{}'", palette[colour++ % palette.size()]);
    plots.push_back(fmt::format("{} skip 1 using 1:7 with lines {} dt {} title {} noenhanced", gnuplot_quoted(s.csv), style,
                                s.reference ? "(8,6)" : "1", gnuplot_quoted(s.label + ": most tensile")));
    plots.push_back(fmt::format("{} skip 1 using 1:6 with lines {} dt {} title {} noenhanced", gnuplot_quoted(s.csv), style,
                                s.reference ? "(2,6)" : "2", gnuplot_quoted(s.label + ": most compressive")));
  }
  if (sources.size() == 1) {
    plots.push_back(fmt::format("{} skip 1 using 1:10 with points pt 7 ps 0.6 lc rgb '#555555' title 'top fibre at the peak'",
                                gnuplot_quoted(sources.front().csv)));
    plots.push_back(fmt::format("{} skip 1 using 1:11 with points pt 6 ps 0.6 lc rgb '#555555' title 'bottom fibre at the peak'",
                                gnuplot_quoted(sources.front().csv)));
  }
  std::string allowable;
  if (scene.boom.allowable_stress) {
    const double limit = *scene.boom.allowable_stress * per_megapascal;
    allowable = fmt::format(
        "set arrow 1 from graph 0, first {0:g} to graph 1, first {0:g} nohead dt 3 lw 2 lc rgb '#aa0000'\n"
        "set arrow 2 from graph 0, first {1:g} to graph 1, first {1:g} nohead dt 3 lw 2 lc rgb '#aa0000'\n"
        "set label 1 'allowable ±{0:g} MPa' at graph 0.01, first {0:g} left offset 0,0.6 font ',9' tc rgb '#aa0000'\n",
        limit, -limit);
  }
  const std::string script = fmt::format(
      "# Drawn by `{0}`; restyle and rerun with `gnuplot boom_stress.gp` in this directory.\n"
      "set terminal {1} size 1000,560 font ',11'\n"
      "set output 'boom_stress.png'\n"
      "set datafile separator ','\n"
      "set grid\nset key below horizontal maxrows 3 font ',10'\n"
      "set title {2} noenhanced\n"
      "set xlabel 'x along the boom from the heel B [m]'\nset ylabel 'extreme fibre stress [MPa] (tension > 0)'\n"
      "{3}plot {4}\n",
      command, png_terminal(), gnuplot_lines("Fibre stress along the boom: extremes over the run", subtitle), allowable,
      fmt::format("{}", fmt::join(plots, ", \\\n     ")));
  draw_chart(out, "boom_stress", script);
}

}  // namespace ffrf::report
