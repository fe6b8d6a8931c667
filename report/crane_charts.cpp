// gnuplot scripts of the crane time-history charts (see crane_charts.hpp).
#include "report/crane_charts.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "report/gnuplot.hpp"
#include "study/error_split.hpp"
#include "study/output_series.hpp"

namespace ffrf::report {
namespace {

enum class Needs { hull, cargo, wire, luffing, a_frame, boom };

struct Chart {
  const char* name;
  const char* title;
  const char* ylabel;  // with the unit
  const char* unit;    // of the difference panel
  const char* column;  // study/output_series.hpp
  double scale;        // plotted value = column × scale
  Needs needs;
};

constexpr std::array charts{
    Chart{"crane_heave", "Crane heave (G1) about its static equilibrium", "heave [m]", "m", "crane_heave_m", 1.0, Needs::hull},
    Chart{"crane_pitch", "Crane pitch about its static equilibrium (the trim)", "pitch [deg]", "deg", "crane_pitch_deg", 1.0,
          Needs::hull},
    Chart{"cargo_heave", "Cargo heave (G2) about its static equilibrium", "heave [m]", "m", "cargo_heave_m", 1.0, Needs::cargo},
    Chart{"cargo_pitch", "Cargo pitch about its static equilibrium", "pitch [deg]", "deg", "cargo_pitch_deg", 1.0, Needs::cargo},
    Chart{"wire_tension", "Wire rope tension", "tension [MN]", "MN", "wire_tension_N", 1e-6, Needs::wire},
    Chart{"luffing_tension", "Luffing wires' tension (all together)", "tension [MN]", "MN", "luffing_tension_N", 1e-6,
          Needs::luffing},
    Chart{"backstay_tension", "Backstays' tension (all together)", "tension [MN]", "MN", "backstay_tension_N", 1e-6,
          Needs::a_frame},
    Chart{"a_frame_rotation", "A-frame rotation on its deck pin about its static equilibrium", "rotation [deg]", "deg",
          "a_frame_rotation_deg", 1.0, Needs::a_frame},
    Chart{"tip_transverse", "Boom tip transverse elastic deflection (boom frame)", "deflection [m]", "m", "tip_transverse_m",
          1.0, Needs::boom},
    Chart{"tip_axial", "Boom tip axial elastic deflection (boom frame)", "deflection [mm]", "mm", "tip_axial_m", 1e3,
          Needs::boom},
};

// Model colours (colour-blind safe order); the reference is black.
constexpr std::array palette{"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#17becf", "#e377c2"};

const Chart& chart(const std::string& name) {
  for (const Chart& c : charts) {
    if (name == c.name) return c;
  }
  throw std::out_of_range("no chart " + name);
}

bool is_tip(const Chart& c) { return c.needs == Needs::boom; }

std::string using_column(const Chart& c) {
  const std::size_t column = study::series_index(c.column) + 2;  // time_s is column 1
  return c.scale == 1.0 ? fmt::format("1:{}", column) : fmt::format("1:(${} * {:g})", column, c.scale);
}

// The overlay: every model (the rigid boom not on the tip charts), the reference last.
std::string overlay_plot(const Chart& c, const ChartSet& set) {
  std::vector<std::string> plots;
  std::size_t colour = 0;
  for (const ChartSource& s : set.sources) {
    if (s.reference) continue;
    const std::string style = fmt::format("lc rgb '{}'", palette[colour++ % palette.size()]);
    if (is_tip(c) && !s.elastic) continue;
    plots.push_back(fmt::format("{} skip 1 using {} with lines lw 2 {} title {} noenhanced", gnuplot_quoted(s.csv),
                                using_column(c), style, gnuplot_quoted(s.label)));
  }
  for (const ChartSource& s : set.sources) {
    if (!s.reference) continue;
    plots.push_back(fmt::format("{} skip 1 using {} with lines lw 3 dt (8,6) lc rgb 'black' title {} noenhanced",
                                gnuplot_quoted(s.csv), using_column(c), gnuplot_quoted(s.label)));
  }
  return "plot " + fmt::format("{}", fmt::join(plots, ", \\\n     ")) + "\n";
}

// The difference panel: |d − d_ref| per model on a log axis, floored.
std::string difference_plot(const Chart& c, std::size_t chart_index, const ChartSet& set, double floor) {
  std::vector<std::string> plots;
  std::size_t models = 0;
  for (const ChartSource& s : set.sources) models += s.reference ? 0 : 1;
  std::size_t model = 0;
  for (const ChartSource& s : set.sources) {
    if (s.reference) continue;
    const std::size_t m = model++;
    if (is_tip(c) && !s.elastic) continue;
    const std::size_t column = difference_column(chart_index, m, models);
    plots.push_back(fmt::format("{} skip 1 using 1:(floored(${})) with lines lw 1.5 lc rgb '{}' notitle",
                                gnuplot_quoted(set.differences_csv), column, palette[m % palette.size()]));
  }
  // Only rigid booms against the reference on a tip chart: no difference to draw, the panel says so.
  if (plots.empty()) return "set label 3 'no elastic model: a rigid boom has no tip deflection' at graph 0.5, 0.5 center\nplot [GPVAL_X_MIN:GPVAL_X_MAX] [1:10] NaN notitle  # the upper panel's time range\n";
  return fmt::format("floor = {:.3g}\nfloored(x) = abs(x) > floor ? abs(x) : floor\n", floor) + "plot " +
         fmt::format("{}", fmt::join(plots, ", \\\n     ")) + "\n";
}

// The curves a chart would draw: the models that have its output (a rigid boom has no tip
// deflection) and the reference.
std::size_t curve_count(const Chart& c, const ChartSet& set) {
  std::size_t curves = 0;
  for (const ChartSource& s : set.sources) curves += s.reference || !is_tip(c) || s.elastic ? 1 : 0;
  return curves;
}

}  // namespace

std::vector<std::string> crane_chart_names(const scene::Scene& scene) {
  std::vector<std::string> names;
  for (const Chart& c : charts) {
    const bool applies = c.needs == Needs::boom || (c.needs == Needs::hull && scene.hull) ||
                         (c.needs == Needs::cargo && scene.cargo) || (c.needs == Needs::wire && scene.wire) ||
                         (c.needs == Needs::luffing && scene.luffing && scene.boom.mount && scene.boom.mount->pinned) ||
                         (c.needs == Needs::a_frame && scene.a_frame && scene.luffing && scene.boom.mount && scene.boom.mount->pinned);
    if (applies) names.emplace_back(c.name);
  }
  return names;
}

std::string crane_chart_column(const std::string& name) { return chart(name).column; }
double crane_chart_scale(const std::string& name) { return chart(name).scale; }

std::size_t difference_column(std::size_t chart_index, std::size_t model, std::size_t models) {
  return 2 + chart_index * models + model;
}

std::string difference_csv(const study::Comparison& c, const std::vector<std::string>& names) {
  std::vector<const study::ModelRun*> runs;
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    if (c.plotted[m]) runs.push_back(&c.runs[m]);
  }
  std::string csv = "time_s";
  std::vector<std::vector<double>> columns;
  for (const std::string& name : names) {
    const Chart& chart_ = chart(name);
    const study::SeriesSpec& spec = study::crane_series()[study::series_index(chart_.column)];
    for (const study::ModelRun* run : runs) {
      csv += fmt::format(",{}_minus_reference:{}", name, run->choice.label());
      columns.push_back(study::dynamic_difference(*run, c.reference.run, spec));
      for (double& value : columns.back()) value *= chart_.scale;
    }
  }
  csv += '\n';
  const std::vector<double>& time = c.reference.run.result.time;
  for (std::size_t i = 0; i < time.size(); ++i) {
    csv += fmt::format("{:.10g}", time[i]);
    for (const std::vector<double>& column : columns) csv += fmt::format(",{:.9g}", column[i]);
    csv += '\n';
  }
  return csv;
}

