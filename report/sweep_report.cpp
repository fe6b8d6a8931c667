// The sweep's CSV read back, Pareto front, charts and report (see sweep_report.hpp).
#include "report/sweep_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "report/gnuplot.hpp"
#include "report/reference_report.hpp"
#include "study/error_measure.hpp"
#include "report/sweep_csv.hpp"

namespace ffrf::report {
namespace {

std::string sci(const std::optional<double>& v) { return v ? fmt::format("{:.2e}", *v) : "-"; }

const std::vector<std::string> families{"rigid", "nodal", "modal", "modal+static"};

// The best (smallest worst-channel error) ok row of each model, in first-appearance order.
std::vector<const SweepRow*> best_per_model(const std::vector<SweepRow>& rows) {
  std::vector<const SweepRow*> best;
  std::map<std::string, std::size_t> index;
  for (const SweepRow& row : rows) {
    if (!row.ok()) continue;
    const auto [it, added] = index.emplace(row.model, best.size());
    if (added) best.push_back(&row);
    else if (*row.worst < *best[it->second]->worst) best[it->second] = &row;
  }
  return best;
}

std::string script_header(const std::string& name, const std::string& terminal, const std::string& size) {
  return fmt::format(
      "# Drawn by `ffrf sweep --out`; restyle and rerun with `gnuplot {0}.gp` in this directory.\n"
      "set terminal {1} size {2} font ',11'\nset output '{0}.png'\nset grid\nset logscale xy\n"
      "set format y '10^{{%L}}'\n",
      name, terminal, size);
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<SweepRow>& rows) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].ok() && *rows[i].worst > 0.0) order.push_back(i);
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return *rows[a].wall != *rows[b].wall ? *rows[a].wall < *rows[b].wall : *rows[a].worst < *rows[b].worst;
  });
  std::vector<std::size_t> front;
  for (std::size_t i : order) {
    if (front.empty() || *rows[i].worst < *rows[front.back()].worst) front.push_back(i);
  }
  return front;
}

void draw_sweep_charts(const StagedDirectory& out, const std::vector<SweepRow>& rows, const std::string& subtitle) {
  const std::string terminal = png_terminal();
  // accuracy_speed.dat: one gnuplot data set (index) per model family; pareto.dat: the front.
  std::string points = "# wall_s worst_nrms id (one index per family: rigid, nodal, modal, modal+static)\n";
  for (const std::string& family : families) {
    points += fmt::format("# {}\n", family);
    bool any = false;
    for (const SweepRow& row : rows) {
      if (row.family != family || !row.ok() || *row.worst <= 0.0) continue;
      points += fmt::format("{} {} {}\n", *row.wall, *row.worst, row.id);
      any = true;
    }
    if (!any) points += "NaN NaN -1\n";
    points += "\n\n";
  }
  out.write("accuracy_speed.dat", points);
  std::string front = "# wall_s worst_nrms id (Pareto front, by wall time)\n";
  for (std::size_t i : pareto_front(rows)) front += fmt::format("{} {} {}\n", *rows[i].wall, *rows[i].worst, rows[i].id);
  out.write("pareto.dat", front);
  std::string script = script_header("accuracy_speed", terminal, "1000,650");
  script += fmt::format(
      "set title \"Accuracy vs speed: every successful sweep run\\n{}\" noenhanced\n"
      "set xlabel 'wall time of the integration [s]'\n"
      "set ylabel 'worst normalized RMS error over the judged outputs'\n"
      "set key outside right\n"
      "plot 'accuracy_speed.dat' index 0 using 1:2 with points pt 5 ps 1.4 lc rgb '#444444' title 'rigid', \\\n"
      "     '' index 1 using 1:2 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'nodal', \\\n"
      "     '' index 2 using 1:2 with points pt 9 ps 1.3 lc rgb '#ff7f0e' title 'modal', \\\n"
      "     '' index 3 using 1:2 with points pt 13 ps 1.3 lc rgb '#2ca02c' title 'modal+static', \\\n"
      "     'pareto.dat' using 1:2 with steps lw 2 lc rgb '#d62728' title 'Pareto front'\n",
      subtitle);
  out.write("accuracy_speed.gp", script);
  run_gnuplot(out.staging(), "accuracy_speed.gp");

  // mode_count.dat: best error per model (over its integrator settings) vs k; nodal vs N.
  std::string modes = "# k worst_nrms cargo_heave_nrms (index 0: modal, 1: modal+static, 2: nodal vs N)\n";
  for (const std::string family : {"modal", "modal+static", "nodal"}) {
    std::map<int, const SweepRow*> best;
    for (const SweepRow* row : best_per_model(rows)) {
      if (row->family == family) best[family == "nodal" ? row->elements : row->modes] = row;
    }
    for (const auto& [count, row] : best) modes += fmt::format("{} {} {}\n", count, *row->worst, row->cargo_heave.value_or(NAN));
    if (best.empty()) modes += "NaN NaN NaN\n";
    modes += "\n\n";
  }
  out.write("mode_count.dat", modes);
  script = script_header("mode_count", terminal, "1200,550");
  script += fmt::format(
      "set multiplot layout 1,2 title \"Error vs basis size: the best run of each model\\n{}\" noenhanced\n"
      "set ylabel 'worst normalized RMS error'\nset key top right\n"
      "set xlabel 'vibration modes k (N = 16 mesh)'\nset logscale x 2\n"
      "plot 'mode_count.dat' index 0 using 1:2 with linespoints pt 9 lw 2 lc rgb '#ff7f0e' title 'modal', \\\n"
      "     '' index 1 using 1:2 with linespoints pt 13 lw 2 lc rgb '#2ca02c' title 'modal + static modes'\n"
      "set xlabel 'elements N'\n"
      "plot 'mode_count.dat' index 2 using 1:2 with linespoints pt 7 lw 2 lc rgb '#1f77b4' title 'nodal'\n"
      "unset multiplot\n",
      subtitle);
  out.write("mode_count.gp", script);
  run_gnuplot(out.staging(), "mode_count.gp");
}

