// The operability chart and its limit contour (see operability_chart.hpp).
#include "report/operability_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "report/gnuplot.hpp"
#include "report/quantities.hpp"

namespace ffrf::report {
namespace {

using study::CellResult;
using study::CellStatus;


// Half the spacing of an evenly spaced axis (1 for a single value): the half-width of a cell's box.
double half_step(const std::vector<double>& axis) {
  return axis.size() < 2 ? 0.5 : 0.5 * (axis.back() - axis.front()) / static_cast<double>(axis.size() - 1);
}

struct Look {
  const char* title;
  const char* fill;    // gnuplot fill style
  const char* colour;  // box colour
  const char* text;    // label colour
};
const std::map<CellStatus, std::array<Look, 2>> looks{
    // [0]: fail or the only look, [1]: pass
    {CellStatus::ok, {Look{"fail (u > 1)", "solid 1.0 border lc rgb 'black'", "#b2182b", "white"},
                      Look{"pass (u <= 1)", "solid 1.0 border lc rgb 'black'", "#a6dba0", "black"}}},
    {CellStatus::not_physical, {Look{"not physical (too steep)", "pattern 4 border lc rgb 'black'", "#808080", "black"},
                                Look{}}},
    {CellStatus::failed, {Look{"run failed", "empty border lc rgb 'black'", "black", "black"}, Look{}}},
};

}  // namespace

std::vector<ContourSegment> level_contour(const std::vector<double>& x, const std::vector<double>& y,
                                          const std::vector<double>& values, double level) {
  std::vector<ContourSegment> segments;
  const std::size_t nx = x.size();
  const auto at = [&](std::size_t i, std::size_t j) { return values[j * nx + i]; };
  for (std::size_t j = 0; j + 1 < y.size(); ++j) {
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      // Corners counter-clockwise from (i, j); edge k runs from corner k to corner k + 1.
      const std::array<double, 4> cx{x[i], x[i + 1], x[i + 1], x[i]}, cy{y[j], y[j], y[j + 1], y[j + 1]};
      const std::array<double, 4> v{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      if (std::any_of(v.begin(), v.end(), [](double u) { return std::isnan(u); })) continue;
      std::vector<std::array<double, 2>> crossings;  // in edge order
      for (std::size_t k = 0; k < 4; ++k) {
        const std::size_t l = (k + 1) % 4;
        if ((v[k] > level) == (v[l] > level)) continue;
        const double t = (level - v[k]) / (v[l] - v[k]);
        crossings.push_back({cx[k] + t * (cx[l] - cx[k]), cy[k] + t * (cy[l] - cy[k])});
      }
      if (crossings.size() == 2) {
        segments.push_back({crossings[0][0], crossings[0][1], crossings[1][0], crossings[1][1]});
      } else if (crossings.size() == 4) {
        // A saddle: corners 0 and 2 on one side, 1 and 3 on the other. When the centre lies on corner
        // 0's side, the line separates corners 1 and 3 from it: it joins edges (0, 1) and (2, 3).
        const bool centre_like_corner0 = ((v[0] + v[1] + v[2] + v[3]) / 4.0 > level) == (v[0] > level);
        const std::array<std::size_t, 4> pair = centre_like_corner0 ? std::array<std::size_t, 4>{0, 1, 2, 3}
                                                                    : std::array<std::size_t, 4>{3, 0, 1, 2};
        for (std::size_t p = 0; p < 4; p += 2) {
          segments.push_back({crossings[pair[p]][0], crossings[pair[p]][1], crossings[pair[p + 1]][0], crossings[pair[p + 1]][1]});
        }
      }
    }
  }
  return segments;
}

void draw_operability_chart(const StagedDirectory& out, const study::OperabilityStudy& s) {
  std::vector<hydro::WaveHeading> headings;
  for (const CellResult& c : s.cells) {
    if (std::find(headings.begin(), headings.end(), c.cell.heading) == headings.end()) headings.push_back(c.cell.heading);
  }
  std::string data, panels;
  int block = 0;
  std::size_t largest_axis = 1;
  for (hydro::WaveHeading heading : headings) {
    std::set<double> tp_set, hs_set;
    for (const CellResult& c : s.cells) {
      if (c.cell.heading != heading) continue;
      tp_set.insert(c.cell.peak_period);
      hs_set.insert(c.cell.significant_height);
    }
    const std::vector<double> tp(tp_set.begin(), tp_set.end()), hs(hs_set.begin(), hs_set.end());
    largest_axis = std::max({largest_axis, tp.size(), hs.size()});
    const double dx = half_step(tp), dy = half_step(hs);
    std::vector<std::string> series;
    // One block per look, with each cell's box and its label's two lines (criterion, utilisation).
    for (const auto& [status, variants] : looks) {
      for (std::size_t variant = 0; variant < 2; ++variant) {
        const Look& look = variants[variant];
        if (look.title == nullptr) continue;
        std::string points;
        for (const CellResult& c : s.cells) {
          if (c.cell.heading != heading || c.status() != status) continue;
          if (status == CellStatus::ok && c.verdict.pass != (variant == 1)) continue;
          const std::string upper = status == CellStatus::ok             ? std::string(study::to_string(c.verdict.governing))
                                    : status == CellStatus::not_physical ? std::string("not")
                                                                         : std::string("run");
          const std::string lower = status == CellStatus::ok ? fmt::format("{:.2f}", c.verdict[c.verdict.governing].utilisation)
                                    : status == CellStatus::not_physical ? std::string("physical")
                                                                         : std::string("failed");
          points += fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} \"{}\" \"{}\"\n", c.cell.peak_period,
                                c.cell.significant_height, dx, dy, upper, lower);
        }
        if (points.empty()) continue;
        data += fmt::format("# {} {}\n{}\n\n", heading_name(heading), look.title, points);
        series.push_back(fmt::format("'operability.dat' index {} using 1:2:3:4 with boxxyerror fs {} lc rgb '{}' title '{}'",
                                     block, look.fill, look.colour, look.title));
        for (const auto& [column, offset] : {std::pair{5, "0.6"}, std::pair{6, "-0.6"}}) {
          series.push_back(fmt::format("'operability.dat' index {} using 1:2:{} with labels offset 0,{} tc rgb '{}' "
                                       "font ',__FONT__' notitle",
                                       block, column, offset, look.text));
        }
        ++block;
      }
    }
    // The limit contour: u = 1 of the governing utilisation over the cells with a verdict.
    std::vector<double> governing(tp.size() * hs.size(), std::nan(""));
    for (const CellResult& c : s.cells) {
      if (c.cell.heading != heading || c.status() != CellStatus::ok) continue;
      const auto i = static_cast<std::size_t>(std::find(tp.begin(), tp.end(), c.cell.peak_period) - tp.begin());
      const auto j = static_cast<std::size_t>(std::find(hs.begin(), hs.end(), c.cell.significant_height) - hs.begin());
      governing[j * tp.size() + i] = c.verdict[c.verdict.governing].utilisation;
    }
    std::string contour;
    for (const ContourSegment& g : level_contour(tp, hs, governing, 1.0)) {
      contour += fmt::format("{:.17g} {:.17g}\n{:.17g} {:.17g}\n\n", g.x0, g.y0, g.x1, g.y1);
    }
    if (!contour.empty()) {
      data += fmt::format("# {} limit contour u = 1 (segments)\n{}\n", heading_name(heading), contour);
      series.push_back(fmt::format("'operability.dat' index {} using 1:2 with lines lw 4 lc rgb 'black' title 'limit u = 1'", block++));
    }
    panels += fmt::format("set title '{} sea: verdict by fill, governing criterion and utilisation in each cell'\n"
                          "set xrange [{:.17g}:{:.17g}]\nset yrange [{:.17g}:{:.17g}]\nplot ",
                          heading_name(heading), tp.front() - dx, tp.back() + dx, hs.front() - dy, hs.back() + dy);
    for (std::size_t i = 0; i < series.size(); ++i) panels += (i ? ", \\\n     " : "") + series[i];
    panels += "\n";
  }
  // Labels shrink with the grid so that they fit their boxes.
  const int font = std::clamp(static_cast<int>(std::lround(40.0 / static_cast<double>(largest_axis))), 7, 12);
  for (std::size_t at; (at = panels.find("__FONT__")) != std::string::npos;) panels.replace(at, 8, std::to_string(font));
  const int width = 960 * static_cast<int>(headings.size());
  std::string script = fmt::format(
      "# Operability map: Hs over Tp, one box per cell. Fill: the verdict (light green pass, dark red fail, grey\n"
      "# hatching: too steep to exist, white: a record failed); label: the governing criterion and its utilisation\n"
      "# (1 = at the limit); thick black line: the limit contour u = 1. Data: operability.dat.\n"
      "set terminal {} size {},640 font ',11' noenhanced\nset output 'operability.png'\n"
      "set key outside below horizontal\nset xlabel 'peak period Tp [s]'\nset ylabel 'significant wave height Hs [m]'\n"
      "set style fill solid 1.0 border lc rgb 'black'\nset multiplot layout 1,{}\n",
      png_terminal(), width, headings.size());
  script += panels + "unset multiplot\n";
  out.write("operability.dat", data);
  draw_chart(out, "operability", script);
}

}  // namespace ffrf::report
