// Text, JSON, CSV and gnuplot renderings of the spinning / prestressed modes and the Campbell diagram.
#include "report/campbell_report.hpp"

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>

#include "report/json.hpp"
#include "fem/analytic_rotating_beam.hpp"
#include "report/quantities.hpp"

namespace ffrf::report {
namespace {

double rate(double omega2) { return std::sqrt(std::abs(omega2)); }  // ω or the growth rate

std::string rate_cell(double omega2) {
  return omega2 >= 0.0 ? fmt::format("{:.8g}", rate(omega2)) : fmt::format("unstable, growth rate {:.4g} 1/s", rate(omega2));
}
std::string rate_cell(const std::optional<double>& omega2) { return omega2 ? rate_cell(*omega2) : "-"; }

std::string short_cell(double omega2) {
  return omega2 >= 0.0 ? fmt::format("{:.6g}", rate(omega2)) : fmt::format("unstable g={:.3g}/s", rate(omega2));
}
std::string short_cell(const std::optional<double>& omega2) { return omega2 ? short_cell(*omega2) : "-"; }

// Relative error of ω (both stable) or of the growth rate (both unstable); none when the
// stabilities differ or no reference exists.
std::optional<double> relative_error(double omega2, const std::optional<double>& reference) {
  if (!reference || (omega2 >= 0.0) != (*reference >= 0.0) || *reference == 0.0) return std::nullopt;
  return std::abs(rate(omega2) - rate(*reference)) / rate(*reference);
}
std::string error_cell(double omega2, const std::optional<double>& reference) {
  if (!reference) return "-";
  const auto error = relative_error(omega2, reference);
  return error ? fmt::format("{:.2e}", *error) : "stability differs";
}

std::string beam_lines(const fem::BeamMesh& mesh, fem::Boundary boundary, int dof, const ModesContext& context) {
  std::string out;
  out += fmt::format("scene      {}{}\n", context.scene_file, context.scene_name.empty() ? "" : " (" + context.scene_name + ")");
  out += fmt::format("beam       L = {:g} m, EI = {:.6g} N m^2, EA = {:.6g} N, rhoA = {:.6g} kg/m\n", mesh.length,
                     mesh.section.bending_rigidity(), mesh.section.axial_rigidity(), mesh.section.mass_per_length);
  out += fmt::format("mesh       N = {} elements, {} free DOFs, {}\n", mesh.element_count, dof, fem::to_string(boundary));
  return out;
}

std::string load_lines(const fem::BeamMesh& mesh, fem::Boundary boundary, double spin, double hub_radius, double axial_force,
                       const std::optional<double>& critical) {
  std::string out;
  const double scale = fem::rotating_beam_frequency_scale(mesh);
  out += fmt::format("spin       Omega = {:g} rad/s ({:.6g} Hz), hub radius r = {:g} m, Omega sqrt(rhoA L^4/EI) = {:.6g}\n",
                     spin, hertz(spin), hub_radius, spin / scale);
  if (axial_force != 0.0 || critical) {
    out += fmt::format("axial      P = {:g} N ({}), buckling load P_cr = {:.6g} N, load ratio P/P_cr = {} (negative: compression){}\n", axial_force,
                       axial_force < 0.0 ? "compression" : axial_force > 0.0 ? "tension" : "none",
                       critical.value_or(0.0), critical ? fmt::format("{:.6g}", axial_force / *critical) : "-",
                       critical && axial_force <= -*critical ? "  BUCKLED" : "");
  }
  const bool buckled = critical && axial_force <= -*critical;
  out += boundary != fem::Boundary::clamped_free ? "reference  none (the power series covers clamped-free only)\n"
         : buckled ? "reference  none: the beam is buckled (the power series needs P > -P_cr)\n"
                   : "reference  power series of the rotating clamped-free Euler-Bernoulli beam (Frobenius, long double)\n";
  out += "model      in-plane, rotating frame: K + Omega^2 K_c + P K_g - Omega^2 M; Coriolis coupling neglected\n";
  return out;
}

Json optional_number(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }

void rate_json(Json& json, const std::string& prefix, const std::optional<double>& omega2) {
  json[prefix + "_omega2_rad2_per_s2"] = optional_number(omega2);
  json[prefix + "_rad_per_s"] = optional_number(omega2 && *omega2 >= 0.0 ? std::optional<double>(rate(*omega2)) : std::nullopt);
  json[prefix + "_growth_per_s"] = optional_number(omega2 ? std::optional<double>(*omega2 < 0.0 ? rate(*omega2) : 0.0) : std::nullopt);
}

std::string csv_rate(const std::optional<double>& omega2) {
  return omega2 && *omega2 >= 0.0 ? fmt::format("{:.12g}", rate(*omega2)) : "";
}
std::string csv_growth(const std::optional<double>& omega2) {
  return omega2 ? fmt::format("{:.12g}", *omega2 < 0.0 ? rate(*omega2) : 0.0) : "";
}

}  // namespace

std::string spin_modes_table(const study::SpinModesResult& r, const ModesContext& context) {
  std::string out = beam_lines(r.mesh, r.boundary, r.dof, context);
  out += load_lines(r.mesh, r.boundary, r.spin_rate, r.hub_radius, r.axial_force, r.buckling_load);
  out += fmt::format("solver     {}, shift sigma = {:.6g} rad^2/s^2 (below the spectrum), {} modes, {:.3g} s\n\n",
                     modal::to_string(r.solver), r.shift, r.rows.size(), r.solve_seconds);
  const bool spinning = r.spin_rate > 0.0;
  out += fmt::format("{:>4}  {:<8} {:>5}  {:>32}  {:>32}  {:>14}  {:>32}  {:>17}\n", "mode", "kind", "order",
                     spinning ? "omega w/o stiffening [rad/s]" : "omega unloaded [rad/s]",
                     spinning ? "omega stiffened [rad/s]" : "omega prestressed [rad/s]", "f [Hz]",
                     "omega series [rad/s]", "rel. error");
  for (std::size_t j = 0; j < r.rows.size(); ++j) {
    const study::SpinModeRow& row = r.rows[j];
    out += fmt::format("{:>4}  {:<8} {:>5}  {:>32}  {:>32}  {:>14}  {:>32}  {:>17}\n", j + 1, fem::to_string(row.kind),
                       row.order, rate_cell(row.plain_omega2), rate_cell(row.stiffened_omega2),
                       row.stiffened_omega2 >= 0.0 ? fmt::format("{:.8g}", hertz(rate(row.stiffened_omega2))) : "-",
                       rate_cell(row.reference_omega2), error_cell(row.stiffened_omega2, row.reference_omega2));
  }
  return out;
}

std::string spin_modes_json(const study::SpinModesResult& r, const ModesContext& context) {
  Json json{{"scene", context.scene_file},
            {"scene_name", context.scene_name},
            {"elements", r.mesh.element_count},
            {"dof", r.dof},
            {"boundary", fem::to_string(r.boundary)},
            {"solver", modal::to_string(r.solver)},
            {"spin_rad_per_s", r.spin_rate},
            {"hub_radius_m", r.hub_radius},
            {"axial_force_N", r.axial_force},
            {"buckling_load_N", optional_number(r.buckling_load)},
            {"load_ratio", optional_number(r.buckling_load ? std::optional<double>(r.axial_force / *r.buckling_load) : std::nullopt)},
            {"buckled", r.buckling_load && r.axial_force <= -*r.buckling_load},
            {"shift_rad2_per_s2", r.shift},
            {"solve_s", r.solve_seconds},
            {"warnings", r.warnings}};
  json["modes"] = Json::array();
  for (std::size_t j = 0; j < r.rows.size(); ++j) {
    const study::SpinModeRow& row = r.rows[j];
    Json mode{{"mode", j + 1}, {"kind", fem::to_string(row.kind)}, {"order", row.order}, {"stable", row.stiffened_omega2 >= 0.0}};
    rate_json(mode, "stiffened", row.stiffened_omega2);
    rate_json(mode, "unstiffened", row.plain_omega2);
    rate_json(mode, "series", row.reference_omega2);
    mode["relative_error"] = optional_number(relative_error(row.stiffened_omega2, row.reference_omega2));
    mode["axial_energy_share"] = row.axial_energy_share;
    json["modes"].push_back(std::move(mode));
  }
  return json_text(json);
}

std::string spin_modes_csv(const study::SpinModesResult& r) {
  std::string out =
      "mode,kind,order,unstiffened_rad_per_s,unstiffened_growth_per_s,stiffened_rad_per_s,stiffened_growth_per_s,"
      "series_rad_per_s,series_growth_per_s,relative_error\n";
  for (std::size_t j = 0; j < r.rows.size(); ++j) {
    const study::SpinModeRow& row = r.rows[j];
    const auto error = relative_error(row.stiffened_omega2, row.reference_omega2);
    out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", j + 1, fem::to_string(row.kind), row.order,
                       csv_rate(row.plain_omega2), csv_growth(row.plain_omega2), csv_rate(row.stiffened_omega2),
                       csv_growth(row.stiffened_omega2), csv_rate(row.reference_omega2), csv_growth(row.reference_omega2),
                       error ? fmt::format("{:.6e}", *error) : "");
  }
  return out;
}

