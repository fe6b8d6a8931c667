// sweep.csv written and read back (see sweep_csv.hpp).
#include "report/sweep_csv.hpp"

#include "report/verdict_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ffrf::report {
namespace {

// Shortest exact form; empty for "no value" (NaN, infinity, or not applicable).
std::string number(double value) { return std::isfinite(value) ? fmt::format("{}", value) : std::string(); }

std::string quoted(const std::string& text) {
  std::string q = "\"";
  for (char c : text) {
    if (c == '"') q += "\"\"";
    else if (c == '\n' || c == '\r') q += ' ';
    else q += c;
  }
  return q + "\"";
}

std::string unit_slug(std::string_view unit) { return unit == "N m" ? "Nm" : std::string(unit); }

std::optional<double> optional_number(const std::string& field) {
  if (field.empty()) return std::nullopt;
  return std::stod(field);
}

}  // namespace

std::string sweep_csv_header() {
  std::string h = "id,model,family,elements,modes,static_modes,integrator,rtol,step,erk_stable_step";
  for (const auto channel : multibody::all_channels) h += fmt::format(",{}_nrms", multibody::channel_name(channel));
  for (const auto channel : multibody::all_channels) {
    h += fmt::format(",{}_max_{}", multibody::channel_name(channel), unit_slug(display_unit(channel)));
  }
  return h + ",daf_error,worst_nrms,steps,state_size,work,rhs_evaluations,jacobian_evaluations,newton_iterations,status,reason,wall_s,radiation\n";
}

std::string sweep_csv_line(const study::SweepResult& r) {
  const study::SweepConfig& c = r.config;
  const bool modal = c.choice.kind == scene::BoomKind::modal;
  std::string line = fmt::format(
      "{},{},{},{},{},{},{},{},{},{}", c.id, c.choice.label(), study::model_family(c.choice),
      c.choice.kind == scene::BoomKind::rigid ? std::string() : std::to_string(c.choice.elements),
      modal ? std::to_string(c.choice.modes) : std::string(), modal ? (c.choice.static_modes ? "1" : "0") : "",
      solve::to_string(c.integrator), c.rtol > 0.0 ? number(c.rtol) : std::string(), r.step > 0.0 ? number(r.step) : "",
      r.stable_step > 0.0 ? number(r.stable_step) : "");
  const bool ok = r.status == study::RunStatus::ok;
  for (const auto& e : r.errors.channels) line += "," + (ok ? number(e.normalized_rms) : std::string());
  for (std::size_t channel = 0; channel < multibody::all_channels.size(); ++channel) {
    const double unit = display_scale(multibody::all_channels[channel]);
    line += "," + (ok ? number(r.errors.channels[channel].max_abs * unit) : std::string());
  }
  line += "," + (ok ? number(r.errors.daf_error) : std::string());
  line += "," + (ok ? number(r.worst.error) : std::string());
  if (ok) {
    line += fmt::format(",{},{},{},{},{},{}", r.stats.steps, r.state_size,
                        number(study::solver_work(r.stats.function_evaluations, r.state_size)), r.stats.function_evaluations,
                        r.stats.jacobian_evaluations, r.stats.newton_iterations);
  } else {
    line += ",,,,,,";
  }
  line += fmt::format(",{},{},{},{}\n", study::to_string(r.status), r.reason.empty() ? std::string() : quoted(r.reason),
                      ok ? number(r.stats.wall_seconds) : std::string(), study::radiation_name(c));
  return line;
}


std::string SweepRow::settings() const {
  const std::string hull = radiation.empty() ? std::string() : ", " + radiation + " radiation";
  if (integrator == "arkode" && step && !rtol) return fmt::format("arkode h {:.3g} s{}", *step, hull);
  if (step) return fmt::format("{} h {:g} s{}", integrator, *step, hull);
  return fmt::format("{} rtol {:g}{}", integrator, rtol.value_or(0.0), hull);
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::vector<SweepRow> read_sweep_csv(const std::string& text, const std::string& name) {
  const std::string header = sweep_csv_header();
  if (text.compare(0, header.size(), header) != 0) {
    throw std::runtime_error(name + ": not a sweep CSV of this ffrf version (its header differs)");
  }
  const std::vector<std::string> columns = split_csv_line(header.substr(0, header.size() - 1));
  auto column = [&](std::string_view column_name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), column_name) - columns.begin());
  };
  std::vector<SweepRow> rows;
  std::size_t start = header.size();
  for (int line_number = 2; start < text.size(); ++line_number) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) throw std::runtime_error(fmt::format("{}:{}: unterminated last line", name, line_number));
    SweepRow row;
    row.line = text.substr(start, end - start + 1);
    start = end + 1;
    const std::vector<std::string> f = split_csv_line(row.line.substr(0, row.line.size() - 1));
    if (f.size() != columns.size()) {
      throw std::runtime_error(fmt::format("{}:{}: {} fields, expected {}", name, line_number, f.size(), columns.size()));
    }
    try {
      row.id = std::stoi(f[column("id")]);
      row.model = f[column("model")];
      row.family = f[column("family")];
      row.elements = f[column("elements")].empty() ? 0 : std::stoi(f[column("elements")]);
      row.modes = f[column("modes")].empty() ? 0 : std::stoi(f[column("modes")]);
      row.static_modes = f[column("static_modes")] == "1";
      row.integrator = f[column("integrator")];
      row.rtol = optional_number(f[column("rtol")]);
      row.step = optional_number(f[column("step")]);
      row.cargo_heave = optional_number(f[column("cargo_heave_nrms")]);
      row.daf_error = optional_number(f[column("daf_error")]);
      row.worst = optional_number(f[column("worst_nrms")]);
      row.steps = f[column("steps")].empty() ? 0 : std::stol(f[column("steps")]);
      row.state_size = f[column("state_size")].empty() ? 0 : std::stoi(f[column("state_size")]);
      row.rhs_evaluations = f[column("rhs_evaluations")].empty() ? 0 : std::stol(f[column("rhs_evaluations")]);
      row.status = f[column("status")];
      row.reason = f[column("reason")];
      row.wall = optional_number(f[column("wall_s")]);
      row.radiation = f[column("radiation")];
    } catch (const std::logic_error&) {
      throw std::runtime_error(fmt::format("{}:{}: a malformed number", name, line_number));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string sweep_csv(std::vector<SweepRow>& rows) {
  std::sort(rows.begin(), rows.end(), [](const SweepRow& a, const SweepRow& b) { return a.id < b.id; });
  std::string csv = sweep_csv_header();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0 && rows[i].id == rows[i - 1].id) {
      throw std::runtime_error(fmt::format("configuration {} appears twice (overlapping shards?)", rows[i].id));
    }
    csv += rows[i].line;
  }
  return csv;
}

}  // namespace ffrf::report
