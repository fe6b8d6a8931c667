// The sweep's charts (see sweep_report.hpp), drawn by gnuplot from data files written beside them:
//  * accuracy_speed: every ok run, worst error against wall time (log–log); colour = model family,
//    marker = integrator (keyed), the Pareto front as a step line with its points circled and
//    labelled, the tolerance τ of the verdict and the reference's own error floor as lines;
//  * mode_count: the best run of each model against its basis size, modal k (with and without
//    static modes) beside nodal N, the two panels on one y-range, with τ and the reference's floor.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cmath>
#include <map>

#include "report/gnuplot.hpp"
#include "report/sweep_report.hpp"

namespace ffrf::report {
namespace {

struct Style {
  const char* name;
  const char* colour;  // families
  int point;           // integrators
};

constexpr std::array families{Style{"rigid", "#555555", 0}, Style{"nodal", "#1f77b4", 0}, Style{"modal", "#ff7f0e", 0},
                              Style{"modal+static", "#2ca02c", 0}};
// Filled circle, square, triangle, diamond, inverted triangle, pentagon, star.
constexpr std::array integrators{Style{"cvode", "", 7},     Style{"ida", "", 5},       Style{"arkode", "", 9},
                                 Style{"generalized-alpha", "", 13}, Style{"index1", "", 11}, Style{"baumgarte", "", 15},
                                 Style{"projection", "", 3}};

int rgb(const char* hex) { return static_cast<int>(std::strtol(hex + 1, nullptr, 16)); }

const char* family_colour(const std::string& family) {
  for (const Style& s : families) {
    if (family == s.name) return s.colour;
  }
  return "#000000";
}

int integrator_point(const std::string& integrator) {
  for (const Style& s : integrators) {
    if (integrator == s.name) return s.point;
  }
  return 1;
}

std::string script_header(const std::string& name, const std::string& terminal, const std::string& size) {
  return fmt::format(
      "# Drawn by `ffrf sweep --out`; restyle and rerun with `gnuplot {0}.gp` in this directory.\n"
      "set terminal {1} size {2} font ',11'\nset output '{0}.png'\nset grid\nset logscale xy\n"
      "set format y '10^{{%L}}'\n",
      name, terminal, size);
}

// τ and the reference's floor as horizontal lines across the whole plot (arrows, set before the
// plot) and their key entries (plot items).
struct Thresholds {
  std::string arrows, keys;
};
Thresholds threshold_lines(const SweepFacts& facts) {
  Thresholds t;
  t.arrows = fmt::format("set arrow 11 from graph 0, first {0:g} to graph 1, first {0:g} nohead dt 2 lw 2 lc rgb '#d62728'\n",
                         facts.tolerance);
  t.keys = fmt::format(", \\\n     keyentry with lines dt 2 lw 2 lc rgb '#d62728' title 'tolerance τ = {:g}'", facts.tolerance);
  if (std::isfinite(facts.reference_change) && facts.reference_change > 0.0) {
    t.arrows += fmt::format("set arrow 12 from graph 0, first {0:g} to graph 1, first {0:g} nohead dt 3 lw 2 lc rgb 'black'\n",
                            facts.reference_change);
    t.keys += fmt::format(", \\\n     keyentry with lines dt 3 lw 2 lc rgb 'black' title \"reference's own error floor {:.2g}\"",
                          facts.reference_change);
  }
  return t;
}

// The letter marking a run's radiation model on the chart (a sweep of a [bem] scene).
std::string radiation_letter(const std::string& radiation) {
  if (radiation == "constant") return "C";
  if (radiation == "state-space") return "S";
  if (radiation == "convolution") return "V";
  return "?";
}

}  // namespace

std::string pareto_label(const SweepRow& row) {
  std::string model = row.model;
  if (row.family == "nodal") model = fmt::format("N={}", row.elements);
  if (row.family == "modal") model = fmt::format("k={}", row.modes);
  if (row.family == "modal+static") model = fmt::format("k={}+s", row.modes);
  std::string integrator = row.integrator == "generalized-alpha" ? "gα" : row.integrator;
  if (row.rtol && !row.step) integrator += fmt::format(" {:.0e}", *row.rtol);
  if (row.step) integrator += fmt::format(" h={:.2g}s", *row.step);
  return fmt::format("#{} {} {}{}", row.id, model, integrator, row.radiation.empty() ? "" : " " + radiation_letter(row.radiation));
}

std::string pareto_data(const std::vector<SweepRow>& rows) {
  // Label heights: the chart's y axis spans the decades of the ok rows' errors over ~560 pixels; a
  // label is ~15 pixels tall. Going down the front (errors decrease), each label sits at its point's
  // height or, where that would overlap the label above, just below that label.
  double low = INFINITY, high = 0.0;
  for (const SweepRow& row : rows) {
    if (!row.ok() || *row.worst <= 0.0) continue;
    low = std::min(low, *row.worst);
    high = std::max(high, *row.worst);
  }
  const double decades = high > 0.0 ? std::max(1.0, std::ceil(std::log10(high)) - std::floor(std::log10(low))) : 1.0;
  const double spacing = std::pow(10.0, decades * 15.0 / 560.0);  // one label height as a factor
  std::string front = "# wall_s worst_nrms \"label\" id label_y (Pareto front, by wall time; label: #id model integrator)\n";
  double previous = INFINITY;
  for (std::size_t i : pareto_front(rows)) {
    std::string label = pareto_label(rows[i]);
    std::replace(label.begin(), label.end(), '"', '\'');
    const double label_y = std::min(*rows[i].worst, previous / spacing);
    previous = label_y;
    front += fmt::format("{} {} \"{}\" {} {}\n", *rows[i].wall, *rows[i].worst, label, rows[i].id, label_y);
  }
  return front;
}

void draw_sweep_charts(const StagedDirectory& out, const std::vector<SweepRow>& rows, const SweepFacts& facts) {
  const std::string terminal = png_terminal();
  const std::string subtitle = fmt::format("{:g} s simulated, errors against {}", facts.duration, facts.reference);
  // accuracy_speed.dat: one row per ok run: wall, worst, marker, colour, id.
  std::string points = "# wall_s worst_nrms point_type rgb_colour id family integrator\n";
  double wall_low = INFINITY, wall_high = 0.0;
  for (const SweepRow& row : rows) {
    if (!row.ok() || *row.worst <= 0.0) continue;
    wall_low = std::min(wall_low, *row.wall);
    wall_high = std::max(wall_high, *row.wall);
    points += fmt::format("{} {} {} {} {} {} {}\n", *row.wall, *row.worst, integrator_point(row.integrator),
                          rgb(family_colour(row.family)), row.id, row.family, row.integrator);
  }
  if (!(wall_high > 0.0)) wall_low = wall_high = 1.0;  // no ok run: an empty chart on a valid range
  out.write("accuracy_speed.dat", points);
  out.write("pareto.dat", pareto_data(rows));
  // A sweep crossed with the radiation models: each point also carries its model's letter.
  std::string letters = "# wall_s worst_nrms radiation_letter (C constant, S state-space, V convolution)\n";
  bool radiation_axis = false;
  for (const SweepRow& row : rows) {
    if (!row.ok() || *row.worst <= 0.0 || row.radiation.empty()) continue;
    radiation_axis = true;
    letters += fmt::format("{} {} {}\n", *row.wall, *row.worst, radiation_letter(row.radiation));
  }
  if (radiation_axis) out.write("radiation.dat", letters);
  const std::string radiation_plot =
      radiation_axis ? ", \\\n     'radiation.dat' using 1:2:3 with labels offset 0,0.9 font ',8' textcolor rgb '#444444' "
                       "title 'radiation model: C constant, S state-space, V convolution'"
                     : "";
  std::string keys;
  for (const Style& f : families) {
    keys += fmt::format(", \\\n     keyentry with points pt 7 ps 1.5 lc rgb '{}' title '{}'", f.colour, f.name);
  }
  std::map<std::string, bool> used;
  for (const SweepRow& row : rows) used[row.integrator] = used[row.integrator] || row.ok();
  for (const Style& i : integrators) {
    if (used[i.name]) keys += fmt::format(", \\\n     keyentry with points pt {} ps 1.5 lc rgb 'black' title '{}'", i.point, i.name);
  }
  const Thresholds thresholds = threshold_lines(facts);
  std::string script = script_header("accuracy_speed", terminal, "1100,800") + thresholds.arrows;
  script += fmt::format(
      "set title \"Accuracy vs speed: every successful sweep run (colour: model, marker: integrator)\\n{}\\n"
      "Pareto points labelled #id (report.md's table); N = elements, k = vibration modes, +s = static modes\" noenhanced\n"
      "set style textbox opaque noborder margins 1,1\n"
      "set xlabel 'wall time of the integration [s]'\n"
      "set ylabel 'worst normalized RMS error over the judged outputs'\n"
      "set key below horizontal Left reverse maxrows 3 samplen 2 width 2 font ',10'\n"
      "set xrange [{:g}:{:g}]\n"
      "# the Pareto points' labels: right of each point, moved down where they would overlap (column 5)\n"
      "plot 'accuracy_speed.dat' using 1:2:3:4 with points pt variable ps 1.3 lc rgb variable notitle, \\\n"
      "     'pareto.dat' using 1:2 with steps lw 2 lc rgb '#d62728' title 'Pareto front', \\\n"
      "     'pareto.dat' using 1:2 with points pt 6 ps 2.6 lw 1.5 lc rgb '#d62728' notitle, \\\n"
      "     'pareto.dat' using 1:5:3 with labels boxed left offset 1.6,0 font ',8' noenhanced notitle{}{}{}\n",
      subtitle, wall_low / 1.3, wall_high * 6.0, radiation_plot, thresholds.keys, keys);
  draw_chart(out, "accuracy_speed", script);

  // mode_count.dat: best error per model (over its integrator settings) vs k; nodal vs N.
  std::string modes = "# k worst_nrms cargo_heave_nrms (index 0: modal, 1: modal+static, 2: nodal vs N)\n";
  double low = facts.tolerance, high = facts.tolerance;
  int largest_k = 1, largest_n = 1;
  if (std::isfinite(facts.reference_change) && facts.reference_change > 0.0) low = std::min(low, facts.reference_change);
  for (const std::string family : {"modal", "modal+static", "nodal"}) {
    std::map<int, const SweepRow*> best;
    for (const SweepRow* row : best_per_model(rows)) {
      if (row->family == family) best[family == "nodal" ? row->elements : row->modes] = row;
    }
    for (const auto& [count, row] : best) {
      modes += fmt::format("{} {} {}\n", count, *row->worst, row->cargo_heave.value_or(NAN));
      (family == "nodal" ? largest_n : largest_k) = std::max(family == "nodal" ? largest_n : largest_k, count);
      low = std::min(low, *row->worst);
      high = std::max(high, *row->worst);
    }
    if (best.empty()) modes += "NaN NaN NaN\n";
    modes += "\n\n";
  }
  out.write("mode_count.dat", modes);
  const double y_low = std::pow(10.0, std::floor(std::log10(low)));
  const double y_high = std::pow(10.0, std::ceil(std::log10(high)));
  script = script_header("mode_count", terminal, "1200,600") + thresholds.arrows;
  script += fmt::format(
      "set multiplot layout 1,2 title \"Error vs basis size: the best run of each model over its integrator settings\\n{}\" "
      "noenhanced\n"
      "set ylabel 'worst normalized RMS error'\nset yrange [{:g}:{:g}]\nset key below Left reverse font ',10'\nset bmargin 8  # one height for both panels\n"
      "set xlabel 'vibration modes k (N = 16 mesh)'\nset logscale x 2\nset xrange [0.8:{:g}]\nset xtics (1, 2, 3, 4, 6, 8, 12)\n"
      "plot 'mode_count.dat' index 0 using 1:2 with linespoints pt 9 ps 1.3 lw 2 lc rgb '#ff7f0e' title 'modal', \\\n"
      "     '' index 1 using 1:2 with linespoints pt 13 ps 1.3 lw 2 lc rgb '#2ca02c' title 'modal + static modes'{}\n"
      "set xlabel 'elements N'\nset xrange [0.8:{:g}]\nset xtics (1, 2, 4, 8, 16, 32, 64)\n"
      "plot 'mode_count.dat' index 2 using 1:2 with linespoints pt 7 ps 1.3 lw 2 lc rgb '#1f77b4' title 'nodal'{}\n"
      "unset multiplot\n",
      subtitle, y_low, y_high, 1.25 * std::max(2, largest_k), thresholds.keys, 1.25 * std::max(2, largest_n),
      thresholds.keys);
  draw_chart(out, "mode_count", script);
}

}  // namespace ffrf::report
