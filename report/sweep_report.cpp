// The sweep's Pareto front, verdict, report and context (see sweep_report.hpp).
#include "report/sweep_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "report/chart_notes.hpp"
#include "report/json.hpp"
#include "report/reference_report.hpp"
#include "report/sweep_csv.hpp"
#include "report/verdict_report.hpp"
#include "study/error_measure.hpp"

namespace ffrf::report {
namespace {

std::string sci(const std::optional<double>& v) { return v ? fmt::format("{:.2e}", *v) : "-"; }

// The value of "<!-- key: value -->" among the context's first lines (empty when absent).
std::string context_value(const std::string& context, const std::string& key) {
  const std::string tag = "<!-- " + key + ": ";
  for (std::size_t start = 0; context.compare(start, 5, "<!-- ") == 0;) {
    const std::size_t end = context.find('\n', start);
    if (end == std::string::npos) break;
    if (context.compare(start, tag.size(), tag) == 0) {
      const std::size_t close = context.find(" -->", start);
      if (close != std::string::npos && close < end) return context.substr(start + tag.size(), close - start - tag.size());
    }
    start = end + 1;
  }
  return "";
}

double context_number(const std::string& context, const std::string& key, double otherwise) {
  const std::string value = context_value(context, key);
  try {
    return value.empty() ? otherwise : std::stod(value);
  } catch (const std::logic_error&) {
    return otherwise;
  }
}

}  // namespace

std::vector<const SweepRow*> best_per_model(const std::vector<SweepRow>& rows) {
  std::vector<const SweepRow*> best;
  std::map<std::string, std::size_t> index;
  for (const SweepRow& row : rows) {
    if (!row.ok()) continue;
    const auto [it, added] = index.emplace(row.model, best.size());
    if (added) best.push_back(&row);
    else if (*row.worst < *best[it->second]->worst) best[it->second] = &row;
  }
  return best;
}

std::vector<std::size_t> pareto_front(const std::vector<SweepRow>& rows) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].ok() && *rows[i].worst > 0.0) order.push_back(i);
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return *rows[a].wall != *rows[b].wall ? *rows[a].wall < *rows[b].wall : *rows[a].worst < *rows[b].worst;
  });
  std::vector<std::size_t> front;
  for (std::size_t i : order) {
    if (front.empty() || *rows[i].worst < *rows[front.back()].worst) front.push_back(i);
  }
  return front;
}

bool at_choice_rtol(const SweepRow& row, double tolerance) {
  // An adaptive run (no fixed step) at exactly the model-choice rtol: the decade the CSV writes back.
  return row.rtol && !(row.step && *row.step > 0.0) && *row.rtol > 0.0 &&
         std::abs(std::log10(*row.rtol) - std::log10(study::model_choice_rtol(tolerance))) < 1e-6;
}

std::vector<study::MeasuredModel> measured_rows(const std::vector<SweepRow>& rows, double tolerance) {
  std::vector<study::MeasuredModel> measured;
  for (const SweepRow& row : rows) {
    study::MeasuredModel m;
    m.label = row.model + ", " + row.settings();
    m.ran = row.ok();
    m.reason = row.status;
    if (row.ok()) {
      m.error = *row.worst;
      m.wall_seconds = *row.wall;
      m.work = row.work();
    }
    m.at_choice_rtol = at_choice_rtol(row, tolerance);
    measured.push_back(std::move(m));
  }
  return measured;
}

