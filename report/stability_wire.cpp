// Section 4 of the stability report: the slack wire and its snap loads (study/stability.hpp,
// experiment 4): slack intervals and snap peaks per model against the hand result k(s + A), the
// tension chart with the slack intervals shaded, and the finding.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "report/run_report.hpp"
#include "report/stability_section.hpp"

namespace ffrf::report {
namespace {

const char* run_colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e"};

// Each run's tension in its colour; its slack intervals as a bar of the same colour along the bottom
// of the chart (one row per run), so that the intervals of two runs do not hide each other or the curves.
std::string tension_script(const std::vector<study::WireRun>& runs, const std::string& title) {
  std::string gp = fmt::format(
      "set terminal {} size 1000,560 font ',11'\nset output 'wire_tension.png'\nset datafile separator ','\n"
      "set title {} noenhanced\nset xlabel 'time [s]'\nset ylabel 'wire tension [MN]'\n"
      "set key below horizontal Left reverse\nset grid\nset offsets 0, 0, 0, graph 0.12  # room for the slack bars\n",
      png_terminal(), gnuplot_quoted(title));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const char* colour = run_colours[i % 4];
    for (const multibody::SlackInterval& slack : runs[i].slack) {
      const double end = std::isfinite(slack.end) ? slack.end : runs[i].run->result.time.back();
      gp += fmt::format("set object rect from {}, graph {:.3f} to {}, graph {:.3f} fc rgb '{}' fs solid 0.8 noborder front\n",
                        slack.start, 0.01 + 0.045 * static_cast<double>(i), end, 0.045 + 0.045 * static_cast<double>(i),
                        colour);
    }
  }
  gp += "plot ";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    gp += fmt::format("{}'wire_tension.csv' using 1:(column({})/1e6) with lines lw 2 lc rgb '{}' title {}", i == 0 ? "" : ", ",
                      i + 2, run_colours[i % 4], gnuplot_quoted(runs[i].choice.label() + " (bar below: wire slack)"));
  }
  return gp + "\n";
}

std::string tension_csv(const std::vector<study::WireRun>& runs) {
  std::string csv = "time_s";
  std::size_t longest = 0;
  const std::vector<double>* time = nullptr;
  for (const study::WireRun& run : runs) {
    csv += fmt::format(",{}_wire_tension_N", slug(run.choice.label()));
    if (run.run && run.run->result.time.size() > longest) longest = run.run->result.time.size(), time = &run.run->result.time;
  }
  csv += '\n';
  for (std::size_t i = 0; i < longest; ++i) {
    csv += fmt::format("{:.8g}", (*time)[i]);
    for (const study::WireRun& run : runs) {
      const bool has = run.run && i < run.run->result.samples.size();
      csv += has ? fmt::format(",{:.8g}", run.run->result.samples[i].wire_tension) : ",";
    }
    csv += '\n';
  }
  return csv;
}

}  // namespace

