// The probe that estimates an operability table's cost (see operability_cost.hpp).
#include "study/operability_cost.hpp"

#include <algorithm>
#include <chrono>

#include "scene/irregular_sea.hpp"
#include "study/run_pipeline.hpp"
#include "study/wall_clock.hpp"

namespace ffrf::study {
namespace {

RecordCost probe(const scene::Scene& scene, const SeaCell& cell, const CellModel& model, const OperabilityRequest& request,
                 modal::ModeCache* modes) {
  const auto start = std::chrono::steady_clock::now();
  // The record's own sea (its components over the whole record length), integrated over the probe only.
  const scene::Scene record = record_scene(scene, cell, record_seed(cell, 0), request);
  DynamicsRequest dynamics;
  dynamics.integrator = model.integrator;
  dynamics.relative_tolerance = dynamics.absolute_tolerance = model.relative_tolerance;
  dynamics.duration = probe_length(scene, cell, request);
  const ModelRun run = run_model(record, model.choice, integrator_settings(record, dynamics), modes);
  const double total = seconds_since(start);
  RecordCost cost;
  cost.probe_length = *dynamics.duration;
  cost.seconds_per_simulated_second = run.result.stats.wall_seconds / cost.probe_length;
  cost.setup_seconds = std::max(total - run.result.stats.wall_seconds, 0.0);
  return cost;
}

}  // namespace

double probe_length(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request) {
  const scene::Scene record = record_scene(scene, cell, record_seed(cell, 0), request);
  return std::min(request.duration, scene::wave_ramp_duration(record) + 2.0 * cell.peak_period);
}

TableCostEstimate estimate_table_cost(const scene::Scene& scene, const OperabilityRequest& request,
                                      const OperabilityPlan& plan, std::size_t workers, modal::ModeCache* modes) {
  TableCostEstimate estimate;
  estimate.workers = std::max<std::size_t>(workers, 1);
  estimate.records = plan.records(request.seeds);
  bool found = false;
  for (std::size_t c = 0; c < plan.cells.size(); ++c) {
    if (!plan.seas[c].physical()) continue;
    const SeaCell& cell = plan.cells[c], &best = plan.cells[estimate.probe_cell];
    if (!found || cell.peak_period < best.peak_period ||
        (cell.peak_period == best.peak_period && cell.significant_height > best.significant_height)) {
      estimate.probe_cell = c;
      found = true;
    }
  }
  const SeaCell& cell = plan.cells[estimate.probe_cell];
  estimate.recommended = probe(scene, cell, plan.recommended[estimate.probe_cell], request, modes);
  const double seeds = request.seeds;
  const double recommended = estimate.recommended.record_seconds(request.duration);
  double total = static_cast<double>(plan.physical_cells()) * seeds * recommended, longest = recommended;
  if (!plan.verified.empty()) {
    estimate.converged = probe(scene, cell, plan.converged[estimate.probe_cell], request, modes);
    const double converged = estimate.converged.record_seconds(request.duration);
    total += static_cast<double>(plan.verified.size()) * seeds * converged;
    longest = std::max(longest, converged);
  }
  estimate.seconds = std::max(total / static_cast<double>(estimate.workers), longest);
  return estimate;
}

}  // namespace ffrf::study
