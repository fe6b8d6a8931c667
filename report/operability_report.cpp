// operability.csv, report.md, summary.json and the operability chart (see operability_report.hpp).
#include "report/operability_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "report/chart_notes.hpp"
#include "report/gnuplot.hpp"
#include "report/json.hpp"
#include "report/operability_chart.hpp"
#include "report/quantities.hpp"

namespace ffrf::report {
namespace {

using study::CellResult;
using study::Criterion;


std::string verdict_word(bool pass) { return pass ? "pass" : "FAIL"; }

// "pass daf 0.87" / "FAIL slack 1.06" / "not physical" / "failed".
std::string cell_word(const CellResult& c) {
  if (c.status() == study::CellStatus::not_physical) return "not physical";
  if (!c.ok) return "failed";
  return fmt::format("{} {} {:.2f}", verdict_word(c.verdict.pass), study::to_string(c.verdict.governing),
                     c.verdict[c.verdict.governing].utilisation);
}

std::vector<hydro::WaveHeading> headings_of(const study::OperabilityStudy& s) {
  std::vector<hydro::WaveHeading> headings;
  for (const CellResult& c : s.cells) {
    if (std::find(headings.begin(), headings.end(), c.cell.heading) == headings.end()) headings.push_back(c.cell.heading);
  }
  return headings;
}

// The operability table of one heading: Tp down, Hs across.
std::string heading_table(const study::OperabilityStudy& s, hydro::WaveHeading heading, bool markdown) {
  std::set<double> hs, tp;
  std::map<std::pair<double, double>, const CellResult*> at;
  for (const CellResult& c : s.cells) {
    if (c.cell.heading != heading) continue;
    hs.insert(c.cell.significant_height);
    tp.insert(c.cell.peak_period);
    at[{c.cell.peak_period, c.cell.significant_height}] = &c;
  }
  std::string text = markdown ? "| Tp [s] \\ Hs [m] |" : fmt::format("{:>8} |", "Tp\\Hs");
  for (double h : hs) text += markdown ? fmt::format(" {:g} |", h) : fmt::format(" {:>16g} |", h);
  text += "\n";
  if (markdown) {
    text += "|---|";
    for (std::size_t i = 0; i < hs.size(); ++i) text += "---|";
    text += "\n";
  }
  for (double t : tp) {
    text += markdown ? fmt::format("| {:g} |", t) : fmt::format("{:>8g} |", t);
    for (double h : hs) {
      const auto found = at.find({t, h});
      const std::string word = found == at.end() ? "" : cell_word(*found->second);
      text += markdown ? fmt::format(" {} |", word) : fmt::format(" {:>16} |", word);
    }
    text += "\n";
  }
  return text;
}

}  // namespace

std::string operability_csv(const study::OperabilityStudy& s) {
  std::string csv =
      "hs_m,tp_s,heading,status,model,governing,verdict,daf,daf_standard_error,min_tension_ratio,snap_ratio,"
      "cargo_heave_mpm_m,root_moment_mpm_Nm,compression_mpm_N,peak_stress_mpm_MPa,u_daf,u_slack,u_snap,u_cargo_motion,u_root_moment,"
      "u_boom_stress,u_buckling,"
      "seeds,work,verified,converged_model,converged_governing,converged_verdict,converged_u_governing,converged_work,"
      "steepness,steepness_limit,band_lower_radps,band_upper_radps,band_variance_share,components,repeat_period_sec,"
      "record_repeats,independent_wave_cycles,failure,wall_s,converged_wall_s\n";
  for (const CellResult& c : s.cells) {
    const bool physical = c.status() != study::CellStatus::not_physical;
    csv += fmt::format("{:g},{:g},{},{},\"{}\",", c.cell.significant_height, c.cell.peak_period, heading_name(c.cell.heading),
                       study::to_string(c.status()), physical ? c.model.label() : std::string());
    if (c.ok) {
      const study::CellStatistics& st = c.statistics;
      csv += fmt::format("{},{},{:.6g},{:.3g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},", study::to_string(c.verdict.governing),
                         verdict_word(c.verdict.pass), st.daf, st.daf_standard_error, st.minimum_tension / st.static_tension,
                         st.snap_peak / st.static_tension, st.cargo_heave_mpm.mean, st.root_moment_mpm.mean,
                         st.compression_mpm.mean, st.peak_stress_mpm.mean * 1e-6);
      for (Criterion criterion : study::all_criteria) csv += fmt::format("{:.6g},", c.verdict[criterion].utilisation);
      csv += fmt::format("{},{:.6g},", st.seeds, st.work);
    } else {
      csv += ",,,,,,,,,,,,,,,,,,,";
    }
    if (c.verified && c.converged_ok) {
      csv += fmt::format("yes,\"{}\",{},{},{:.6g},{:.6g},", c.converged.label(), study::to_string(c.converged_verdict.governing),
                         verdict_word(c.converged_verdict.pass),
                         c.converged_verdict[c.converged_verdict.governing].utilisation, c.converged_statistics.work);
    } else {
      csv += c.verified ? "failed,,,,,," : "no,,,,,,";
    }
    const study::CellSea& sea = c.sea;
    csv += fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{:.6g},{:.4g},{:.4g},", sea.steepness.steepness,
                       sea.steepness.limit, sea.band.lower, sea.band.upper, sea.variance_share, sea.components,
                       sea.repeat_period, sea.record_repeats, sea.independent_wave_cycles);
    std::string failure = c.ok ? c.converged_failure : c.failure;
    std::replace(failure.begin(), failure.end(), '"', '\'');
    csv += fmt::format("\"{}\",{:.3f},{}\n", failure, c.wall_seconds,
                       c.verified ? fmt::format("{:.3f}", c.converged_wall_seconds) : std::string());
  }
  return csv;
}

