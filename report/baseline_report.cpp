// Text and JSON of a recorded baseline and of a check against one (see baseline_report.hpp).
#include "report/baseline_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "report/json.hpp"
#include "report/run_report.hpp"

namespace ffrf::report {
namespace {

std::string model_line(const study::BaselineModel& m) {
  std::string text = fmt::format("{}, geometric stiffening {}; {} rtol {:g} atol {:g}, largest BDF order {}", m.choice.label(),
                                 scene::to_string(m.choice.stiffening.value_or(scene::Stiffening::none)),
                                 solve::to_string(m.integrator), m.relative_tolerance, m.absolute_tolerance, m.max_order);
  if (m.fixed_step > 0.0) text += fmt::format(", fixed step {:g} s", m.fixed_step);
  return text + fmt::format(", {:g} s, output every {:g} s", m.duration, m.output_interval);
}

std::string cost_line(const solve::SolverStats& s) {
  return fmt::format("{} steps, {} function and {} Jacobian evaluations, {} Newton iterations, {:.3g} s", s.steps,
                     s.function_evaluations, s.jacobian_evaluations, s.newton_iterations, s.wall_seconds);
}

std::string tighter_text(const study::IntegrationError& e) {
  return e.fixed_step > 0.0 ? fmt::format("fixed step {:g} s", e.fixed_step)
                            : fmt::format("rtol {:g}, atol {:g}", e.relative_tolerance, e.absolute_tolerance);
}

// How the default tolerance of the responses came about.
std::string response_tolerance_text(const study::Baseline& b) {
  std::string text = fmt::format("max({:g} x the baseline's rtol {:g}", study::response_tolerance_factor, b.model.relative_tolerance);
  if (b.integration_error && b.integration_error->measured()) {
    text += fmt::format(", {:g} x its run's integration error {:.3g}", study::integration_error_factor, b.integration_error->largest);
  }
  return text + ")";
}

std::string commit_text(const std::string& commit) { return commit == "unknown" ? "commit unknown" : "commit " + commit; }

// The deviation and its tolerance in units of the scale (absolute when the scale is 0).
double tolerance_ratio(const study::Deviation& d) { return d.scale > 0.0 ? d.allowed / d.scale : d.allowed; }

std::string verdict_word(const study::Deviation& d) { return d.passed ? "pass" : "FAIL"; }

// Per channel, the quantities that failed and the largest normalized deviation among them.
std::string moved_text(const study::BaselineCheck& check) {
  std::string text;
  std::vector<std::string> channels;
  for (const study::Deviation& d : check.deviations) {
    if (!d.passed && std::find(channels.begin(), channels.end(), d.channel) == channels.end()) channels.push_back(d.channel);
  }
  for (const std::string& channel : channels) {
    std::string quantities;
    const study::Deviation* largest = nullptr;
    for (const study::Deviation& d : check.deviations) {
      if (d.channel != channel || d.passed) continue;
      quantities += (quantities.empty() ? "" : ", ") + d.quantity;
      if (d.compared && (largest == nullptr || d.normalized() > largest->normalized())) largest = &d;
    }
    text += fmt::format("{:12}{}: {}", text.empty() ? "moved" : "", channel, quantities);
    if (largest != nullptr) {
      text += fmt::format("; largest deviation {:.4g} ({}) against {:.3g}", largest->normalized(), largest->quantity,
                          tolerance_ratio(*largest));
    }
    text += "\n";
  }
  return text;
}

}  // namespace

std::string baseline_record_text(const BaselineFile& file) {
  const BaselineProvenance& p = file.provenance;
  const study::Baseline& b = file.baseline;
  std::string text = fmt::format("scene       {} ({}), {}\n", p.scene_path, p.scene_name, p.scene_hash);
  text += fmt::format("model       {}\n", model_line(b.model));
  text += fmt::format("program     ffrf {}, {}, {}\n", p.ffrf_version, commit_text(p.git_commit), p.date);
  text += fmt::format("run         {}\n", cost_line(b.cost));
  std::string frequencies;
  for (const study::BoomFrequency& f : b.boom_frequencies) {
    frequencies += fmt::format("{}{:.10g} ({} {})", frequencies.empty() ? "" : ", ", f.hz, f.kind, f.order);
  }
  text += fmt::format("boom        clamped-free, N = {}: {} Hz\n", b.boom_elements, frequencies.empty() ? "(none)" : frequencies);
  std::string coupled;
  for (const study::CoupledFrequency& f : b.coupled_modes) {
    coupled += fmt::format("{}{:.8g} ({}, zeta {:.3g} %)", coupled.empty() ? "" : ", ", f.hz, f.dominant, 100.0 * f.damping_ratio);
  }
  text += fmt::format("coupled     natural modes of the linearised crane: {}{}\n", coupled.empty() ? "(none: no hull)" : coupled,
                      coupled.empty() ? "" : " Hz");
  text += fmt::format("statistics  over t >= {:g} s{}\n", b.window_start, b.window_after_ramp ? " (after the wave ramp)" : " (the whole run)");
  if (b.integration_error && !b.integration_error->measured()) {
    text += fmt::format("error       integration error not measured ({}): a check's default tolerance of the responses is "
                        "{:.3g}\n", b.integration_error->problem, study::default_response_tolerance(b));
  } else if (b.integration_error) {
    const study::IntegrationError& e = *b.integration_error;
    text += fmt::format("error       integration error {:.3g} ({} {}) against the same run at {} ({} steps): a check's "
                        "default tolerance of the responses is {:.3g}\n",
                        e.largest, e.channel, e.quantity, tighter_text(e), e.steps, study::default_response_tolerance(b));
  }
  text += fmt::format("history     every {} output sample{} ({:g} s, at least {} points per shortest period), {} samples\n",
                      b.decimation, b.decimation == 1 ? "" : "s", b.decimation * b.model.output_interval,
                      study::history_points_per_period, b.history_time.size());
  text += fmt::format("\n  {:<24} {:>13} {:>13} {:>13} {:>13} {:>13} {:>13}\n", "output", "static", "min", "max", "mean", "RMS", "std");
  for (const study::ChannelBaseline& c : b.channels) {
    text += fmt::format("  {:<24} {:>13} {:>13} {:>13} {:>13} {:>13} {:>13}\n", c.name, format_value(c.static_value),
                        format_value(c.min), format_value(c.max), format_value(c.mean), format_value(c.rms),
                        format_value(c.standard_deviation));
  }
  if (b.wire_amplification) text += fmt::format("  wire tension amplification {:.6g} (max over the run / static)\n", *b.wire_amplification);
  return text;
}

std::string baseline_check_text(const BaselineCheckContext& context, const study::BaselineCheck& check) {
  const BaselineProvenance& p = context.baseline->provenance;
  const study::Baseline& b = context.baseline->baseline;
  std::string text = fmt::format("baseline    {}: recorded {} by ffrf {} ({}) from {}\n", context.baseline_path, p.date,
                                 p.ffrf_version, commit_text(p.git_commit), p.scene_path);
  text += context.scene_hash == p.scene_hash
              ? fmt::format("scene       {}: unchanged since the baseline ({})\n", context.scene_path, p.scene_hash)
              : fmt::format("scene       {}: CHANGED since the baseline ({} -> {})\n", context.scene_path, p.scene_hash,
                            context.scene_hash);
  text += fmt::format("model       {}\n", model_line(check.run.model));
  if (check.model_differences.empty()) {
    text += "            the baseline's model and settings\n";
  } else {
    text += "            DIFFERS from the baseline's (deviations below include the model difference):\n";
    for (const study::SettingDifference& d : check.model_differences) {
      text += fmt::format("              {}: baseline {}, this run {}\n", d.setting, d.baseline, d.run);
    }
  }
  text += fmt::format(
      "tolerances  |difference| <= relative x scale + absolute; boom frequencies: relative {:g} of f; responses: "
      "relative {:.3g} ({}) of the channel's standard deviation in the baseline, absolute {:g} (channel units)\n",
      check.frequency_tolerance, check.response_tolerance,
      check.response_tolerance_given ? "given" : "default: " + response_tolerance_text(b),
      check.absolute_tolerance);
  text += fmt::format("run         {}\n            baseline: {}\n\n", cost_line(check.run.cost), cost_line(b.cost));
  text += fmt::format("{:<20} {:<14} {:>15} {:>15} {:>12} {:>10} {:>10}  {}\n", "channel", "quantity", "baseline", "this run",
                      "|difference|", "deviation", "tolerance", "verdict");
  for (const study::Deviation& d : check.deviations) {
    if (!d.compared) {
      text += fmt::format("{:<20} {:<14} {:>15} {:>15} {:>12} {:>10} {:>10}  FAIL  not compared: {}\n", d.channel, d.quantity,
                          "-", "-", "-", "-", "-", d.problem);
      continue;
    }
    text += fmt::format("{:<20} {:<14} {:>15.9g} {:>15.9g} {:>12.4g} {:>10.3g} {:>10.3g}  {}{}\n", d.channel, d.quantity,
                        d.baseline, d.value, d.difference, d.normalized(), tolerance_ratio(d), verdict_word(d),
                        d.detail.empty() ? "" : "  " + d.detail);
  }
  text += "(deviation = |difference| / scale; tolerance = (relative x scale + absolute) / scale; scale = f for a "
          "frequency, the amplification itself, else the channel's standard deviation in the baseline)\n\n";
  const int failures = check.failures();
  if (failures == 0) {
    text += fmt::format("verdict     PASS: all {} quantities within their tolerances\n", check.deviations.size());
  } else {
    text += fmt::format("verdict     FAIL: {} of {} quantities outside their tolerances\n", failures, check.deviations.size());
    text += moved_text(check);
  }
  return text;
}

std::string baseline_check_json(const BaselineCheckContext& context, const study::BaselineCheck& check) {
  const BaselineProvenance& p = context.baseline->provenance;
  Json doc;
  doc["command"] = "baseline check";
  doc["verdict"] = check.passed() ? "pass" : "fail";
  doc["failures"] = check.failures();
  doc["quantities"] = check.deviations.size();
  doc["baseline"] = Json{{"path", context.baseline_path},
                         {"ffrf_version", p.ffrf_version},
                         {"git_commit", p.git_commit},
                         {"date", p.date},
                         {"scene_path", p.scene_path},
                         {"scene_hash", p.scene_hash}};
  doc["scene"] = Json{{"path", context.scene_path}, {"content_hash", context.scene_hash}, {"changed", context.scene_hash != p.scene_hash}};
  doc["model"] = check.run.model.choice.label();
  Json differences = Json::array();
  for (const study::SettingDifference& d : check.model_differences) {
    differences.push_back(Json{{"setting", d.setting}, {"baseline", d.baseline}, {"run", d.run}});
  }
  doc["model_differences"] = differences;
  doc["tolerances"] = Json{{"frequency_relative", check.frequency_tolerance},
                           {"response_relative_default", study::default_response_tolerance(context.baseline->baseline)},
                           {"response_relative", check.response_tolerance},
                           {"response_absolute", check.absolute_tolerance}};
  Json deviations = Json::array();
  for (const study::Deviation& d : check.deviations) {
    Json row{{"channel", d.channel}, {"quantity", d.quantity}, {"detail", d.detail}, {"passed", d.passed}};
    if (d.compared) {
      row.update(Json{{"baseline", d.baseline},
                      {"value", d.value},
                      {"difference", d.difference},
                      {"scale", d.scale},
                      {"relative_tolerance", d.relative_tolerance},
                      {"absolute_tolerance", d.absolute_tolerance},
                      {"allowed", d.allowed},
                      {"deviation", d.normalized()},
                      {"tolerance", tolerance_ratio(d)}});
    } else {
      row["problem"] = d.problem;
    }
    deviations.push_back(row);
  }
  doc["deviations"] = deviations;
  doc["cost"] = Json{{"steps", check.run.cost.steps},
                     {"function_evaluations", check.run.cost.function_evaluations},
                     {"wall_time_s", check.run.cost.wall_seconds}};
  return json_text(doc);
}

}  // namespace ffrf::report
