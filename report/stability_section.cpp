// Cells, sections and their formatting for `ffrf stability` (see stability_section.hpp).
#include "app/stability_section.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include <cstdio>

namespace ffrf::app {

StabilityCell failure_cell(std::string row, std::string column, const coupling::Detection& detection, std::string unit) {
  StabilityCell cell;
  cell.row = std::move(row);
  cell.column = std::move(column);
  cell.ok = false;
  cell.status = std::string(coupling::to_string(detection.kind));
  cell.time = detection.time;
  cell.value = detection.value;
  cell.unit = std::move(unit);
  cell.detail = detection.cause;
  return cell;
}

std::string shown(double value, int digits) {
  return std::isfinite(value) ? fmt::format("{:.{}g}", value, digits) : "-";
}

std::string cell_markdown(const StabilityCell& cell) {
  const std::string number =
      std::isfinite(cell.value) ? fmt::format("{}{}{}", shown(cell.value), cell.unit.empty() ? "" : " ", cell.unit) : "";
  if (cell.ok) return fmt::format("✅ {}", number.empty() ? cell.status : number);
  std::string text = "❌ " + cell.status;
  if (std::isfinite(cell.time)) text += fmt::format(" at t = {} s", shown(cell.time));
  if (!number.empty()) text += fmt::format(" ({})", number);
  return text;
}

std::string markdown_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::string table = "|";
  std::string rule = "|";
  for (const std::string& name : header) {
    table += fmt::format(" {} |", name);
    rule += "---|";
  }
  table += "\n" + rule + "\n";
  for (const auto& row : rows) {
    table += "|";
    for (const std::string& text : row) table += fmt::format(" {} |", text);
    table += "\n";
  }
  return table;
}

std::string gnuplot_quoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

void stability_progress(const StabilityOptions& options, const std::string& line) {
  if (!options.progress) return;
  fmt::print(stderr, "ffrf stability: {}\n", line);
  std::fflush(stderr);
}

void write_section_json(JsonWriter& json, const StabilitySection& section) {
  json.begin_object();
  json.field("title", section.title);
  json.key("charts").begin_array();
  for (const std::string& chart : section.charts) json.value(chart);
  json.end_array();
  json.key("numbers").begin_object();
  for (const auto& [name, value] : section.numbers) json.field(name, value);
  json.end_object();
  json.key("cells").begin_array();
  for (const StabilityCell& cell : section.cells) {
    json.begin_object();
    json.field("row", cell.row);
    json.field("column", cell.column);
    json.field("ok", cell.ok);
    json.field("status", cell.status);
    json.field("time_s", cell.time);
    json.field("value", cell.value);
    json.field("unit", cell.unit);
    json.field("detail", cell.detail);
    for (const auto& [name, value] : cell.extra) json.field(name, value);
    json.end_object();
  }
  json.end_array();
  json.end_object();
}

coupling::IntegratorSettings experiment_settings(const DynamicsOptions& dynamics, const cases::Scene& scene) {
  const SettingsOrError settings = integrator_settings(dynamics, scene);
  if (!settings.settings) throw std::invalid_argument(settings.error);
  coupling::IntegratorSettings quiet = *settings.settings;
  quiet.progress = false;
  return quiet;
}

}  // namespace ffrf::app