namespace {
// A sweep crossed with the radiation models (a [bem] scene): the radiation model of
// the cheapest passing configuration, and per model its cheapest passing configuration.
std::string radiation_verdict(const std::vector<SweepRow>& rows, const study::Verdict& verdict) {
  std::vector<std::string> kinds;
  for (const SweepRow& row : rows) {
    if (!row.radiation.empty() && std::find(kinds.begin(), kinds.end(), row.radiation) == kinds.end()) kinds.push_back(row.radiation);
  }
  if (kinds.empty()) return {};
  if (!verdict.cheapest) return " No radiation model passes.";
  std::string per_model;
  for (const std::string& kind : kinds) {
    const SweepRow* cheapest = nullptr;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (rows[i].radiation == kind && verdict.models[i].passed && (cheapest == nullptr || rows[i].work() < cheapest->work())) {
        cheapest = &rows[i];
      }
    }
    per_model += fmt::format("{}{}: {}", per_model.empty() ? "" : "; ", kind,
                             cheapest != nullptr ? fmt::format("{}, {} (work {:.3g})", cheapest->model, cheapest->settings(),
                                                               cheapest->work())
                                                 : std::string("none passes"));
  }
  return fmt::format(" Cheapest radiation model that passes: {} (cheapest passing per radiation model — {}).",
                     rows[*verdict.cheapest].radiation, per_model);
}
}  // namespace

study::Verdict sweep_verdict(const std::vector<SweepRow>& rows, const SweepFacts& facts) {
  return study::judge(measured_rows(rows, facts.tolerance), facts.reference_wall_seconds, facts.reference_work, facts.tolerance);
}

std::string sweep_verdict_sentence(const std::vector<SweepRow>& rows, const SweepFacts& facts) {
  const study::Verdict verdict = sweep_verdict(rows, facts);
  const std::vector<study::MeasuredModel> measured = measured_rows(rows, facts.tolerance);
  std::string s = verdict_headline(verdict, measured, facts.reference, "configurations",
                                   fmt::format(" at rtol {:g} (the model-choice rtol of τ)", study::model_choice_rtol(facts.tolerance)));
  // The models none of whose settings passes, with their best error.
  std::set<std::string> passing;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (verdict.models[i].passed) passing.insert(rows[i].model);
  }
  std::string never;
  for (const SweepRow* best : best_per_model(rows)) {
    if (passing.count(best->model) == 0) never += fmt::format("{}{} ({:.3g})", never.empty() ? "" : ", ", best->model, *best->worst);
  }
  if (!never.empty()) s += " Fail at every setting (best error): " + never + ".";
  s += radiation_verdict(rows, verdict);
  std::size_t not_ok = 0;
  for (const SweepRow& row : rows) not_ok += row.ok() ? 0 : 1;
  if (not_ok > 0) s += fmt::format(" {} run{} failed or {} skipped.", not_ok, not_ok == 1 ? "" : "s", not_ok == 1 ? "was" : "were");
  return s;
}