ModelSavings model_savings(const study::OperabilityStudy& s) {
  ModelSavings m;
  double work = 0.0, converged_work = 0.0, wall = 0.0, converged_wall = 0.0;
  for (const CellResult& c : s.cells) {
    if (!c.verified || !c.ok || !c.converged_ok) continue;
    ++m.cells;
    const bool same = c.verdict.pass == c.converged_verdict.pass && c.verdict.governing == c.converged_verdict.governing;
    m.agreeing += same ? 1 : 0;
    const double reference = c.converged_verdict[c.converged_verdict.governing].utilisation;
    const double mine = c.verdict[c.converged_verdict.governing].utilisation;
    if (reference > 0.0) m.largest_difference = std::max(m.largest_difference, std::abs(mine - reference) / reference);
    work += c.statistics.work;
    converged_work += c.converged_statistics.work;
    wall += c.wall_seconds;
    converged_wall += c.converged_wall_seconds;
  }
  if (work > 0.0) m.work_ratio = converged_work / work;
  if (wall > 0.0) m.wall_ratio = converged_wall / wall;
  return m;
}

std::string operability_sea_text(const study::OperabilityRequest& request) {
  return fmt::format("irregular, JONSWAP γ = {:g}, long-crested, {}; each cell's band holds {:g} % of its variance m0 (tails "
                     "split equally)",
                     request.peak_enhancement,
                     request.components > 0 ? fmt::format("{} components per record", request.components)
                                            : std::string("components every 2π/duration (never repeats)"),
                     100.0 * request.variance_share);
}

