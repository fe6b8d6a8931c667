// Report lines for the charts not drawn (see chart_notes.hpp).
#include "report/chart_notes.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "report/json.hpp"

namespace ffrf::report {
namespace {

using Status = ChartRecord::Status;

std::string script_of(const std::string& png) { return png.substr(0, png.rfind('.')) + ".gp"; }

// gnuplot's message on one line (the report's bullet, the console's line).
std::string one_line(std::string text) {
  for (char& c : text) c = c == '\n' ? ' ' : c;
  return text;
}

}  // namespace

std::string charts_markdown(const StagedDirectory& out) {
  std::string md;
  for (const ChartRecord& chart : out.charts()) {
    if (chart.status == Status::left_out) {
      md += fmt::format("- `{}` left out: {}.\n", chart.png, chart.reason);
    } else if (chart.status == Status::failed) {
      md += fmt::format("- `{}` not drawn: gnuplot failed (`{}` is kept to rerun): {}\n", chart.png, script_of(chart.png),
                        one_line(chart.reason));
    }
  }
  if (md.empty()) return md;
  return "\n## Charts not drawn\n\nThe data of every chart are in this directory; these charts are not:\n\n" + md;
}

std::string with_charts_json(const std::string& summary, const StagedDirectory& out) {
  Json json = Json::parse(summary);
  Json charts{{"drawn", Json::array()}, {"left_out", Json::array()}, {"failed", Json::array()}};
  for (const ChartRecord& chart : out.charts()) {
    if (chart.status == Status::drawn) {
      charts["drawn"].push_back(chart.png);
    } else {
      charts[chart.status == Status::left_out ? "left_out" : "failed"].push_back(Json{{"chart", chart.png}, {"reason", chart.reason}});
    }
  }
  json["charts"] = std::move(charts);
  return json_text(json);
}

std::string chart_notes_text(std::string_view command, const StagedDirectory& out) {
  std::string text;
  for (const ChartRecord& chart : out.charts()) {
    if (chart.status == Status::left_out) {
      text += fmt::format("ffrf {}: note: chart {} left out: {}\n", command, chart.png, chart.reason);
    } else if (chart.status == Status::failed) {
      text += fmt::format("ffrf {}: warning: chart {} not drawn (gnuplot failed; {} is kept): {}\n", command, chart.png,
                          script_of(chart.png), one_line(chart.reason));
    }
  }
  return text;
}

}  // namespace ffrf::report
