// gnuplot scripts and their execution for `ffrf modes --out`.
#include "app/gnuplot.hpp"

#include <array>
#include <cstdio>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ffrf::app {
namespace {

// Quotes a path for /bin/sh.
std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string capture(const std::string& command, int& status) {
  std::string output;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    status = -1;
    return output;
  }
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) output.append(buffer.data(), n);
  status = ::pclose(pipe);
  return output;
}

std::string header(const std::string& terminal, const std::string& output, const std::string& title) {
  return fmt::format(
      "# Drawn by `ffrf modes --out`; restyle and rerun with `gnuplot {0}.gp` in this directory.\n"
      "set terminal {1} size 1000,650 font ',11'\n"
      "set output '{0}.png'\n"
      "set datafile separator ','\n"
      "set key outside right\n"
      "set grid\n"
      "set title '{2}' noenhanced\n",
      output, terminal, title);
}

}  // namespace

std::string png_terminal() {
  int status = 0;
  const std::string terminals = capture("gnuplot -e 'set terminal' 2>&1", status);
  if (status != 0) {
    throw std::runtime_error("gnuplot is needed for the charts of --out but could not be run "
                             "(install it: apt-get install gnuplot-nox)");
  }
  return terminals.find("pngcairo") != std::string::npos ? "pngcairo" : "png";
}

void run_gnuplot(const std::filesystem::path& directory, const std::string& script) {
  int status = 0;
  const std::string output =
      capture(fmt::format("cd {} && gnuplot {} 2>&1", shell_quote(directory.string()), shell_quote(script)), status);
  if (status != 0) throw std::runtime_error(fmt::format("gnuplot {} failed: {}", script, output));
}

std::string mode_shapes_script(const ModesResult& r, const std::string& terminal) {
  std::string script = header(terminal, "mode_shapes",
                              fmt::format("Bending mode shapes, {} elements, {}", r.mesh.element_count,
                                          fem::to_string(r.boundary)));
  script += "set xlabel 'x [m]'\nset ylabel 'transverse v [1/sqrt(kg)] (M-normalized)'\nset xzeroaxis\n";
  std::vector<std::string> curves;
  for (std::size_t j = 0; j < r.modes.size(); ++j) {
    if (r.modes[j].kind != fem::ModeKind::bending) continue;
    // mode_shapes_sampled.csv: column 1 is x_m, then v of mode j+1 in column j + 2.
    curves.push_back(fmt::format("'mode_shapes_sampled.csv' skip 1 using 1:{} with lines lw 2 title 'bending {} ({:.4g} Hz)'",
                                 j + 2, r.modes[j].order, r.modes[j].angular_frequency / (2 * 3.14159265358979323846)));
  }
  if (curves.empty()) {
    script += "set label 'no bending modes among the computed modes' at graph 0.5, 0.5 center\n"
              "plot [0:1] [-1:1] NaN notitle\n";
  } else {
    script += "plot " + fmt::format("{}", fmt::join(curves, ", \\\n     ")) + "\n";
  }
  return script;
}

std::string convergence_script(const ModesResult& r, const std::string& terminal) {
  std::string script = header(terminal, "frequency_convergence",
                              fmt::format("Bending frequency error vs elements, {}, {} solver",
                                          fem::to_string(r.boundary), modal::to_string(r.solver)));
  script +=
      "set logscale xy\n"
      "set format y '10^{%L}'\n"
      "set xlabel 'elements N'\n"
      "set ylabel '|f_{FE} - f_{analytic}| / f_{analytic}'\n"
      "set xtics (2, 4, 8, 16, 32, 64, 128)\n"
      "plot for [k=1:4] 'frequency_convergence.csv' skip 1 using 1:(column(k+2) > 0 ? column(k+2) : NaN) \\\n"
      "       with linespoints pt 7 title sprintf('f%d', k), \\\n"
      "     'frequency_convergence.csv' skip 1 using 1:(column(3) > 0 ? 1e-3 * (4.0 / $1)**4 : NaN) \\\n"
      "       with lines dt 2 lc 'gray' title 'slope -4'\n";
  return script;
}

}  // namespace ffrf::app