std::string sweep_markdown(const std::vector<SweepRow>& rows, const std::string& preamble) {
  const SweepFacts facts = context_facts(preamble);
  std::size_t ok = 0, failed = 0, skipped = 0;
  for (const SweepRow& row : rows) {
    ok += row.ok() ? 1 : 0;
    failed += row.status == "failed" ? 1 : 0;
    skipped += row.status == "skipped" ? 1 : 0;
  }
  const study::Verdict verdict = sweep_verdict(rows, facts);
  std::string r = preamble;
  r += fmt::format("\n{} configurations: {} ok, {} failed, {} skipped. Every row is in `sweep.csv` (timing columns: "
                   "names ending in `_s`).\n\n",
                   rows.size(), ok, failed, skipped);
  r += "Error measure: the **worst total normalized RMS error over the judged outputs** named above (study/error_measure.hpp: "
       "the same outputs, window and reference physics as compare and recommend; static and dynamic parts together, as "
       "`ffrf compare` splits them) against the reference; cost: the wall time of the integration (static equilibrium and "
       "mode shapes excluded) and the solver work, RHS evaluations × state size (recommend's measure, independent of the machine's "
       "load). Speed-ups are the reference's over the run's.\n\n";
  r += fmt::format("## Verdict (τ = {:g})\n\n**{}**\n\n", facts.tolerance, sweep_verdict_sentence(rows, facts));
  if (std::isfinite(facts.reference_change)) {
    r += fmt::format("Errors below the reference's own last change ({:.2g}) are not resolved.\n\n", facts.reference_change);
  }
  r += "## Pareto-optimal configurations\n\nNo other run is both faster and more accurate (labelled on the chart).\n\n"
       "| id | model | integrator | worst error | cargo heave error | DAF error | wall time [s] | real-time factor | steps | "
       "speed-up (wall) | speed-up (work) | τ |\n|--:|---|---|--:|--:|--:|--:|--:|--:|--:|--:|:-:|\n";
  const std::vector<study::MeasuredModel> measured = measured_rows(rows, facts.tolerance);
  for (std::size_t i : pareto_front(rows)) {
    const SweepRow& row = rows[i];
    r += fmt::format("| {} | {} | {} | {} | {} | {} | {:.3g} | {:.3g} | {} | {} | {} | {} |\n", row.id, row.model, row.settings(),
                     sci(row.worst), sci(row.cargo_heave), sci(row.daf_error), *row.wall, facts.duration / *row.wall, row.steps,
                     speedup_cell(verdict.models[i].wall_speedup), speedup_cell(verdict.models[i].work_speedup),
                     pass_cell(verdict, measured, i));
  }
  r += "\n## Charts\n\n![accuracy vs speed](accuracy_speed.png)\n\n![error vs basis size](mode_count.png)\n\n";
  r += "## Best run of each model\n\n| model | integrator | worst error | cargo heave error | wall time [s] | speed-up (work) |\n"
       "|---|---|--:|--:|--:|--:|\n";
  for (const SweepRow* row : best_per_model(rows)) {
    const std::size_t i = static_cast<std::size_t>(row - rows.data());
    r += fmt::format("| {} | {} | {} | {} | {:.3g} | {} |\n", row->model, row->settings(), sci(row->worst), sci(row->cargo_heave),
                     *row->wall, speedup_cell(verdict.models[i].work_speedup));
  }
  if (failed + skipped > 0) {
    r += "\n## Failed and skipped runs\n\n| id | model | integrator | status | reason |\n|--:|---|---|---|---|\n";
    for (const SweepRow& row : rows) {
      if (row.status == "ok") continue;
      std::string reason = row.reason;
      std::replace(reason.begin(), reason.end(), '|', '/');
      r += fmt::format("| {} | {} | {} | {} | {} |\n", row.id, row.model, row.settings(), row.status, reason);
    }
  }
  return r;
}

std::string sweep_context(const std::string& scene_file, const scene::Scene& scene, study::SweepGrid grid, double duration,
                          const study::SweepStudy& study) {
  const study::ConvergedReference& ref = study.reference;
  return fmt::format(
      "<!-- duration_s: {} -->\n<!-- tolerance: {} -->\n<!-- reference: {} -->\n<!-- reference_wall_s: {} -->\n"
      "<!-- reference_work: {} -->\n<!-- reference_change: {} -->\n"
      "# Accuracy–speed sweep: {}\n\n- scene: `{}`, {:g} s simulated, output every {:g} s\n- {}\n"
      "- geometric stiffening of every run and the reference: {}{}\n- errors against {}, {}, worst over {}\n"
      "- tolerance of the verdict: τ = {:g}\n\n"
      "## Converged reference\n\n{}\n\n{}",
      duration, study.tolerance, reference_label(ref), ref.run.result.stats.wall_seconds, ref.run.work(),
      ref.levels.size() > 1 ? fmt::format("{}", ref.levels.back().change) : std::string("nan"),
      scene.name.empty() ? scene_file : scene.name, scene_file, duration, scene.simulation.output_interval,
      study::grid_description(grid), scene::to_string(study.stiffening),
      study.stiffening_from_physics ? " (what the physics needs, as recommend decides; --stiffening sets it)" : " (--stiffening)",
      reference_label(ref),
      study.window_start > 0.0 ? fmt::format("for t ≥ {:g} s (after the wave ramp)", study.window_start)
                               : std::string("over the whole run"),
      study::output_list(study.judged), study.tolerance, reference_verdict(ref), reference_levels_markdown(ref));
}