std::vector<double> difference_floors(const study::Comparison& c, const std::vector<std::string>& names) {
  std::vector<double> floors;
  const study::ModelRun& reference = c.reference.run;
  for (const std::string& name : names) {
    const Chart& chart_ = chart(name);
    const study::SeriesSpec& spec = study::crane_series()[study::series_index(chart_.column)];
    const double at_rest = spec.value(reference.static_outputs());
    double largest = 0.0;
    for (const multibody::CraneOutputs& sample : reference.result.samples) {
      largest = std::max(largest, std::abs(spec.value(sample) - at_rest) * chart_.scale);
    }
    floors.push_back(std::max(0.01 * c.settings.relative_tolerance * largest, std::numeric_limits<double>::min()));
  }
  return floors;
}

std::string crane_chart_script(const std::string& name, const ChartSet& set, const std::string& terminal) {
  const Chart& c = chart(name);
  const bool differences = !set.differences_csv.empty();
  const std::size_t chart_index =
      static_cast<std::size_t>(std::find(set.names.begin(), set.names.end(), name) - set.names.begin());
  std::string script = fmt::format(
      "# Drawn by `{0}`; restyle and rerun with `gnuplot {1}.gp` in this directory.\n"
      "set terminal {2} size 1000,{3} font ',11'\n"
      "set output '{1}.png'\n"
      "set datafile separator ','\n"
      "set grid\n"
      "set lmargin 12\nset rmargin 4\n",
      set.command, c.name, terminal, differences ? 760 : 500);
  const std::string marker =
      set.window_start > 0.0
          ? fmt::format("set arrow 1 from {0:g}, graph 0 to {0:g}, graph 1 nohead dt 3 lw 1.5 lc rgb '#777777'\n", set.window_start)
          : std::string();
  const std::string window_label =
      set.window_start > 0.0
          ? fmt::format("set label 2 'error window ->' at {:g}, graph 0.05 left offset 0.5,0 font ',9' tc rgb '#555555'\n",
                        set.window_start)
          : std::string();
  const std::string title = gnuplot_lines(c.title, set.subtitle);
  if (!differences) {
    // One model (ffrf run): it is named in the subtitle, no key; several: the key below the plot.
    script += fmt::format("set title {} noenhanced\n{}\nset xlabel 'time [s]'\nset ylabel {} noenhanced\n{}", title,
                          set.sources.size() > 1 ? "set key below horizontal" : "unset key", gnuplot_quoted(c.ylabel), marker);
    return script + overlay_plot(c, set);
  }
  const double floor = chart_index < set.difference_floors.size() ? set.difference_floors[chart_index] : 1e-12;
  script += fmt::format("set multiplot title {} noenhanced\n", title);
  script += fmt::format(
      "# upper panel: every model and the reference\n"
      "set origin 0, 0.40\nset size 1, 0.50\nset bmargin 1\nset tmargin 4\n"
      "set key outside top center horizontal Left reverse maxrows 2 samplen 3 width 1 font ',10'\n"
      "set format x ''\nset ylabel {} noenhanced\n{}{}",
      gnuplot_quoted(c.ylabel), marker, window_label);
  script += overlay_plot(c, set);
  script += "unset label 2\n";
  script += fmt::format(
      "# lower panel: |d - d_ref|, the dynamic difference from the reference (differences.csv)\n"
      "set origin 0, 0\nset size 1, 0.42\nset tmargin 1\nset bmargin 4\nunset key\nset format x '%g'\n"
      "set xlabel 'time [s]'\nset logscale y\nset format y '10^{{%L}}'\n"
      "set ylabel {} noenhanced\n"
      "set offsets 0, 0, graph 0.12, 0  # room for the label above the curves\n"
      "set style textbox opaque noborder\n"
      "set label 1 {} at graph 0.01, graph 0.92 left font ',9' noenhanced front boxed\n{}",
      gnuplot_quoted(fmt::format("|model - reference| [{}]", c.unit)),
      gnuplot_quoted(fmt::format("dynamic difference, each from its own static value; below {:.2g} {} "
                                 "(integration noise) drawn at that floor",
                                 floor, c.unit)),
      marker);
  script += difference_plot(c, chart_index, set, floor);
  return script + "unset multiplot\n";
}

void draw_crane_charts(const StagedDirectory& out, const ChartSet& set) {
  const std::string terminal = png_terminal();
  for (const std::string& name : set.names) {
    const Chart& c = chart(name);
    if (curve_count(c, set) == 0) {
      leave_out_chart(out, name,
                      is_tip(c) ? "a rigid boom has no elastic tip deflection (the column is zero in the CSV)"
                                : "no model has this output");
      continue;
    }
    draw_chart(out, name, crane_chart_script(name, set, terminal));
  }
}

}  // namespace ffrf::report
