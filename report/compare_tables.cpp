// The tables of compare's report.md (see compare_tables.hpp).
#include "report/compare_tables.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "report/quantities.hpp"
#include "report/reference_report.hpp"
#include "report/run_report.hpp"
#include "report/verdict_report.hpp"

namespace ffrf::report {
namespace {

using multibody::all_channels;
using multibody::channel_name;
using study::Comparison;
using study::ModelRun;



// Every run of the report, the reference last, with its label.
std::vector<std::pair<const ModelRun*, std::string>> all_runs(const Comparison& c) {
  std::vector<std::pair<const ModelRun*, std::string>> rows;
  for (const ModelRun& run : c.runs) rows.emplace_back(&run, run.choice.label());
  rows.emplace_back(&c.reference.run, reference_label(c.reference));
  return rows;
}

std::size_t channel_index(multibody::OutputChannel channel) { return static_cast<std::size_t>(channel); }

}  // namespace

std::string verdict_table(const Comparison& c) {
  const std::vector<study::MeasuredModel> measured = study::measured_models(c);
  std::string t = fmt::format(
      "| model | elastic DOFs | worst error | worst output | its static error | its dynamic error | τ = {:g} | wall [s] | "
      "speed-up (wall) | speed-up (work) |\n|---|--:|--:|---|--:|--:|:-:|--:|--:|--:|\n",
      c.verdict.tolerance);
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    const study::SplitError& s = c.split[m][channel_index(c.worst[m].channel)];
    const bool chosen = c.verdict.cheapest && *c.verdict.cheapest == m;
    t += fmt::format("| {}{}{} | {} | {} | {} | {} | {} | {} | {:.3g} | {} | {} |\n", chosen ? "**" : "", c.runs[m].choice.label(),
                     chosen ? "**" : "", c.runs[m].elastic_dof, sci(c.worst[m].error), channel_name(c.worst[m].channel),
                     sci(s.static_error), sci(s.dynamic_error), pass_cell(c.verdict, measured, m),
                     c.runs[m].result.stats.wall_seconds, speedup_cell(c.verdict.models[m].wall_speedup),
                     speedup_cell(c.verdict.models[m].work_speedup));
  }
  t += fmt::format("| {} | {} | - | - | - | - | - | {:.3g} | 1× | 1× |\n", reference_label(c.reference),
                   c.reference.run.elastic_dof, c.reference.run.result.stats.wall_seconds);
  return t;
}

std::string error_table(const Comparison& c, ErrorKind kind) {
  const bool absolute = kind == ErrorKind::static_offset || kind == ErrorKind::dynamic_max || kind == ErrorKind::total_max;
  std::string t = "| model |", rule = "|---|";
  for (const auto channel : all_channels) {
    t += absolute ? fmt::format(" {} [{}] |", channel_name(channel), display_unit(channel)) : fmt::format(" {} |", channel_name(channel));
    rule += "--:|";
  }
  if (kind == ErrorKind::total) {
    t += " DAF error | worst |\n" + rule + "--:|--:|\n";
  } else {
    t += "\n" + rule + "\n";
  }
  for (std::size_t m = 0; m < c.runs.size(); ++m) {
    t += fmt::format("| {} |", c.runs[m].choice.label());
    for (const auto channel : all_channels) {
      const multibody::ChannelError& total = c.errors[m][channel];
      const study::SplitError& split = c.split[m][channel_index(channel)];
      const double unit = display_scale(channel);
      double value = 0.0;
      switch (kind) {
        case ErrorKind::total: value = total.normalized_rms; break;
        case ErrorKind::static_part: value = split.static_error; break;
        case ErrorKind::dynamic_part: value = split.dynamic_error; break;
        case ErrorKind::static_offset: value = split.static_offset * unit; break;
        case ErrorKind::dynamic_max: value = split.dynamic_max * unit; break;
        case ErrorKind::total_max: value = total.max_abs * unit; break;
      }
      t += fmt::format(" {} |", kind == ErrorKind::static_offset && std::isfinite(value) ? fmt::format("{:+.2e}", value) : sci(value));
    }
    if (kind == ErrorKind::total) t += fmt::format(" {} | {} |", sci(c.errors[m].daf_error), sci(c.worst[m].error));
    t += "\n";
  }
  return t;
}

