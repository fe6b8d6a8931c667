// gnuplot scripts of the crane time-history charts (see crane_charts.hpp).
#include "report/crane_charts.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <stdexcept>

#include "study/output_series.hpp"
#include "report/gnuplot.hpp"

namespace ffrf::report {
namespace {

struct Curve {
  const char* column;
  double scale;        // plotted value = column × scale
  const char* suffix;  // appended to the model label when a chart has several curves per model
};

struct Chart {
  const char* name;
  const char* title;
  const char* ylabel;
  std::array<Curve, 2> curves;  // second one unused when its column is null
};

constexpr std::array charts{
    Chart{"crane_heave", "Crane heave (G1) about static equilibrium", "heave [m]", {{{"crane_heave_m", 1.0, ""}, {}}}},
    Chart{"crane_pitch", "Crane pitch about static equilibrium (trim)", "pitch [deg]",
          {{{"crane_pitch_deg", 1.0, ""}, {}}}},
    Chart{"cargo_heave", "Cargo heave (G2) about static equilibrium", "heave [m]", {{{"cargo_heave_m", 1.0, ""}, {}}}},
    Chart{"cargo_pitch", "Cargo pitch about static equilibrium", "pitch [deg]", {{{"cargo_pitch_deg", 1.0, ""}, {}}}},
    Chart{"wire_tension", "Wire rope tension", "tension [MN]", {{{"wire_tension_N", 1e-6, ""}, {}}}},
    Chart{"tip_deflection", "Boom tip elastic deflection in the boom frame", "deflection [m]",
          {{{"tip_transverse_m", 1.0, " transverse"}, {"tip_axial_m", 1.0, " axial"}}}},
};

const Chart& chart(const std::string& name) {
  for (const Chart& c : charts) {
    if (name == c.name) return c;
  }
  throw std::out_of_range("no chart " + name);
}

}  // namespace

std::vector<std::string> crane_chart_names() {
  std::vector<std::string> names;
  for (const Chart& c : charts) names.emplace_back(c.name);
  return names;
}

std::string crane_chart_script(const std::string& name, const std::vector<ChartSource>& sources,
                               const std::string& terminal, const std::string& subtitle, const std::string& command) {
  const Chart& c = chart(name);
  std::string script = fmt::format(
      "# Drawn by `{0}`; restyle and rerun with `gnuplot {1}.gp` in this directory.\n"
      "set terminal {2} size 1000,500 font ',11'\n"
      "set output '{1}.png'\n"
      "set datafile separator ','\n"
      "set key outside right\n"
      "set grid\n"
      "set title {3} noenhanced\n"
      "set xlabel 'time [s]'\n"
      "set ylabel {4} noenhanced\n",
      command, c.name, terminal, gnuplot_lines(c.title, subtitle), gnuplot_quoted(c.ylabel));
  std::vector<std::string> plots;
  for (std::size_t m = 0; m < sources.size(); ++m) {
    for (std::size_t k = 0; k < c.curves.size(); ++k) {
      const Curve& curve = c.curves[k];
      if (curve.column == nullptr) continue;
      const std::size_t column = study::series_index(curve.column) + 2;  // time_s is column 1
      const std::string using_ = curve.scale == 1.0 ? fmt::format("1:{}", column)
                                                    : fmt::format("1:(${} * {})", column, curve.scale);
      // Colour and dash pattern by model (overlapping curves stay visible), width by curve.
      plots.push_back(fmt::format("{} skip 1 using {} with lines lw {} lc {} dt {} title {} noenhanced",
                                  gnuplot_quoted(sources[m].csv), using_, k == 0 ? 2 : 1, m + 1, m + 1,
                                  gnuplot_quoted(sources[m].label + curve.suffix)));
    }
  }
  script += "plot " + fmt::format("{}", fmt::join(plots, ", \\\n     ")) + "\n";
  return script;
}

void draw_crane_charts(const StagedDirectory& out, const std::vector<ChartSource>& sources, const std::string& subtitle,
                       const std::string& command) {
  const std::string terminal = png_terminal();
  for (const std::string& name : crane_chart_names()) {
    out.write(name + ".gp", crane_chart_script(name, sources, terminal, subtitle, command));
    run_gnuplot(out.staging(), name + ".gp");
  }
}

}  // namespace ffrf::report