std::string campbell_table(const study::CampbellResult& r, const ModesContext& context) {
  std::string out = beam_lines(r.mesh, r.boundary, r.dof, context);
  const double first = r.points.empty() ? 0.0 : r.points.front().spin_rate;
  const double last = r.points.empty() ? 0.0 : r.points.back().spin_rate;
  out += fmt::format("campbell   {} spin rates from {:g} to {:g} rad/s, lowest {} bending modes, hub radius r = {:g} m, "
                     "P = {:g} N\n", r.points.size(), first, last, r.bending_count, r.hub_radius, r.axial_force);
  out += r.boundary == fem::Boundary::clamped_free
             ? "reference  power series of the rotating clamped-free Euler-Bernoulli beam, with stiffening\n"
             : "reference  none (the power series covers clamped-free only)\n";
  out += fmt::format("solver     {}, {:.3g} s\n", modal::to_string(r.solver), r.solve_seconds);
  out += "columns    omega [rad/s] per mode: stiffened (K + Omega^2 K_c + P K_g - Omega^2 M), without stiffening "
         "(K - Omega^2 M), power series\n\n";
  out += fmt::format("{:>12}", "spin [rad/s]");
  for (int j = 1; j <= r.bending_count; ++j) {
    out += fmt::format("  {:>19}  {:>19}  {:>19}", fmt::format("mode {} stiffened", j), fmt::format("mode {} w/o stiff.", j),
                       fmt::format("mode {} series", j));
  }
  out += '\n';
  for (const study::CampbellPoint& p : r.points) {
    out += fmt::format("{:>12.6g}", p.spin_rate);
    for (std::size_t j = 0; j < static_cast<std::size_t>(r.bending_count); ++j) {
      out += fmt::format("  {:>19}  {:>19}  {:>19}", short_cell(p.stiffened_omega2[j]), short_cell(p.plain_omega2[j]),
                         short_cell(p.reference_omega2[j]));
    }
    out += '\n';
  }
  return out;
}

