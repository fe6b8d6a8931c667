// Cells, sections and their formatting for `ffrf stability` (see stability_section.hpp).
#include "report/stability_section.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace ffrf::report {

StabilityCell failure_cell(std::string row, std::string column, const solve::Detection& detection, std::string unit) {
  StabilityCell cell;
  cell.row = std::move(row);
  cell.column = std::move(column);
  cell.ok = false;
  cell.status = std::string(solve::to_string(detection.kind));
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

Json section_json(const StabilitySection& section) {
  Json json{{"title", section.title}, {"charts", section.charts}, {"numbers", Json::object()}, {"cells", Json::array()}};
  for (const auto& [name, value] : section.numbers) json["numbers"][name] = value;
  for (const StabilityCell& cell : section.cells) {
    Json c{{"row", cell.row},       {"column", cell.column}, {"ok", cell.ok},     {"status", cell.status},
           {"time_s", cell.time},   {"value", cell.value},   {"unit", cell.unit}, {"detail", cell.detail}};
    for (const auto& [name, value] : cell.extra) c[name] = value;
    json["cells"].push_back(std::move(c));
  }
  return json;
}

}  // namespace ffrf::report
