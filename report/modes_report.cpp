// Text, JSON and CSV renderings of a study::ModesResult.
#include "report/modes_report.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <numbers>

#include "report/gnuplot.hpp"
#include "report/json.hpp"
#include "fem/point_shape.hpp"
#include "report/quantities.hpp"

namespace ffrf::report {
namespace {


std::optional<double> relative_error(const modal::ClassifiedMode& mode) {
  if (!mode.analytic_frequency || *mode.analytic_frequency <= 0.0) return std::nullopt;
  return std::abs(mode.angular_frequency - *mode.analytic_frequency) / *mode.analytic_frequency;
}

std::string header(const std::string& terminal, const std::string& output, const std::string& title) {
  return fmt::format(
      "# Drawn by `ffrf modes --out`; restyle and rerun with `gnuplot {0}.gp` in this directory.\n"
      "set terminal {1} size 1000,650 font ',11'\n"
      "set output '{0}.png'\n"
      "set datafile separator ','\n"
      "set key below horizontal Left reverse\n"
      "set grid\n"
      "set title '{2}' noenhanced\n",
      output, terminal, title);
}

std::string supported_table(const study::SupportedBoomModes& s) {
  std::string out = fmt::format(
      "\nsupported boom: pinned at its heel on the held deck, on its luffing wires ({:.6g} kN together at rest),\n"
      "under its own weight, without the cargo; nodal N = {}, linearised about that equilibrium\n",
      s.luffing_tension / 1e3, s.elements);
  if (s.a_frame) {
    out += fmt::format("the A-frame rocks on its deck pin, held by its backstays ({:.6g} kN together at rest)\n",
                       s.backstay_tension / 1e3);
  }
  out += fmt::format("{:>4}  {:<8} {:>16}  {:>10}  {:>10}  {:>20}  {:>8}", "mode", "kind", "f [Hz]", "boom strain",
                     "axial share", "f pinned-pinned [Hz]", "ratio");
  out += s.a_frame ? fmt::format("  {:>10}\n", "A-frame") : "\n";
  for (std::size_t j = 0; j < s.modes.size(); ++j) {
    const study::SupportedBoomMode& m = s.modes[j];
    const bool bending = m.kind == study::SupportedBoomMode::Kind::bending;
    out += fmt::format("{:>4}  {:<8} {:>16.10g}  {:>10.3f}  {:>10.3f}  {:>20}  {:>8}", j + 1, study::to_string(m.kind), m.hz,
                       m.strain_share, m.axial_share, bending ? fmt::format("{:.10g}", m.pinned_pinned_hz) : "-",
                       bending ? fmt::format("{:.4f}", m.hz / m.pinned_pinned_hz) : "-");
    out += s.a_frame ? fmt::format("  {:>10.3f}\n", m.a_frame_share) : "\n";
  }
  if (s.a_frame) out += "(A-frame: the share of the mode's kinetic energy in the A-frame's rocking; over half: an A-frame mode)\n";
  out += "(boom strain: the share of the mode's potential energy the boom's deformation stores, the wires and gravity the\n"
         " rest; swing: under half, the boom turning about its heel on the wires' spring; axial share: of its kinetic\n"
         " energy; pinned-pinned: the simply supported span's Euler-Bernoulli bending frequency, which the supported\n"
         " boom approaches as its wires stiffen)\n";
  return out;
}

}  // namespace

std::string supported_boom_csv(const study::SupportedBoomModes& s) {
  std::string csv = "mode,kind,frequency_hz,boom_strain_energy_share,axial_energy_share,bending_order,pinned_pinned_frequency_hz";
  csv += s.a_frame ? ",a_frame_energy_share\n" : "\n";
  for (std::size_t j = 0; j < s.modes.size(); ++j) {
    const study::SupportedBoomMode& m = s.modes[j];
    csv += fmt::format("{},{},{:.10g},{:.6g},{:.6g},{},{:.10g}", j + 1, study::to_string(m.kind), m.hz, m.strain_share,
                       m.axial_share, m.bending_order, m.pinned_pinned_hz);
    csv += s.a_frame ? fmt::format(",{:.6g}\n", m.a_frame_share) : "\n";
  }
  return csv;
}

std::string modes_table(const study::ModesResult& r, const ModesContext& context) {
  const modal::EigenStats& stats = r.pairs.stats;
  std::string out;
  out += fmt::format("scene      {}{}\n", context.scene_file, context.scene_name.empty() ? "" : " (" + context.scene_name + ")");
  out += fmt::format("beam       L = {:g} m, EI = {:.6g} N m^2, EA = {:.6g} N, rhoA = {:.6g} kg/m\n", r.mesh.length,
                     r.mesh.section.bending_rigidity(), r.mesh.section.axial_rigidity(), r.mesh.section.mass_per_length);
  out += fmt::format("mesh       N = {} elements, {} free DOFs, {}\n", r.mesh.element_count, r.dofs.free_count(),
                     fem::to_string(r.boundary));
  out += fmt::format("solver     {}, shift sigma = {:.6g} rad^2/s^2, {} modes\n", modal::to_string(r.solver), r.shift,
                     r.modes.size());
  out += fmt::format("stats      {} iterations, {} operator applications, {} converged\n", stats.iterations,
                     stats.operator_applications, stats.converged);
  out += fmt::format("time       assembly {:.3g} s, eigen solve {:.3g} s\n\n", r.assembly_seconds, r.solve_seconds);
  out += fmt::format("{:>4}  {:<8} {:>5}  {:>16}  {:>16}  {:>10}\n", "mode", "kind", "order", "f FE [Hz]",
                     "f analytic [Hz]", "rel. error");
  for (std::size_t j = 0; j < r.modes.size(); ++j) {
    const modal::ClassifiedMode& mode = r.modes[j];
    const auto error = relative_error(mode);
    out += fmt::format("{:>4}  {:<8} {:>5}  {:>16.10g}  {:>16}  {:>10}\n", j + 1, fem::to_string(mode.kind), mode.order,
                       hertz(mode.angular_frequency),
                       mode.analytic_frequency ? fmt::format("{:.10g}", hertz(*mode.analytic_frequency)) : "-",
                       error ? fmt::format("{:.2e}", *error) : "-");
  }
  if (r.supported) out += supported_table(*r.supported);
  return out;
}

std::string modes_json(const study::ModesResult& r, const ModesContext& context,
                       const std::vector<study::ConvergencePoint>& convergence) {
  const auto optional_number = [](const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); };
  Json json{{"scene", context.scene_file},
            {"scene_name", context.scene_name},
            {"elements", r.mesh.element_count},
            {"dof", r.dofs.free_count()},
            {"boundary", fem::to_string(r.boundary)},
            {"solver", modal::to_string(r.solver)},
            {"shift_rad2_per_s2", r.shift},
            {"mode_count", r.modes.size()}};
  json["section"] = Json{{"length_m", r.mesh.length},
                         {"youngs_modulus_Pa", r.mesh.section.youngs_modulus},
                         {"area_m2", r.mesh.section.area},
                         {"second_moment_m4", r.mesh.section.second_moment},
                         {"mass_per_length_kg_per_m", r.mesh.section.mass_per_length}};
  json["timings_s"] = Json{{"assembly", r.assembly_seconds}, {"solve", r.solve_seconds}};
  json["solver_stats"] = Json{{"iterations", r.pairs.stats.iterations},
                              {"operator_applications", r.pairs.stats.operator_applications},
                              {"converged", r.pairs.stats.converged}};
  json["warnings"] = r.warnings;
  json["frequencies_hz"] = Json::array();
  for (const modal::ClassifiedMode& mode : r.modes) json["frequencies_hz"].push_back(hertz(mode.angular_frequency));
  json["modes"] = Json::array();
  for (std::size_t j = 0; j < r.modes.size(); ++j) {
    const modal::ClassifiedMode& mode = r.modes[j];
    json["modes"].push_back(Json{
        {"mode", j + 1},
        {"kind", fem::to_string(mode.kind)},
        {"order", mode.order},
        {"frequency_hz", hertz(mode.angular_frequency)},
        {"analytic_frequency_hz",
         optional_number(mode.analytic_frequency ? std::optional<double>(hertz(*mode.analytic_frequency)) : std::nullopt)},
        {"relative_error", optional_number(relative_error(mode))},
        {"axial_energy_share", mode.axial_energy_share}});
  }
  if (r.supported) {
    Json modes = Json::array();
    for (const study::SupportedBoomMode& m : r.supported->modes) {
      const bool bending = m.kind == study::SupportedBoomMode::Kind::bending;
      modes.push_back(Json{{"kind", study::to_string(m.kind)},
                           {"frequency_hz", m.hz},
                           {"boom_strain_energy_share", m.strain_share},
                           {"axial_energy_share", m.axial_share},
                           {"a_frame_energy_share", m.a_frame_share},
                           {"bending_order", m.bending_order},
                           {"pinned_pinned_frequency_hz", bending ? Json(m.pinned_pinned_hz) : Json(nullptr)}});
    }
    json["supported_boom"] = Json{{"elements", r.supported->elements},
                                  {"luffing_tension_N", r.supported->luffing_tension},
                                  {"backstay_tension_N", r.supported->backstay_tension},
                                  {"support", r.supported->a_frame ? "pinned heel on the held deck, luffing wires to the A-frame on "
                                                                     "its deck pin and backstays, own weight, no cargo"
                                                                   : "pinned heel on the held deck, luffing wires, own weight, no cargo"},
                                  {"modes", std::move(modes)}};
  }
  if (!convergence.empty()) {
    json["convergence"] = Json::array();
    for (const study::ConvergencePoint& point : convergence) {
      Json errors = Json::array();
      for (const auto& error : point.bending_error) errors.push_back(optional_number(error));
      json["convergence"].push_back(Json{{"elements", point.elements},
                                         {"dof", point.dof},
                                         {"bending_relative_error", std::move(errors)},
                                         {"solve_s", point.solve_seconds}});
    }
  }
  return json_text(json);
}