SweepFacts context_facts(const std::string& context) {
  SweepFacts facts;
  facts.duration = context_number(context, "duration_s", 0.0);
  facts.tolerance = context_number(context, "tolerance", 0.01);
  facts.reference = context_value(context, "reference");
  if (facts.reference.empty()) facts.reference = "reference";
  facts.reference_wall_seconds = context_number(context, "reference_wall_s", 0.0);
  facts.reference_work = context_number(context, "reference_work", 0.0);
  facts.reference_change = context_number(context, "reference_change", NAN);
  return facts;
}

std::string sweep_json(const std::vector<SweepRow>& rows, const SweepFacts& facts) {
  const study::Verdict verdict = sweep_verdict(rows, facts);
  const std::vector<study::MeasuredModel> measured = measured_rows(rows, facts.tolerance);
  Json json;
  json["command"] = "sweep";
  json["duration_s"] = facts.duration;
  json["reference"] = Json{{"label", facts.reference},
                           {"wall_s", facts.reference_wall_seconds},
                           {"work", facts.reference_work},
                           {"last_change", facts.reference_change}};
  std::size_t ok = 0, failed = 0, skipped = 0;
  for (const SweepRow& row : rows) {
    ok += row.ok() ? 1 : 0;
    failed += row.status == "failed" ? 1 : 0;
    skipped += row.status == "skipped" ? 1 : 0;
  }
  json["configurations"] = Json{{"total", rows.size()}, {"ok", ok}, {"failed", failed}, {"skipped", skipped}};
  json["verdict"] = verdict_json(verdict, measured, sweep_verdict_sentence(rows, facts));
  json["pareto"] = Json::array();
  for (const std::size_t i : pareto_front(rows)) {
    const SweepRow& row = rows[i];
    json["pareto"].push_back(Json{{"id", row.id},
                                  {"model", row.model},
                                  {"integrator", row.settings()},
                                  {"worst_normalized_rms", *row.worst},
                                  {"wall_s", *row.wall},
                                  {"work", row.work()},
                                  {"wall_speedup", verdict.models[i].wall_speedup},
                                  {"work_speedup", verdict.models[i].work_speedup},
                                  {"passed", verdict.models[i].passed}});
  }
  return json_text(json);
}

std::string pareto_text(const std::vector<SweepRow>& rows, const SweepFacts& facts) {
  const study::Verdict verdict = sweep_verdict(rows, facts);
  std::size_t width = 26;  // the model column: as wide as the longest label on the front
  for (std::size_t i : pareto_front(rows)) width = std::max(width, rows[i].model.size());
  std::string t = fmt::format("{:>4}  {:<{}} {:<28} {:>11} {:>10} {:>7} {:>7}\n", "id", "model", width, "integrator",
                              "worst error", "wall [s]", "x wall", "x work");
  for (std::size_t i : pareto_front(rows)) {
    t += fmt::format("{:>4}  {:<{}} {:<28} {:>11.3e} {:>10.3g} {:>7} {:>7}\n", rows[i].id, rows[i].model, width, rows[i].settings(),
                     *rows[i].worst, *rows[i].wall, speedup_cell(verdict.models[i].wall_speedup),
                     speedup_cell(verdict.models[i].work_speedup));
  }
  return t + fmt::format("\nverdict (tolerance {:g}): {}\n", facts.tolerance, sweep_verdict_sentence(rows, facts));
}

std::string write_sweep_outputs(const std::string& dir, std::vector<SweepRow>& rows, const std::string& context) {
  const SweepFacts facts = context_facts(context);
  StagedDirectory out(dir, "report.md");
  out.write("sweep.csv", sweep_csv(rows));
  out.write(sweep_context_file, context);
  draw_sweep_charts(out, rows, facts);
  out.write("summary.json", with_charts_json(sweep_json(rows, facts), out));
  out.write("report.md", sweep_markdown(rows, context) + charts_markdown(out));
  out.commit();
  return chart_notes_text("sweep", out);
}

}  // namespace ffrf::report