std::string operability_text(const study::OperabilityStudy& s) {
  std::size_t pass = 0, fail = 0, failed = 0, not_physical = 0;
  for (const CellResult& c : s.cells) {
    (c.status() == study::CellStatus::not_physical ? not_physical : c.ok ? (c.verdict.pass ? pass : fail) : failed) += 1;
  }
  std::string text =
      fmt::format("{} cells: {} pass, {} fail, {} not physical (too steep to exist), {} with a failed run ({}; {} records "
                  "computed, {} resumed)\n",
                  s.cells.size(), pass, fail, not_physical, failed, s.farm.engine, s.farm.computed, s.farm.resumed);
  for (hydro::WaveHeading heading : headings_of(s)) text += fmt::format("\n{} sea:\n{}", heading_name(heading), heading_table(s, heading, false));
  const ModelSavings m = model_savings(s);
  if (m.cells > 0) {
    text += fmt::format("\nmodel choice verified on {} cells against the converged model: {} agree on verdict and governing "
                        "criterion, governing utilisation within {:.2g} %; the converged model costs {:.1f}x the work and "
                        "{:.1f}x the wall time\n",
                        m.cells, m.agreeing, 100.0 * m.largest_difference, m.work_ratio, m.wall_ratio);
  }
  return text;
}

