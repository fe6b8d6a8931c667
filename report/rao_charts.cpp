// The gnuplot charts of the frequency domain (report/rao_charts.hpp).
#include "report/rao_charts.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "report/gnuplot.hpp"
#include "report/quantities.hpp"
#include "report/rao_report.hpp"

namespace ffrf::report {
namespace {

using multibody::LinearOutput;

struct Chart {
  const char* name;
  const char* title;
  std::array<LinearOutput, 3> outputs;
};
constexpr std::array<Chart, 3> charts{{
    {"rao_hull", "Hull RAOs", {LinearOutput::hull_surge, LinearOutput::hull_heave, LinearOutput::hull_pitch}},
    {"rao_cargo", "Cargo RAOs", {LinearOutput::cargo_surge, LinearOutput::cargo_heave, LinearOutput::cargo_pitch}},
    {"rao_boom_wire", "Boom tip (elastic deflection) and wire tension RAOs",
     {LinearOutput::tip_transverse, LinearOutput::tip_axial, LinearOutput::wire_tension}},
}};

const Chart& chart_named(const std::string& name) {
  const auto chart = std::find_if(charts.begin(), charts.end(), [&](const Chart& c) { return name == c.name; });
  if (chart == charts.end()) throw std::invalid_argument("rao chart: unknown chart " + name);
  return *chart;
}


// The band's periods [s]: shortest, longest.
std::pair<double, double> period_range(const study::RaoResult& result) {
  const auto [low, high] = std::minmax_element(result.angular_frequencies.begin(), result.angular_frequencies.end());
  return {period_of(*high), period_of(*low)};
}

// Dashed vertical lines at every model's resonant natural periods inside the band, labelled once
// per distinct period (within 1 %).
std::string natural_period_marks(const study::RaoResult& result) {
  const auto [shortest, longest] = period_range(result);
  std::string out = "# natural periods of the coupled modes (dashed, in the model's colour)\n";
  std::vector<double> labelled;
  int tag = 10;
  for (std::size_t m = 0; m < result.models.size(); ++m) {
    const auto& modes = result.models[m].modes;
    for (std::size_t j = 0; j < modes.size(); ++j) {
      const double period = modes[j].period();
      if (!modes[j].resonant() || period < shortest || period > longest) continue;
      out += fmt::format("set arrow {} from {:.6g}, graph 0 to {:.6g}, graph 1 nohead dt 2 lw 1 lc {} back\n", tag, period, period, m + 1);
      const bool seen = std::any_of(labelled.begin(), labelled.end(), [&](double t) { return std::abs(t / period - 1.0) < 0.01; });
      if (!seen) {
        labelled.push_back(period);
        out += fmt::format("set label {} {} at {:.6g}, graph 0.98 rotate by 90 right font ',8' tc lt {} noenhanced front\n", tag,
                           gnuplot_quoted(fmt::format(" T{} {} {:.4g} s", j + 1, modes[j].dominant, period)), period, m + 1);
      }
      ++tag;
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> rao_chart_names() {
  std::vector<std::string> names;
  for (const Chart& chart : charts) names.emplace_back(chart.name);
  return names;
}

std::string rao_chart_title(const std::string& name) { return chart_named(name).title; }

bool rao_drawn(const study::ModelRao& model, LinearOutput output) {
  return model.choice.kind != scene::BoomKind::rigid || (output != LinearOutput::tip_axial && output != LinearOutput::tip_transverse);
}

std::string spectrum_label(const hydro::WaveSpectrum& spectrum) {
  switch (spectrum.kind) {
    case hydro::SpectrumKind::jonswap:
      return fmt::format("JONSWAP Hs {:g} m, Tp {:g} s, γ {:g}", spectrum.significant_height, spectrum.peak_period,
                         spectrum.peak_enhancement);
    case hydro::SpectrumKind::pierson_moskowitz:
      return fmt::format("Pierson–Moskowitz Hs {:g} m, Tp {:g} s", spectrum.significant_height, spectrum.peak_period);
    case hydro::SpectrumKind::tabulated: return "tabulated spectrum";
  }
  return "spectrum";
}

std::string sea_spectrum_csv(const study::RaoResult& result) {
  if (!result.sea) throw std::invalid_argument("sea_spectrum_csv: the result has no sea spectrum");
  const auto [shortest, longest] = period_range(result);
  std::string out = "period_s,angular_frequency_rad_per_s,density_m2_s_per_rad\n";
  constexpr int points = 400;
  for (int i = 0; i < points; ++i) {
    const double period = shortest + (longest - shortest) * i / (points - 1), omega = period_of(period);
    out += fmt::format("{:.10g},{:.10g},{:.10g}\n", period, omega, hydro::spectral_density(result.sea->spectrum, omega));
  }
  return out;
}

std::string rao_chart_script(const std::string& name, const study::RaoResult& result, const std::string& terminal) {
  const Chart& chart = chart_named(name);
  const auto [shortest, longest] = period_range(result);
  std::string script = fmt::format(
      "# Drawn by `ffrf rao --out`; restyle and rerun with `gnuplot {0}.gp` in this directory.\n"
      "set terminal {1} size 1500,860 font ',11'\n"
      "set output '{0}.png'\n"
      "set datafile separator ','\n"
      "set grid\n"
      "set xrange [{3:.6g}:{4:.6g}]\n"
      "set multiplot layout 2,3 title {2} noenhanced\n",
      chart.name, terminal, gnuplot_quoted(std::string(chart.title) + " per metre of wave amplitude"), shortest, longest);
  script += natural_period_marks(result);
  for (const bool amplitude : {true, false}) {
    for (const LinearOutput output : chart.outputs) {
      const int k = static_cast<int>(output);
      std::vector<std::string> curves;
      for (std::size_t m = 0; m < result.models.size(); ++m) {
        if (!rao_drawn(result.models[m], output)) continue;
        curves.push_back(fmt::format("'rao_{}.csv' skip 1 using 1:{} with lines lw 2 lc {} title {}",
                                     model_slug(result.models[m].choice), amplitude ? 3 + 2 * k : 4 + 2 * k, m + 1,
                                     gnuplot_quoted(result.models[m].choice.label())));
      }
      const bool sea = amplitude && result.sea && !curves.empty();
      if (sea) {
        curves.push_back(fmt::format("'sea_spectrum.csv' skip 1 using 1:3 axes x1y2 with lines dt 3 lw 2 lc 'gray40' title {}",
                                     gnuplot_quoted(spectrum_label(result.sea->spectrum))));
      }
      const std::string name_text(multibody::to_string(output));
      script += fmt::format("set title {} noenhanced\nset xlabel 'wave period [s]'\n",
                            gnuplot_quoted(name_text + (amplitude ? " amplitude" : " phase")));
      script += amplitude ? fmt::format("set logscale y\nset format y '%g'\nset ylabel '[{}]'\nset yrange [*:*]\n", multibody::unit_per_amplitude(output))
                          : "unset logscale y\nset format y '%g'\nset ylabel 'phase vs elevation at x = 0 [deg]'\nset yrange [-180:180]\n";
      script += sea ? "set ytics nomirror\nset y2tics\nset y2range [0:*]\nset y2label 'sea S(ω) [m² s/rad]'\n"
                    : "set ytics mirror\nunset y2tics\nunset y2label\n";
      if (curves.empty()) {
        script += "unset key\nunset logscale y\nset label 1 'zero for the rigid boom' at graph 0.5, 0.5 center\nplot [] [0:1] NaN notitle\n"
                  "unset label 1\n";
      } else {
        script += fmt::format("set key opaque box bottom right font ',9'\nplot {}\n", fmt::join(curves, ", \\\n     "));
      }
    }
  }
  return script + "unset multiplot\n";
}

}  // namespace ffrf::report
