// The verdict in words and JSON (see verdict_report.hpp).
#include "report/verdict_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>

namespace ffrf::report {

std::string_view display_unit(multibody::OutputChannel channel) {
  return channel == multibody::OutputChannel::cargo_pitch || channel == multibody::OutputChannel::crane_pitch
             ? "deg"
             : multibody::channel_unit(channel);
}

double display_scale(multibody::OutputChannel channel) { return display_unit(channel) == "deg" ? 180.0 / std::numbers::pi : 1.0; }

namespace {

// 2 significant digits below 100 ("5.3", "47"), whole numbers above ("130").
std::string ratio_text(double ratio) { return ratio < 99.5 ? fmt::format("{:.2g}", ratio) : fmt::format("{:.0f}", ratio); }

}  // namespace

std::string speedup_words(double ratio) {
  if (!std::isfinite(ratio) || ratio <= 0.0) return "-";
  return ratio >= 1.0 ? ratio_text(ratio) + "× less" : ratio_text(1.0 / ratio) + "× more";
}

std::string speedup_cell(double ratio) { return std::isfinite(ratio) && ratio > 0.0 ? ratio_text(ratio) + "×" : std::string("-"); }

namespace {

// Three significant digits: a value just beyond τ must not print as τ.
std::string error_text(double error) { return std::isfinite(error) ? fmt::format("{:.3g}", error) : std::string("not finite"); }

std::string worst_of(const study::MeasuredModel& m) {
  return m.worst_output.empty() ? std::string() : fmt::format(" (worst output: {})", m.worst_output);
}

}  // namespace

std::string verdict_headline(const study::Verdict& v, const std::vector<study::MeasuredModel>& models,
                             const std::string& reference, const std::string& what, const std::string& scope) {
  if (v.cheapest) {
    const study::MeasuredModel& m = models[*v.cheapest];
    const study::ModelVerdict& mv = v.models[*v.cheapest];
    return fmt::format("Cheapest by solver work ({}) of the {}{} that pass τ = {:g}: {}, error {}{}; {} solver work than the "
                       "{}; wall time {} (measured; not decisive: it varies with the machine's load). {} of {} {} pass.",
                       study::solver_work_measure, what, scope, v.tolerance, m.label, error_text(m.error), worst_of(m),
                       speedup_words(mv.work_speedup), reference, speedup_words(mv.wall_speedup), v.passed_count(),
                       models.size(), what);
  }
  if (v.most_accurate) {
    const study::MeasuredModel& m = models[*v.most_accurate];
    return fmt::format("No {}{} reproduces the {} within τ = {:g}: the most accurate, {}, is at {}{}.", what, scope,
                       reference, v.tolerance, m.label, error_text(m.error), worst_of(m));
  }
  return fmt::format("No {}{} reproduces the {} within τ = {:g}: none ran to the end.", what, scope, reference, v.tolerance);
}

std::string failed_list(const study::Verdict& v, const std::vector<study::MeasuredModel>& models) {
  if (v.failed.empty()) return "";
  std::string s = "Fail: ";
  for (std::size_t k = 0; k < v.failed.size(); ++k) {
    const study::MeasuredModel& m = models[v.failed[k]];
    s += k == 0 ? "" : ", ";
    s += m.ran ? fmt::format("{} {}{}", m.label, error_text(m.error), m.worst_output.empty() ? "" : " (" + m.worst_output + ")")
               : fmt::format("{} (not run: {})", m.label, m.reason);
  }
  return s + ".";
}

std::string pass_cell(const study::Verdict& v, const std::vector<study::MeasuredModel>& models, std::size_t i) {
  if (!models[i].ran) return "not run";
  return v.models[i].passed ? "pass" : "FAIL";
}

Json verdict_json(const study::Verdict& v, const std::vector<study::MeasuredModel>& models, const std::string& sentence) {
  Json json;
  json["tolerance"] = v.tolerance;
  json["measure"] = "worst normalized RMS error (total: static and dynamic) over the judged outputs";
  json["cost_measure"] = fmt::format("solver work: {} (decisive; wall time reported)", study::solver_work_measure);
  json["passed"] = v.passed_count();
  json["failed"] = Json::array();
  for (const std::size_t i : v.failed) json["failed"].push_back(models[i].label);
  if (v.cheapest) {
    const study::MeasuredModel& m = models[*v.cheapest];
    json["cheapest"] = Json{{"label", m.label},
                            {"error", m.error},
                            {"worst_output", m.worst_output},
                            {"wall_speedup", v.models[*v.cheapest].wall_speedup},
                            {"work_speedup", v.models[*v.cheapest].work_speedup}};
  } else {
    json["cheapest"] = nullptr;
  }
  json["reference_wall_s"] = v.reference_wall_seconds;
  json["reference_work"] = v.reference_work;
  json["sentence"] = sentence;
  return json;
}

}  // namespace ffrf::report