std::string static_table(const scene::Scene& scene, const Comparison& c) {
  std::string t =
      "| model | elastic DOFs | draft at mid-length [m] | trim [deg] | tip transverse [m] | tip axial [m] | wire stretch [m] | "
      "wire tension [N] | joint moment at B [N m] |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& [run, label] : all_runs(c)) {
    const multibody::CraneOutputs& o = run->static_outputs();
    const double draft = study::draft_at_mid_length(scene, o);  // NaN without a hull (a hub): shown as "-"
    t += fmt::format("| {} | {} | {} | {:+.4f} | {:+.5f} | {:+.5f} | {:.5f} | {} | {} |\n", label, run->elastic_dof,
                     std::isfinite(draft) ? fmt::format("{:.4f}", draft) : std::string("-"), o.hull.z() * degrees, o.tip_deflection.y(), o.tip_deflection.x(),
                     scene.wire ? o.wire_length - scene.wire->unstretched_length : 0.0, format_value(o.wire_tension),
                     format_value(o.joint_reaction.z()));
  }
  return t;
}

std::string wire_table(const Comparison& c) {
  std::string t = "| model | static tension [N] | max tension [N] | dynamic amplification factor | slack events |\n"
                  "|---|--:|--:|--:|--:|\n";
  for (const auto& [run, label] : all_runs(c)) {
    // No wire (a hub) or no tension: no amplification factor, shown as "-".
    t += fmt::format("| {} | {} | {} | {} | {} |\n", label, format_value(run->static_outputs().wire_tension),
                     format_value(run->amplification * run->static_outputs().wire_tension),
                     std::isfinite(run->amplification) ? fmt::format("{:.4f}", run->amplification) : std::string("-"),
                     run->slack_events());
  }
  return t;
}

std::string cost_table(const Comparison& c) {
  std::string t = "| model | wall time [s] | real-time factor | steps | state size | work (RHS evaluations × state size) | function "
                  "evaluations | Jacobian evaluations | Newton iterations | error-test failures | max constraint residual [m] |\n"
                  "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& [run, label] : all_runs(c)) {
    const solve::SolverStats& s = run->result.stats;
    t += fmt::format("| {} | {:.3g} | {:.4g} | {} | {} | {:.4g} | {} | {} | {} | {} | {:.2g} |\n", label, s.wall_seconds,
                     run->real_time_factor, s.steps, run->state_size, run->work(), s.function_evaluations,
                     s.jacobian_evaluations, s.newton_iterations, s.error_test_failures, run->max_constraint_residual);
  }
  return t;
}

std::string stress_recovery_table(const Comparison& c) {
  using multibody::StressRecovery;
  std::string t = fmt::format(
      "| model | stress by | history error, mode displacement | history error, mode acceleration | largest peak [MPa], "
      "displacement | largest peak [MPa], acceleration | its error, displacement | its error, acceleration |\n"
      "|---|---|--:|--:|--:|--:|--:|--:|\n");
  for (std::size_t m = 0; m < c.runs.size() && m < c.stress.size(); ++m) {
    const scene::BoomChoice& choice = c.runs[m].choice;
    const study::StressRecoveryErrors& e = c.stress[m];
    const bool both = choice.kind == scene::BoomKind::modal;
    const auto cell = [&](StressRecovery method, double value, bool scientific) {
      if (!both && method == StressRecovery::mode_displacement && choice.kind == scene::BoomKind::rigid) return std::string("-");
      return scientific ? sci(value) : fmt::format("{:.4g}", value * 1e-6);
    };
    const char* own = choice.kind == scene::BoomKind::rigid ? "quasi-static"
                      : choice.kind == scene::BoomKind::nodal
                          ? "nodal"
                          : (choice.stress_recovery == StressRecovery::mode_acceleration ? "acceleration" : "displacement");
    t += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", choice.label(), own,
                     cell(StressRecovery::mode_displacement, e[StressRecovery::mode_displacement].normalized_rms, true),
                     sci(e[StressRecovery::mode_acceleration].normalized_rms),
                     cell(StressRecovery::mode_displacement, e[StressRecovery::mode_displacement].peak, false),
                     fmt::format("{:.4g}", e[StressRecovery::mode_acceleration].peak * 1e-6),
                     cell(StressRecovery::mode_displacement, e[StressRecovery::mode_displacement].design_peak, true),
                     sci(e[StressRecovery::mode_acceleration].design_peak));
  }
  if (!c.stress.empty()) {
    t += fmt::format("| {} | nodal | - | - | - | {:.4g} | - | - |\n", reference_label(c.reference), c.stress.front().reference_peak * 1e-6);
  }
  return t;
}

}  // namespace ffrf::report
