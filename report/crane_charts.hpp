// The time-history charts of `ffrf run` and `ffrf compare` (crane heave and pitch, cargo heave and
// pitch like the paper's Figs. 8–11, wire tension, and the boom tip's transverse and axial
// deflection — 2 m against 8 mm, so each on its own axis) as gnuplot scripts over the time-series
// CSV files (one curve per model). Only the charts of what the scene has are drawn: crane charts
// need a hull, cargo charts a cargo, the wire chart a wire. With a reference (compare), the
// reference is drawn last (thick dashed black) and a difference panel under each overlay draws
// |d − d_ref| on a log axis from differences.csv: the dynamic difference of each model from the
// reference (study/error_split.hpp), what the dynamic error measures.
#pragma once

#include <string>
#include <vector>

#include "report/output_directory.hpp"
#include "scene/scene.hpp"
#include "study/compare.hpp"

namespace ffrf::report {

struct ChartSource {
  std::string csv;         // file name in the output directory
  std::string label;       // curve title ("nodal N=16")
  bool elastic = true;     // false: a rigid boom, left off the tip-deflection charts (it has none)
  bool reference = false;  // the reference: drawn last, thick dashed black; the differences are against it
};

// The charts that apply to the scene (script NAME.gp draws NAME.png), in report order.
std::vector<std::string> crane_chart_names(const scene::Scene& scene);
// The time-series column (study/output_series.hpp) a chart draws, and the factor to its axis unit.
std::string crane_chart_column(const std::string& name);
double crane_chart_scale(const std::string& name);

// What the charts of one command draw.
struct ChartSet {
  std::vector<ChartSource> sources;  // at most one reference
  std::vector<std::string> names;    // crane_chart_names(scene)
  std::string subtitle;
  std::string command;               // the program that drew them ("ffrf run --out")
  double window_start = 0.0;         // marked by a dotted line when > 0 (the error window starts)
  // compare: differences.csv (difference_csv) and, per chart, the log axis' floor (difference_floors).
  std::string differences_csv;
  std::vector<double> difference_floors;
};

// differences.csv: time_s, then for each chart of `names` and each non-reference source of the
// comparison's plotted runs (in run order) the dynamic difference d − d_ref in the chart's unit.
std::string difference_csv(const study::Comparison& comparison, const std::vector<std::string>& names);
// Column (1-based) of chart `chart` and model `model` in differences.csv with `models` models.
std::size_t difference_column(std::size_t chart, std::size_t model, std::size_t models);
// The difference panels' floors: 1 % of the models' relative tolerance times the largest |d_ref| of
// each chart's quantity — differences below are integration noise (the floor is drawn, not hidden),
// at least the smallest positive double.
std::vector<double> difference_floors(const study::Comparison& comparison, const std::vector<std::string>& names);

// The gnuplot script of one chart.
std::string crane_chart_script(const std::string& name, const ChartSet& set, const std::string& terminal);

// Writes every chart's script into the staging directory and runs gnuplot on it (the CSV files
// must be written first); a chart with no curve (the tip charts of a rigid boom alone) is left out,
// one gnuplot fails on is recorded (report/gnuplot.hpp's draw_chart); throws std::runtime_error only
// when gnuplot is missing.
void draw_crane_charts(const StagedDirectory& out, const ChartSet& set);

}  // namespace ffrf::report