std::string frequencies_csv(const study::ModesResult& r) {
  std::string out = "mode,kind,order,frequency_hz,analytic_frequency_hz,relative_error\n";
  for (std::size_t j = 0; j < r.modes.size(); ++j) {
    const modal::ClassifiedMode& mode = r.modes[j];
    const auto error = relative_error(mode);
    out += fmt::format("{},{},{},{:.17g},{},{}\n", j + 1, fem::to_string(mode.kind), mode.order,
                       hertz(mode.angular_frequency),
                       mode.analytic_frequency ? fmt::format("{:.17g}", hertz(*mode.analytic_frequency)) : "",
                       error ? fmt::format("{:.6e}", *error) : "");
  }
  return out;
}

std::string mode_shapes_csv(const study::ModesResult& r) {
  std::string out = "x_m";
  const auto count = r.pairs.eigenvectors.cols();
  std::vector<Eigen::VectorXd> full;
  for (Eigen::Index j = 0; j < count; ++j) {
    out += fmt::format(",mode{0}_u_per_sqrtkg,mode{0}_v_per_sqrtkg,mode{0}_phi_rad_per_sqrtkg", j + 1);
    full.push_back(fem::extend_to_full(r.pairs.eigenvectors.col(j), r.dofs));
  }
  out += '\n';
  for (int node = 0; node < r.mesh.node_count(); ++node) {
    out += fmt::format("{:.10g}", r.mesh.node_position(node));
    for (const Eigen::VectorXd& shape : full) {
      out += fmt::format(",{:.10e},{:.10e},{:.10e}", shape(3 * node), shape(3 * node + 1), shape(3 * node + 2));
    }
    out += '\n';
  }
  return out;
}