std::string campbell_json(const study::CampbellResult& r, const ModesContext& context) {
  Json json{{"scene", context.scene_file},
            {"scene_name", context.scene_name},
            {"elements", r.mesh.element_count},
            {"boundary", fem::to_string(r.boundary)},
            {"solver", modal::to_string(r.solver)},
            {"hub_radius_m", r.hub_radius},
            {"axial_force_N", r.axial_force},
            {"bending_modes", r.bending_count},
            {"solve_s", r.solve_seconds}};
  json["campbell"] = Json::array();
  for (const study::CampbellPoint& p : r.points) {
    Json point{{"spin_rad_per_s", p.spin_rate}, {"modes", Json::array()}};
    for (std::size_t j = 0; j < static_cast<std::size_t>(r.bending_count); ++j) {
      Json mode{{"order", j + 1}};
      rate_json(mode, "stiffened", p.stiffened_omega2[j]);
      rate_json(mode, "unstiffened", p.plain_omega2[j]);
      rate_json(mode, "series", p.reference_omega2[j]);
      point["modes"].push_back(std::move(mode));
    }
    json["campbell"].push_back(std::move(point));
  }
  return json_text(json);
}

std::string campbell_csv(const study::CampbellResult& r) {
  std::string out = "spin_rad_per_s";
  for (int j = 1; j <= r.bending_count; ++j) {
    for (const char* variant : {"stiffened", "unstiffened", "series"}) {
      out += fmt::format(",mode{0}_{1}_rad_per_s,mode{0}_{1}_growth_per_s", j, variant);
    }
  }
  out += '\n';
  for (const study::CampbellPoint& p : r.points) {
    out += fmt::format("{:.12g}", p.spin_rate);
    for (std::size_t j = 0; j < static_cast<std::size_t>(r.bending_count); ++j) {
      for (const std::optional<double>& omega2 :
           {std::optional<double>(p.stiffened_omega2[j]), std::optional<double>(p.plain_omega2[j]), p.reference_omega2[j]}) {
        out += fmt::format(",{},{}", csv_rate(omega2), csv_growth(omega2));
      }
    }
    out += '\n';
  }
  return out;
}

