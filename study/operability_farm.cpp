// The operability table on the distributed engine (see operability.hpp): one task per (physical
// cell, seed) and per verified (cell, seed) with the converged model; each task's record is its
// SeedExtremes (operability_criteria.hpp) as text, so the journal holds finished records and a rerun
// resumes. Each task's simulated time is followed (solve/time_reached.hpp), so that the progress
// line's ETA moves inside the first records.
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <stdexcept>

#include "solve/stop_request.hpp"
#include "distributed/atomic_file.hpp"
#include "distributed/errors.hpp"
#include "study/operability.hpp"

namespace ffrf::study {
namespace {

struct RecordTask {
  std::size_t cell = 0;
  int seed = 0;
  bool converged = false;
};

// The root-moment capacity: the scene's (infinite for a pinned heel: resolve_criteria), or the DAF limit
// times the static root moment (none binds a moment that is round-off).
double capacity_for(const OperabilityCriteria& criteria, const CellStatistics& statistics) {
  if (criteria.root_moment_capacity > 0.0) return criteria.root_moment_capacity;
  const double capacity = criteria.daf_limit * std::abs(statistics.static_root_moment);
  return capacity > 1e-6 ? capacity : std::numeric_limits<double>::infinity();
}

// The statistics and verdict of one cell's records, or the first failure.
void judge_records(const std::vector<const distributed::TaskOutcome*>& outcomes, const OperabilityCriteria& criteria,
                   double euler_load, bool& ok, std::string& failure, CellStatistics& statistics, CellVerdict& verdict,
                   double& wall) {
  std::vector<SeedExtremes> seeds;
  ok = true;
  for (const distributed::TaskOutcome* outcome : outcomes) {
    wall += outcome->wall_seconds;
    if (!outcome->ok) {
      if (ok) failure = fmt::format("{}: {}", outcome->key, outcome->error);
      ok = false;
      continue;
    }
    seeds.push_back(decode_seed_extremes(outcome->record));
  }
  if (!ok) return;
  statistics = cell_statistics(seeds);
  OperabilityCriteria resolved = criteria;
  resolved.root_moment_capacity = capacity_for(criteria, statistics);
  verdict = judge_cell(statistics, resolved, euler_load);
}

}  // namespace

OperabilityStudy run_operability(distributed::Session& session, const scene::Scene& scene,
                                 const OperabilityRequest& request, distributed::FarmOptions farm_options) {
  modal::ModeCache modes;
  return run_operability(session, scene, request, plan_operability(scene, request, &modes), std::move(farm_options));
}

OperabilityStudy run_operability(distributed::Session& session, const scene::Scene& scene,
                                 const OperabilityRequest& request, const OperabilityPlan& plan,
                                 distributed::FarmOptions farm_options) {
  validate(request);
  OperabilityStudy study;
  study.criteria = resolve_criteria(scene, request.criteria);
  study.warnings = plan.warnings;
  modal::ModeCache modes;
  const std::vector<SeaCell>& cells = plan.cells;
  const std::vector<CellModel>&recommended = plan.recommended, &converged = plan.converged;
  const std::vector<std::size_t>& verified = plan.verified;

  std::vector<RecordTask> records;
  std::vector<std::string> keys;
  std::vector<double> costs;
  const auto add = [&](std::size_t cell, int seed, bool with_converged) {
    records.push_back({cell, seed, with_converged});
    keys.push_back(fmt::format("{} seed={} model={}", cells[cell].key(), seed, with_converged ? "converged" : "recommended"));
    const CellModel& model = with_converged ? converged[cell] : recommended[cell];
    costs.push_back(model.choice.kind == scene::BoomKind::nodal ? 3.0 * model.choice.elements : 3.0 + model.choice.modes);
  };
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (!plan.seas[c].physical()) continue;  // no records: the sea cannot exist
    for (int s = 0; s < request.seeds; ++s) add(c, s, false);
  }
  for (std::size_t c : verified) {
    for (int s = 0; s < request.seeds; ++s) add(c, s, true);
  }
  std::vector<distributed::Task> tasks = distributed::make_tasks(keys);
  for (std::size_t i = 0; i < tasks.size(); ++i) tasks[i].expected_cost = costs[i];