std::string sampled_shapes_csv(const study::ModesResult& r) {
  const auto count = r.pairs.eigenvectors.cols();
  std::string out = "x_m";
  for (Eigen::Index j = 0; j < count; ++j) out += fmt::format(",mode{}_v_per_sqrtkg", j + 1);
  out += '\n';
  const int intervals = std::min(8 * r.mesh.element_count, 1000);
  for (int i = 0; i <= intervals; ++i) {
    const double x = i == intervals ? r.mesh.length : r.mesh.length * i / intervals;
    const Eigen::RowVectorXd v = fem::point_shape(r.mesh, r.dofs, x).displacement.row(1) * r.pairs.eigenvectors;
    out += fmt::format("{:.10g}", x);
    for (Eigen::Index j = 0; j < count; ++j) out += fmt::format(",{:.10e}", v(j));
    out += '\n';
  }
  return out;
}

std::string convergence_csv(const std::vector<study::ConvergencePoint>& convergence) {
  std::string out = "elements,dof,f1_relative_error,f2_relative_error,f3_relative_error,f4_relative_error,solve_s\n";
  for (const study::ConvergencePoint& point : convergence) {
    out += fmt::format("{},{}", point.elements, point.dof);
    // Empty cell where a mode is missing; a zero error cannot be drawn on log axes either.
    for (const auto& error : point.bending_error) out += error && *error > 0.0 ? fmt::format(",{:.6e}", *error) : ",";
    out += fmt::format(",{:.6g}\n", point.solve_seconds);
  }
  return out;
}

std::string mode_shapes_script(const study::ModesResult& r, const std::string& terminal) {
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

std::string convergence_script(const study::ModesResult& r, const std::string& terminal) {
  std::string script = header(terminal, "frequency_convergence",
                              fmt::format("Bending frequency error vs elements, {}, {} solver",
                                          fem::to_string(r.boundary), modal::to_string(r.solver)));
  script +=
      "set logscale xy\n"
      "set format y '10^{%L}'\n"
      "set xlabel 'elements N'\n"
      "set ylabel '|f_{FE} - f_{analytic}| / f_{analytic}'\n"
      "set xtics (2, 4, 8, 16, 32, 64, 128)\nset xrange [1.6:160]\n"
      "plot for [k=1:4] 'frequency_convergence.csv' skip 1 using 1:(column(k+2) > 0 ? column(k+2) : NaN) \\\n"
      "       with linespoints pt 7 title sprintf('f%d', k), \\\n"
      "     'frequency_convergence.csv' skip 1 using 1:(column(3) > 0 ? 1e-3 * (4.0 / $1)**4 : NaN) \\\n"
      "       with lines dt 2 lc 'gray' title 'slope -4'\n";
  return script;
}

}  // namespace ffrf::report