std::string campbell_script(const study::CampbellResult& r, const std::string& terminal) {
  std::string script = fmt::format(
      "# Drawn by `ffrf modes --spin-range --out`; restyle and rerun with `gnuplot campbell.gp` in this directory.\n"
      "set terminal {} size 1000,720 font ',11'\n"
      "set output 'campbell.png'\n"
      "set datafile separator ','\n"
      "set key below horizontal Left reverse maxcols 4\n"
      "set grid\n"
      "set title 'Campbell diagram, {} elements, {}, hub radius {:g} m' noenhanced\n"
      "set xlabel 'spin Omega [rad/s]'\n"
      "set ylabel 'omega [rad/s]  (below 0: minus the growth rate of a divergent mode)'\n"
      "set xzeroaxis lt -1 lw 1.5\n",
      terminal, r.mesh.element_count, fem::to_string(r.boundary), r.hub_radius);
  // campbell.csv: column 1 spin; mode j (1-based) starts at column 2 + 6 (j − 1): stiffened ω,
  // growth; unstiffened ω, growth; series ω, growth. A divergent mode is drawn at −growth rate.
  const auto curve = [](int column, const std::string& style, const std::string& title) {
    return fmt::format("'campbell.csv' skip 1 using 1:(column({1}) > 0 ? -column({1}) : column({0})) {2} title '{3}'",
                       column, column + 1, style, title);
  };
  std::string plot = "plot x with lines dt 2 lw 1.5 lc rgb 'black' title '1x Omega excitation'";
  for (int j = 1; j <= r.bending_count; ++j) {
    const int base = 2 + 6 * (j - 1);
    plot += ", \\\n     " + curve(base, fmt::format("with lines lw 2 lc {}", j), fmt::format("mode {} stiffened", j));
    plot += ", \\\n     " + curve(base + 2, fmt::format("with lines dt 3 lw 2 lc {}", j), fmt::format("mode {} without stiffening", j));
    if (r.boundary == fem::Boundary::clamped_free) {
      plot += ", \\\n     " + curve(base + 4, fmt::format("with points pt 6 ps 1.2 lc {}", j), fmt::format("mode {} power series", j));
    }
  }
  return script + plot + "\n";
}

}  // namespace ffrf::report