std::string operability_markdown(const study::OperabilityStudy& s, const OperabilityContext& ctx) {
  const study::OperabilityCriteria& k = s.criteria;
  std::string md = fmt::format(
      "# Operability of `{}`\n\n`{}`\n\n{} seeds per cell, {:g} s per record, sea: {}. Engine: {}; {} records computed, {} "
      "resumed from the journal, {:.1f} s wall.\n\n",
      ctx.scene_file, ctx.command, ctx.seeds, ctx.duration, ctx.sea, s.farm.engine, s.farm.computed, s.farm.resumed,
      s.farm.wall_seconds);
  if (!s.warnings.empty()) {
    md += "## Warnings\n\n";
    for (const std::string& warning : s.warnings) md += "- " + warning + "\n";
    md += "\n";
  }
  md += fmt::format(
      "## Criteria\n\n| criterion | limit | utilisation |\n|---|---|---|\n"
      "| daf | MPM tension / static ≤ {:g} | DAF / limit |\n"
      "| slack | T_min ≥ {:g} × static | (1 − T_min/T_s) / (1 − margin) |\n"
      "| snap | peak after slack ≤ DAF limit × static | snap peak / ({:g} T_s) |\n"
      "| cargo_motion | MPM heave amplitude ≤ {:g} m | MPM / limit |\n"
      "| root_moment | MPM root moment ≤ {} | MPM / capacity |\n"
      "| boom_stress | MPM peak fibre stress along the boom ≤ {} | MPM / allowable |\n"
      "| buckling | MPM compression ≤ {:g} × Euler load | MPM / ({:g} P_E) |\n\n"
      "A cell passes when every utilisation is ≤ 1; the governing criterion is the largest (docs/operability.md). A cell "
      "whose sea is steeper than DNV-RP-C205's breaking limit (Hs/λp above 1/15 at Tp ≤ 8 s, 1/25 at Tp ≥ 15 s) is not "
      "physical: no records, no verdict.\n\n",
      k.daf_limit, k.slack_margin, k.daf_limit, k.cargo_motion_limit,
      !std::isfinite(k.root_moment_capacity) ? std::string("— (not judged: a pinned heel carries no moment)")
      : k.root_moment_capacity > 0.0        ? fmt::format("{:.4g} N m", k.root_moment_capacity)
                                            : fmt::format("{:g} × static moment", k.daf_limit),
      k.allowable_stress > 0.0 ? fmt::format("{:.4g} MPa (boom.allowable_stress)", k.allowable_stress * 1e-6)
                               : std::string("— (not judged: the scene gives no boom.allowable_stress)"),
      k.buckling_ratio, k.buckling_ratio);
  for (hydro::WaveHeading heading : headings_of(s)) {
    md += fmt::format("## {} sea\n\n{}\n", heading_name(heading), heading_table(s, heading, true));
  }
  md += "![operability map](operability.png)\n\n## Cells\n\n"
        "| Hs [m] | Tp [s] | heading | model | verdict | governing | DAF (± s.e.) | T_min/T_s | cargo MPM [m] | root moment MPM [MN m] | peak stress MPM [MPa] | compression MPM [MN] |\n"
        "|--:|--:|---|---|---|---|--:|--:|--:|--:|--:|--:|\n";
  for (const CellResult& c : s.cells) {
    if (c.status() == study::CellStatus::not_physical) {
      md += fmt::format("| {:g} | {:g} | {} | | not physical: {} | | | | | | | |\n", c.cell.significant_height,
                        c.cell.peak_period, heading_name(c.cell.heading), c.failure);
      continue;
    }
    if (!c.ok) {
      md += fmt::format("| {:g} | {:g} | {} | {} | failed: {} | | | | | | | |\n", c.cell.significant_height, c.cell.peak_period,
                        heading_name(c.cell.heading), c.model.label(), c.failure);
      continue;
    }
    const study::CellStatistics& st = c.statistics;
    md += fmt::format("| {:g} | {:g} | {} | {} | {} | {} ({:.3f}) | {:.4f} ± {:.4f} | {:.3f} | {:.3f} | {:.2f} | {:.4g} | {:.2f} |\n",
                      c.cell.significant_height, c.cell.peak_period, heading_name(c.cell.heading), c.model.label(),
                      verdict_word(c.verdict.pass), study::to_string(c.verdict.governing),
                      c.verdict[c.verdict.governing].utilisation, st.daf, st.daf_standard_error,
                      st.minimum_tension / st.static_tension, st.cargo_heave_mpm.mean, st.root_moment_mpm.mean / 1e6,
                      st.peak_stress_mpm.mean * 1e-6, st.compression_mpm.mean / 1e6);
  }
  md += "\n## The sea of each cell\n\nEach cell's records keep the band of its own JONSWAP spectrum that holds the "
        "stated share of its variance m0 (the rest split equally between the low and high tails; the share computed back "
        "by quadrature). Components on ω_n = n Δω repeat after 2π/Δω: a record longer than that counts the same waves "
        "again, and its statistics rest on the wave cycles of one repeat (repeat / Tz), not on the record length.\n\n"
        "| Hs [m] | Tp [s] | heading | Hs/λp (limit) | band [rad/s] | share of m0 | components | repeats after [s] | "
        "record / repeat | independent wave cycles |\n|--:|--:|---|--:|---|--:|--:|--:|--:|--:|\n";
  for (const CellResult& c : s.cells) {
    const study::CellSea& sea = c.sea;
    md += fmt::format("| {:g} | {:g} | {} | {:.4f} ({:.4f}) | {:.3f} – {:.3f} | {:.4f} | {} | {:.5g} | {:.2f} | {:.0f} |\n",
                      c.cell.significant_height, c.cell.peak_period, heading_name(c.cell.heading), sea.steepness.steepness,
                      sea.steepness.limit, sea.band.lower, sea.band.upper, sea.variance_share, sea.components,
                      sea.repeat_period, sea.record_repeats, sea.independent_wave_cycles);
  }
  const ModelSavings m = model_savings(s);
  md += fmt::format("\n## The boom model per cell\n\n`ffrf recommend` picked each cell's model on a probe record of its sea "
                    "(the first seed, {:g} peak periods or the record if shorter): the cheapest by solver work that passes "
                    "τ = {:g} against the converged reference. Verified on {} cells against the converged model (same seeds):\n\n"
                    "| Hs [m] | Tp [s] | heading | model | governing (u) | converged model | governing (u) |\n|--:|--:|---|---|---|---|---|\n",
                    study::probe_peak_periods, ctx.tolerance, m.cells);
  for (const CellResult& c : s.cells) {
    if (!c.verified || !c.ok || !c.converged_ok) continue;
    md += fmt::format("| {:g} | {:g} | {} | {} | {} {} ({:.4f}) | {} | {} {} ({:.4f}) |\n", c.cell.significant_height,
                      c.cell.peak_period, heading_name(c.cell.heading), c.model.label(), verdict_word(c.verdict.pass),
                      study::to_string(c.verdict.governing), c.verdict[c.verdict.governing].utilisation, c.converged.label(),
                      verdict_word(c.converged_verdict.pass), study::to_string(c.converged_verdict.governing),
                      c.converged_verdict[c.converged_verdict.governing].utilisation);
  }
  if (m.cells > 0) {
    md += fmt::format("\n{} of {} agree on the verdict and the governing criterion; the governing utilisation differs by at most "
                      "{:.2g} %. The converged model would cost **{:.1f}× the solver work** (RHS evaluations × state size) and "
                      "**{:.1f}× the wall time** of the recommended models on these cells.\n",
                      m.agreeing, m.cells, 100.0 * m.largest_difference, m.work_ratio, m.wall_ratio);
  }
  return md;
}