std::string sweep_markdown(const std::vector<SweepRow>& rows, const std::string& preamble, double duration) {
  std::size_t ok = 0, failed = 0, skipped = 0;
  for (const SweepRow& row : rows) {
    ok += row.ok() ? 1 : 0;
    failed += row.status == "failed" ? 1 : 0;
    skipped += row.status == "skipped" ? 1 : 0;
  }
  std::string r = preamble;
  r += fmt::format("\n{} configurations: {} ok, {} failed, {} skipped. Every row is in `sweep.csv` (timing columns: "
                   "names ending in `_s`).\n\n",
                   rows.size(), ok, failed, skipped);
  r += "Error measure: the **worst normalized RMS error over the judged outputs** named above (study/error_measure.hpp: "
       "the same outputs, window and reference physics as compare and recommend) against the reference; cost: the wall "
       "time of the integration (static equilibrium and mode shapes excluded).\n\n";
  r += "## Pareto-optimal configurations\n\nNo other run is both faster and more accurate.\n\n"
       "| id | model | integrator | worst error | cargo heave error | DAF error | wall time [s] | real-time factor | steps |\n"
       "|--:|---|---|--:|--:|--:|--:|--:|--:|\n";
  for (std::size_t i : pareto_front(rows)) {
    const SweepRow& row = rows[i];
    r += fmt::format("| {} | {} | {} | {} | {} | {} | {:.3g} | {:.3g} | {} |\n", row.id, row.model, row.settings(),
                     sci(row.worst), sci(row.cargo_heave), sci(row.daf_error), *row.wall, duration / *row.wall, row.steps);
  }
  r += "\n## Charts\n\n![accuracy vs speed](accuracy_speed.png)\n\n![error vs basis size](mode_count.png)\n\n";
  r += "## Best run of each model\n\n| model | integrator | worst error | cargo heave error | wall time [s] |\n"
       "|---|---|--:|--:|--:|\n";
  for (const SweepRow* row : best_per_model(rows)) {
    r += fmt::format("| {} | {} | {} | {} | {:.3g} |\n", row->model, row->settings(), sci(row->worst),
                     sci(row->cargo_heave), *row->wall);
  }
  if (failed + skipped > 0) {
    r += "\n## Failed and skipped runs\n\n| id | model | integrator | status | reason |\n|--:|---|---|---|---|\n";
    for (const SweepRow& row : rows) {
      if (row.status == "ok") continue;
      std::string reason = row.reason;
      std::replace(reason.begin(), reason.end(), '|', '/');
      r += fmt::format("| {} | {} | {} | {} | {} |\n", row.id, row.model, row.settings(), row.status, reason);
    }
  }
  return r;
}

std::string sweep_context(const std::string& scene_file, const scene::Scene& scene, study::SweepGrid grid, double duration,
                          const study::SweepStudy& study) {
  return fmt::format(
      "<!-- duration_s: {} -->\n# Accuracy–speed sweep: {}\n\n- scene: `{}`, {:g} s simulated, output every {:g} s\n- {}\n"
      "- geometric stiffening of every run and the reference: {}{}\n- errors against {}, {}, worst over {}\n\n"
      "## Converged reference\n\n{}\n\n{}",
      duration, scene.name.empty() ? scene_file : scene.name, scene_file, duration, scene.simulation.output_interval,
      study::grid_description(grid), scene::to_string(study.stiffening),
      study.stiffening_from_physics ? " (what the physics needs, as recommend decides; --stiffening sets it)" : " (--stiffening)",
      reference_label(study.reference),
      study.window_start > 0.0 ? fmt::format("for t ≥ {:g} s (after the wave ramp)", study.window_start)
                               : std::string("over the whole run"),
      study::output_list(study.judged), reference_verdict(study.reference), reference_levels_markdown(study.reference));
}

double context_duration(const std::string& context) {
  const std::string tag = "<!-- duration_s: ";
  return context.rfind(tag, 0) == 0 ? std::stod(context.substr(tag.size())) : 0.0;
}

std::string pareto_text(const std::vector<SweepRow>& rows) {
  std::string t = fmt::format("{:>4}  {:<26} {:<28} {:>11} {:>10}\n", "id", "model", "integrator", "worst error", "wall [s]");
  for (std::size_t i : pareto_front(rows)) {
    t += fmt::format("{:>4}  {:<26} {:<28} {:>11.3e} {:>10.3g}\n", rows[i].id, rows[i].model, rows[i].settings(),
                     *rows[i].worst, *rows[i].wall);
  }
  return t;
}

void write_sweep_outputs(const std::string& dir, std::vector<SweepRow>& rows, const std::string& context, double duration) {
  StagedDirectory out(dir, "report.md");
  out.write("sweep.csv", sweep_csv(rows));
  out.write(sweep_context_file, context);
  draw_sweep_charts(out, rows, fmt::format("{:g} s simulated", duration));
  out.write("report.md", sweep_markdown(rows, context, duration));
  out.commit();
}

}  // namespace ffrf::report