StabilitySection wire_section(const scene::Scene& scene, const study::WireStudy& study, const StagedDirectory& out) {
  const std::vector<study::WireRun>& runs = study.runs;
  const multibody::RunSettings& settings = study.settings;
  const double lift = study.lift, m = study.mass, k = study.stiffness, g = study.gravity;
  const double s = study.static_stretch, omega = study.omega, amplitude = study.amplitude, hand_peak = study.hand_peak;
  StabilitySection section;
  section.key = "wire";
  section.title = "Slack wire and snap loads";
  section.provenance = fmt::format(
      "Cargo raised {} m above its hanging equilibrium{} and released at rest; models {} and {}; cvode, rtol {:g}, "
      "{} s, output every {} s (the sampled peak). Wire: k = {} N/m, damping {} % of critical. Data: `wire_tension.csv`.",
      lift, study.lift_from_scene ? "" : " (simulation.cargo_lift is 0 in this scene: 1 m is used here so the snap is shown)",
      runs[0].choice.label(), runs[1].choice.label(), settings.relative_tolerance, settings.duration, settings.output_interval,
      shown(k), 100.0 * scene.wire->damping_ratio);
  std::vector<std::vector<std::string>> rows;
  for (const study::WireRun& wire : runs) {
    const std::string label = wire.choice.label();
    if (wire.failure) {
      StabilityCell cell = failure_cell(label, "run", *wire.failure, "");
      rows.push_back({label, cell_markdown(cell), "-", "-", "-"});
      section.cells.push_back(std::move(cell));
      continue;
    }
    const double static_tension = wire.run->statics.outputs.wire_tension;
    constexpr std::size_t listed = 3;  // in the table; summary.json has every one
    std::string intervals;
    for (const multibody::SlackInterval& slack : wire.slack) {
      if (&slack - wire.slack.data() == listed) intervals += fmt::format(", … ({} in all)", wire.slack.size());
      if (&slack - wire.slack.data() < static_cast<std::ptrdiff_t>(listed)) intervals += fmt::format("{}{}–{} s", intervals.empty() ? "" : ", ", shown(slack.start),
                               std::isfinite(slack.end) ? shown(slack.end) : "end");
      StabilityCell cell{label, "slack", false, std::string(solve::to_string(solve::FailureKind::wire_slack)),
                         slack.start, std::isfinite(slack.end) ? slack.end - slack.start : NAN, "s",
                         "the wire went slack (duration in value)", {}};
      section.cells.push_back(std::move(cell));
    }
    std::string peaks;
    for (const multibody::SnapLoad& snap : wire.snaps) {
      if (&snap - wire.snaps.data() == listed) peaks += fmt::format(", … ({} in all)", wire.snaps.size());
      if (&snap - wire.snaps.data() < static_cast<std::ptrdiff_t>(listed)) peaks += fmt::format("{}{} MN at {} s (× {})", peaks.empty() ? "" : ", ", shown(snap.peak_tension / 1e6),
                           shown(snap.peak_time), shown(snap.ratio, 3));
      StabilityCell cell{label, "snap", false, std::string(solve::to_string(solve::FailureKind::snap_load)),
                         snap.time, snap.peak_tension, "N",
                         fmt::format("peak {} N at {} s, {} × the static tension", shown(snap.peak_tension, 6),
                                     shown(snap.peak_time), shown(snap.ratio, 3)),
                         {{"peak_time_s", snap.peak_time}, {"ratio_to_static", snap.ratio},
                          {"hand_peak_N", hand_peak}, {"static_tension_N", static_tension}}};
      section.cells.push_back(std::move(cell));
    }
    if (wire.slack.empty()) {
      section.cells.push_back({label, "slack", true, "ok", NAN, NAN, "", "the wire stayed taut", {}});
    }
    rows.push_back({label, shown(static_tension / 1e6), intervals.empty() ? "✅ taut throughout" : "❌ " + intervals,
                    peaks.empty() ? "✅ none" : "❌ " + peaks,
                    wire.snaps.empty() ? "-" : shown(wire.snaps.front().peak_tension / hand_peak, 4)});
  }
  section.table = markdown_table({"model", "static tension [MN]", "slack intervals", "snap loads (peak, time, ratio)",
                                  "first peak / hand k(s + A)"}, rows);
  out.write("wire_tension.csv", tension_csv(runs));
  bool any = false;
  for (const study::WireRun& wire : runs) any = any || (wire.run && !wire.run->result.time.empty());
  if (any) {
    draw_chart(out, "wire_tension", tension_script(runs, fmt::format("{}: wire tension, cargo dropped from {} m", scene.name, lift)));
    section.charts = {"wire_tension.png"};
  } else {
    leave_out_chart(out, "wire_tension", "no drop run produced a tension history (every run failed before its first output)");
  }
  section.numbers = {{"lift_m", lift}, {"static_stretch_m", s}, {"hand_amplitude_m", amplitude},
                     {"hand_peak_tension_N", hand_peak}, {"hand_peak_ratio", hand_peak / (m * g)}};
  const double rigid_peak = runs[0].snaps.empty() ? NAN : runs[0].snaps.front().peak_tension;
  const double elastic_peak = runs[1].snaps.empty() ? NAN : runs[1].snaps.front().peak_tension;
  section.finding = fmt::format(
      "A wire carries tension only. Lifted {} m (the static stretch is s = mg/k = {} m) the cargo falls freely for "
      "√(2(d − s)/g) = {} s and meets the wire at √(2g(d − s)) = {} m/s; the wire stops it over a quarter of its "
      "period 2π/ω = {} s. The hand peak k(s + A) = {} MN is {} × the static tension; the rigid boom's first sampled "
      "peak is {} MN (ratio to hand {}), the elastic boom's {} MN — the boom's flexibility in series with the wire "
      "{} the peak. ffrf locates every slack/taut event (CVODE root finding) and reports each snap "
      "(run_monitor: snap_loads). Remedy: avoid slack (keep the cargo below its free-fall lift, hoist with tension), "
      "or size the wire for the snap.",
      lift, shown(s), shown(std::sqrt(2.0 * std::max(0.0, lift - s) / g)), shown(std::sqrt(2.0 * g * std::max(0.0, lift - s))),
      shown(2.0 * std::numbers::pi / omega), shown(hand_peak / 1e6), shown(hand_peak / (m * g), 3), shown(rigid_peak / 1e6),
      shown(rigid_peak / hand_peak, 4), shown(elastic_peak / 1e6), elastic_peak < rigid_peak ? "softens" : "does not soften");
  return section;
}

}  // namespace ffrf::report
