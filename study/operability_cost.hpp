// What an operability table will cost, before it starts: a probe runs the first seconds of one cell's
// record with its model (and with the converged model when cells are verified) and times the two
// parts of a record's wall time, the set-up (model build, static equilibrium, wave synthesis) and the
// integration per simulated second; the table then costs
//   Σ over its records (set-up + rate × record length) / workers,
// at least one record's time. The probe cell is the physical cell with the shortest Tp (its band
// reaches the highest frequencies, so its steps are the shortest), the largest Hs among those: an
// estimate from the costly end. It is a timing: it goes to a terminal, never into a result.
#pragma once

#include <cstddef>

#include "study/operability.hpp"

namespace ffrf::study {

struct RecordCost {
  double setup_seconds = 0.0;                 // wall time before the integration
  double seconds_per_simulated_second = 0.0;  // integration wall time / simulated time
  double probe_length = 0.0;                  // simulated [s]
  double record_seconds(double record_length) const { return setup_seconds + seconds_per_simulated_second * record_length; }
};

struct TableCostEstimate {
  std::size_t probe_cell = 0;     // index into the plan's cells
  RecordCost recommended, converged;  // converged: zero when no cell is verified
  std::size_t records = 0, workers = 1;
  double seconds = 0.0;           // the estimated wall time of the table
};

// The probe's simulated length: the ramp-in and two peak periods, at most the record.
double probe_length(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request);

// Runs the probe (seconds of wall time: a few Tp of one record) and extrapolates to `records`
// records on `workers` workers. Throws what a record throws (a solver failure of the probe).
TableCostEstimate estimate_table_cost(const scene::Scene& scene, const OperabilityRequest& request,
                                      const OperabilityPlan& plan, std::size_t workers, modal::ModeCache* modes);

}  // namespace ffrf::study
