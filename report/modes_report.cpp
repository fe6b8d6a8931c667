// Text, JSON and CSV renderings of a ModesResult.
#include "app/modes_report.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <numbers>

#include "app/json_writer.hpp"
#include "fem/point_shape.hpp"

namespace ffrf::app {
namespace {

double hertz(double angular_frequency) { return angular_frequency / (2.0 * std::numbers::pi); }

std::optional<double> relative_error(const modal::ClassifiedMode& mode) {
  if (!mode.analytic_frequency || *mode.analytic_frequency <= 0.0) return std::nullopt;
  return std::abs(mode.angular_frequency - *mode.analytic_frequency) / *mode.analytic_frequency;
}

}  // namespace

std::string modes_table(const ModesResult& r, const ModesContext& context) {
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
  return out;
}

std::string modes_json(const ModesResult& r, const ModesContext& context,
                       const std::vector<ConvergencePoint>& convergence) {
  JsonWriter json;
  json.begin_object();
  json.field("scene", context.scene_file).field("scene_name", context.scene_name);
  json.field("elements", r.mesh.element_count).field("dof", r.dofs.free_count());
  json.field("boundary", fem::to_string(r.boundary)).field("solver", modal::to_string(r.solver));
  json.field("shift_rad2_per_s2", r.shift).field("mode_count", static_cast<int>(r.modes.size()));
  json.key("section").begin_object();
  json.field("length_m", r.mesh.length).field("youngs_modulus_Pa", r.mesh.section.youngs_modulus);
  json.field("area_m2", r.mesh.section.area).field("second_moment_m4", r.mesh.section.second_moment);
  json.field("mass_per_length_kg_per_m", r.mesh.section.mass_per_length);
  json.end_object();
  json.key("timings_s").begin_object();
  json.field("assembly", r.assembly_seconds).field("solve", r.solve_seconds);
  json.end_object();
  json.key("solver_stats").begin_object();
  json.field("iterations", r.pairs.stats.iterations).field("operator_applications", r.pairs.stats.operator_applications);
  json.field("converged", r.pairs.stats.converged);
  json.end_object();
  json.key("warnings").begin_array();
  for (const std::string& warning : r.warnings) json.value(warning);
  json.end_array();
  json.key("frequencies_hz").begin_array();
  for (const modal::ClassifiedMode& mode : r.modes) json.value(hertz(mode.angular_frequency));
  json.end_array();
  json.key("modes").begin_array();
  for (std::size_t j = 0; j < r.modes.size(); ++j) {
    const modal::ClassifiedMode& mode = r.modes[j];
    json.begin_object();
    json.field("mode", static_cast<int>(j + 1)).field("kind", fem::to_string(mode.kind)).field("order", mode.order);
    json.field("frequency_hz", hertz(mode.angular_frequency));
    json.field("analytic_frequency_hz",
               mode.analytic_frequency ? std::optional<double>(hertz(*mode.analytic_frequency)) : std::nullopt);
    json.field("relative_error", relative_error(mode)).field("axial_energy_share", mode.axial_energy_share);
    json.end_object();
  }
  json.end_array();
  if (!convergence.empty()) {
    json.key("convergence").begin_array();
    for (const ConvergencePoint& point : convergence) {
      json.begin_object().field("elements", point.elements).field("dof", point.dof);
      json.key("bending_relative_error").begin_array();
      for (const auto& error : point.bending_error) json.value(error);
      json.end_array().field("solve_s", point.solve_seconds).end_object();
    }
    json.end_array();
  }
  json.end_object();
  return json.str();
}

std::string frequencies_csv(const ModesResult& r) {
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

std::string mode_shapes_csv(const ModesResult& r) {
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

std::string sampled_shapes_csv(const ModesResult& r) {
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

std::string convergence_csv(const std::vector<ConvergencePoint>& convergence) {
  std::string out = "elements,dof,f1_relative_error,f2_relative_error,f3_relative_error,f4_relative_error,solve_s\n";
  for (const ConvergencePoint& point : convergence) {
    out += fmt::format("{},{}", point.elements, point.dof);
    // Empty cell where a mode is missing; a zero error cannot be drawn on log axes either.
    for (const auto& error : point.bending_error) out += error && *error > 0.0 ? fmt::format(",{:.6e}", *error) : ",";
    out += fmt::format(",{:.6g}\n", point.solve_seconds);
  }
  return out;
}

}  // namespace ffrf::app