std::string operability_json(const study::OperabilityStudy& s, const OperabilityContext& ctx) {
  Json doc;
  doc["scene"] = ctx.scene_file;
  doc["command"] = ctx.command;
  doc["sea"] = ctx.sea;
  doc["seeds"] = ctx.seeds;
  doc["warnings"] = s.warnings;
  doc["record_s"] = ctx.duration;
  doc["criteria"] = {{"daf_limit", s.criteria.daf_limit},
                     {"slack_margin", s.criteria.slack_margin},
                     {"cargo_motion_limit_m", s.criteria.cargo_motion_limit},
                     {"root_moment_capacity_Nm", s.criteria.root_moment_capacity},
                     {"allowable_stress_MPa", s.criteria.allowable_stress * 1e-6},
                     {"buckling_ratio", s.criteria.buckling_ratio}};
  doc["engine"] = {{"description", s.farm.engine}, {"processes", s.farm.processes}, {"computed", s.farm.computed},
                   {"resumed", s.farm.resumed}, {"failed", s.farm.failed}, {"wall_s", s.farm.wall_seconds}};
  Json cells = Json::array();
  for (const CellResult& c : s.cells) {
    const study::CellSea& sea = c.sea;
    Json cell = {{"hs_m", c.cell.significant_height}, {"tp_s", c.cell.peak_period}, {"heading", heading_name(c.cell.heading)},
                 {"status", std::string(study::to_string(c.status()))}, {"ok", c.ok}};
    cell["sea"] = {{"steepness", sea.steepness.steepness}, {"steepness_limit", sea.steepness.limit},
                   {"band_rad_s", {sea.band.lower, sea.band.upper}}, {"band_variance_share", sea.variance_share},
                   {"components", sea.components}, {"repeat_period_s", sea.repeat_period},
                   {"record_repeats", sea.record_repeats}, {"independent_wave_cycles", sea.independent_wave_cycles}};
    if (c.status() == study::CellStatus::not_physical) {
      cell["not_physical"] = c.failure;
    } else if (c.ok) {
      cell["model"] = c.model.label();
      cell["pass"] = c.verdict.pass;
      cell["governing"] = std::string(study::to_string(c.verdict.governing));
      Json utilisation;
      for (Criterion criterion : study::all_criteria) utilisation[std::string(study::to_string(criterion))] = c.verdict[criterion].utilisation;
      cell["utilisation"] = utilisation;
      cell["daf"] = c.statistics.daf;
      cell["daf_standard_error"] = c.statistics.daf_standard_error;
    } else {
      cell["model"] = c.model.label();
      cell["failure"] = c.failure;
    }
    cells.push_back(cell);
  }
  doc["cells"] = cells;
  const ModelSavings m = model_savings(s);
  doc["model_choice"] = {{"verified_cells", m.cells}, {"agreeing", m.agreeing}, {"largest_difference", m.largest_difference},
                         {"converged_work_ratio", m.work_ratio}, {"converged_wall_ratio", m.wall_ratio}};
  return json_text(doc);
}

std::string write_operability_outputs(const std::string& dir, const study::OperabilityStudy& s, const OperabilityContext& ctx) {
  StagedDirectory out(dir, "report.md");
  out.write("operability.csv", operability_csv(s));
  draw_operability_chart(out, s);
  out.write("summary.json", with_charts_json(operability_json(s, ctx), out));
  out.write("report.md", operability_markdown(s, ctx) + charts_markdown(out));
  out.commit();
  return chart_notes_text("operability", out);
}

}  // namespace ffrf::report