  // The simulated time each record has reached, and which records are finished (scheduling thread).
  std::vector<std::atomic<double>> time_reached(tasks.size());
  for (std::atomic<double>& t : time_reached) t.store(0.0);
  std::vector<char> finished_record(tasks.size(), 0);
  farm_options.work_in_progress = [&] {
    double sum = 0.0;
    for (std::size_t i = 0; i < tasks.size(); ++i) {
      if (!finished_record[i]) sum += std::min(time_reached[i].load(std::memory_order_relaxed) / request.duration, 1.0);
    }
    return sum;
  };
  const distributed::WorkFunction work = [&](const distributed::Task& task) {
    const RecordTask& r = records[task.index];
    const CellModel& model = r.converged ? converged[r.cell] : recommended[r.cell];
    try {
      return encode(run_record(scene, cells[r.cell], r.seed, model, request, &modes, &time_reached[task.index]));
    } catch (const solve::Interrupted& stop) {  // not a result: the rerun computes it again
      throw distributed::TaskAbandoned(fmt::format("{}: interrupted by signal {}", task.key, stop.signal));
    }
  };
  if (farm_options.progress_label == "tasks") farm_options.progress_label = "operability records";
  // Cells as they complete (rank 0): the count on the progress line, and each finished cell's verdict
  // appended to cells_finished.csv (in order of completion; the table at the end is in grid order).
  std::vector<std::size_t> records_left(cells.size(), 0);
  for (const RecordTask& r : records) ++records_left[r.cell];
  std::vector<std::vector<distributed::TaskOutcome>> arrived(cells.size());
  std::size_t cells_complete = 0;
  std::string finished = "hs_m,tp_s,heading,status,verdict,governing,utilisation\n";
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (plan.seas[c].physical()) continue;
    finished += fmt::format("{:g},{:g},{},not_physical,,,\n", cells[c].significant_height, cells[c].peak_period,
                            cells[c].heading == hydro::WaveHeading::head ? "head" : "following");
  }
  const std::filesystem::path finished_file = farm_options.output_directory / "cells_finished.csv";
  farm_options.on_outcome = [&](const distributed::TaskOutcome& outcome) -> std::string {
    const RecordTask& r = records[outcome.index];
    finished_record[outcome.index] = 1;
    if (!r.converged) arrived[r.cell].push_back(outcome);
    if (--records_left[r.cell] == 0) {
      ++cells_complete;
      std::vector<const distributed::TaskOutcome*> mine;
      for (const distributed::TaskOutcome& o : arrived[r.cell]) mine.push_back(&o);
      bool ok = false;
      std::string failure;
      CellStatistics statistics;
      CellVerdict verdict;
      double wall = 0.0;
      try {
        judge_records(mine, study.criteria, recommended[r.cell].euler_load, ok, failure, statistics, verdict, wall);
      } catch (const std::exception&) {  // a damaged record: the final table names it
        ok = false;
      }
      const SeaCell& cell = cells[r.cell];
      finished += fmt::format("{:g},{:g},{},{},{},{},{}\n", cell.significant_height, cell.peak_period,
                              cell.heading == hydro::WaveHeading::head ? "head" : "following", ok ? "ok" : "failed",
                              ok ? (verdict.pass ? "pass" : "FAIL") : "", ok ? std::string(to_string(verdict.governing)) : "",
                              ok ? fmt::format("{:.4f}", verdict[verdict.governing].utilisation) : "");
      try {
        distributed::write_file_atomically(finished_file, finished);
      } catch (const std::exception&) {  // a progress file: the journal is what counts
      }
    }
    return fmt::format("{}/{} cells complete", cells_complete, cells.size());
  };
  study.farm = distributed::run_farm(session, tasks, work, farm_options);
  if (!study.farm.root) return study;

  std::vector<std::vector<const distributed::TaskOutcome*>> by_cell(cells.size()), converged_by_cell(cells.size());
  for (const distributed::TaskOutcome& outcome : study.farm.outcomes) {
    const RecordTask& r = records[outcome.index];
    (r.converged ? converged_by_cell : by_cell)[r.cell].push_back(&outcome);
  }
  for (std::size_t c = 0; c < cells.size(); ++c) {
    CellResult result;
    result.cell = cells[c];
    result.sea = plan.seas[c];
    result.model = recommended[c];
    if (!result.sea.physical()) {
      result.failure = not_physical_reason(cells[c].significant_height, cells[c].peak_period, result.sea.steepness);
      study.cells.push_back(std::move(result));
      continue;
    }
    judge_records(by_cell[c], study.criteria, recommended[c].euler_load, result.ok, result.failure, result.statistics,
                  result.verdict, result.wall_seconds);
    if (!converged_by_cell[c].empty()) {
      result.verified = true;
      result.converged = converged[c];
      judge_records(converged_by_cell[c], study.criteria, converged[c].euler_load, result.converged_ok,
                    result.converged_failure, result.converged_statistics, result.converged_verdict,
                    result.converged_wall_seconds);
    }
    study.cells.push_back(std::move(result));
  }
  study.farm.outcomes.clear();
  return study;
}

}  // namespace ffrf::study
