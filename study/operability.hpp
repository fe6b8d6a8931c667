// The operability table (`ffrf operability`, docs/operability.md): a grid of sea states Hs × Tp
// (× heading), N seeds per cell, one record of `duration` seconds per seed. Each (cell, seed) is one
// task of the distributed engine (distributed/farm.hpp), so that cells and seeds are balanced over
// threads and MPI ranks, journaled as they finish and resumed on a rerun. Per cell the seeds'
// extremes become statistics and a verdict (operability_criteria.hpp). A cell steeper than a sea can
// be is not physical: it gets no records and no verdict (operability_sea.hpp); each cell's records
// keep the band of its own spectrum that holds `variance_share` of m0.
// The boom model per cell is `ffrf recommend`'s on a probe record of the cell's sea (its first seed,
// probe_peak_periods peak periods or the record if shorter): the cheapest model that passes the
// tolerance against the converged reference by solver work at the model-choice rtol
// (study::cheapest_passing, the rule of recommend, compare and sweep). A sample of cells is run again, same seeds, with the converged model (a
// fine nodal mesh at a tight tolerance) to verify that choice and to measure what it saved.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "multibody/crane_run.hpp"
#include "distributed/farm.hpp"
#include "hydro/wave_synthesis.hpp"
#include "modal/mode_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"
#include "study/operability_criteria.hpp"
#include "study/operability_sea.hpp"

namespace ffrf::study {

struct SeaCell {
  double significant_height = 0.0;  // Hs [m]
  double peak_period = 0.0;         // Tp [s]
  hydro::WaveHeading heading = hydro::WaveHeading::following;
  std::string key() const;  // "Hs=2.5 Tp=9 heading=following" (exact: %.17g)
};

// "following" or "head"; throws SettingError (Setting::headings) for another name.
hydro::WaveHeading parse_heading(std::string_view name);

struct OperabilityRequest {
  std::vector<double> significant_heights, peak_periods;  // the grid's axes [m], [s]
  std::vector<hydro::WaveHeading> headings{hydro::WaveHeading::following};
  int seeds = 3;                 // records per cell
  double duration = 10800.0;     // of each record [s]
  double peak_enhancement = 3.3; // JONSWAP γ of every cell
  int components = 0;            // wave components per record (0: Δω = 2π / duration, a sea that never repeats)
  double variance_share = hydro::default_variance_share;  // of each cell's m0 within its synthesis band
  OperabilityCriteria criteria;  // limits (0 fields: scene defaults)
  double tolerance = 0.01;       // of the model choice (recommend's τ)
  int verify_cells = 2;          // cells run again with the converged model (0: none)
  int converged_elements = 32;   // the converged model: nodal N at rtol τ/1000
};
// Throws SettingError / std::invalid_argument naming the first setting out of range.
void validate(const OperabilityRequest& request);

std::vector<SeaCell> sea_cells(const OperabilityRequest& request);  // Hs fastest, then Tp, then heading
// The cells verified against the converged model: `count` cells spread evenly over the list.
std::vector<std::size_t> verified_cells(std::size_t cells, int count);

// The probe record of a cell's model choice: probe_peak_periods × Tp, or the record if shorter [s].
inline constexpr double probe_peak_periods = 20.0;
double probe_duration(const SeaCell& cell, const OperabilityRequest& request);

// The model recommend picks for a cell on its probe record (at recommend's rtol; the reference's
// model when no cheaper one passes; when the probe's reference run fails, the reasoning's first
// kept candidate, unverified), and why.
struct CellModel {
  scene::BoomChoice choice;
  solve::Integrator integrator = solve::Integrator::cvode;
  double relative_tolerance = 1e-4;
  double excitation_top = 0.0;  // [rad/s] the upper edge of the sea's energy band
  int dynamic_modes = 0;
  double euler_load = 0.0;      // [N] of the boom
  std::string label() const;    // "modal k=1+static (N=8), cvode rtol 1e-04"
};
CellModel recommended_model(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request,
                            modal::ModeCache* modes);
CellModel converged_model(const scene::Scene& scene, const OperabilityRequest& request, const CellModel& recommended);

// The cell's JONSWAP spectrum (σa, σb of the scene's sea when it has one).
hydro::WaveSpectrum cell_spectrum(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request);
// The sea of the cell's records (band, components, repetition, steepness).
CellSea cell_sea(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request);

// The scene of one record: the cell's JONSWAP sea (scene::in_irregular_sea) with the seed's random
// phases over the cell's own band (hydro::variance_band), the request's component count.
scene::Scene record_scene(const scene::Scene& scene, const SeaCell& cell, std::uint64_t seed,
                          const OperabilityRequest& request);
// The seed of record `index` of a cell: from the cell's key and the index only, the same for both models.
std::uint64_t record_seed(const SeaCell& cell, int index);

// One record: prepare, integrate, reduce (statistics after the wave ramp). Throws on a solver failure.
// `time_reached` (optional) follows the integrator's simulated time, for progress within the record.
SeedExtremes run_record(const scene::Scene& scene, const SeaCell& cell, int seed_index, const CellModel& model,
                        const OperabilityRequest& request, modal::ModeCache* modes,
                        std::atomic<double>* time_reached = nullptr);

enum class CellStatus { ok, failed, not_physical };  // a verdict; a record failed; too steep to exist
std::string_view to_string(CellStatus status);       // "ok", "failed", "not_physical"

struct CellResult {
  SeaCell cell;
  CellSea sea;
  CellModel model;      // none for a cell that is not physical
  bool ok = false;      // every record ran: statistics and verdict hold
  std::string failure;  // the first failed seed's message, or why the cell is not physical
  CellStatus status() const { return !sea.physical() ? CellStatus::not_physical : ok ? CellStatus::ok : CellStatus::failed; }
  CellStatistics statistics;
  CellVerdict verdict;
  double wall_seconds = 0.0;  // timing: the seeds' task times summed
  // The verification with the converged model (verified cells only).
  bool verified = false, converged_ok = false;
  std::string converged_failure;
  CellModel converged;
  CellStatistics converged_statistics;
  CellVerdict converged_verdict;
  double converged_wall_seconds = 0.0;
};

// What a table will run, before anything runs: every cell's sea and models, the verified cells, the
// records. The same on every process.
struct OperabilityPlan {
  std::vector<SeaCell> cells;
  std::vector<CellSea> seas;
  std::vector<CellModel> recommended, converged;  // default-constructed for a cell that is not physical
  std::vector<std::size_t> verified;              // physical cells run again with the converged model
  std::vector<std::string> warnings;              // the sea repeats within the record; the scene's band replaced
  std::size_t physical_cells() const;
  std::size_t records(int seeds) const;           // (physical + verified cells) × seeds
};
// Throws std::invalid_argument when no cell of the grid is physical (every one too steep).
OperabilityPlan plan_operability(const scene::Scene& scene, const OperabilityRequest& request, modal::ModeCache* modes);
// "the sea repeats every 315 s (2π/Δω, 40 components over 0.8 rad/s): a 10800-s record is 34.3
// repeats ..." for the cells whose records repeat, the one with the fewest independent cycles named;
// empty when no record repeats.
std::string repetition_warning(const OperabilityPlan& plan, const OperabilityRequest& request);

struct OperabilityStudy {
  OperabilityCriteria criteria;  // as resolved (DAF limit from the hook load)
  std::vector<CellResult> cells;
  std::vector<std::string> warnings;  // the plan's
  distributed::FarmResult farm;  // engine, counts, journal, wall time (outcomes dropped)
};

// Runs every (cell, seed) task of the physical cells and the verification tasks on the engine and
// judges the cells. Every process calls it; on ranks > 0 the result has farm.root == false and no
// cells. The first form plans itself.
OperabilityStudy run_operability(distributed::Session& session, const scene::Scene& scene,
                                 const OperabilityRequest& request, distributed::FarmOptions farm_options);
OperabilityStudy run_operability(distributed::Session& session, const scene::Scene& scene,
                                 const OperabilityRequest& request, const OperabilityPlan& plan,
                                 distributed::FarmOptions farm_options);

// The criteria with the scene's defaults filled in (DAF limit from the cargo's mass).
OperabilityCriteria resolve_criteria(const scene::Scene& scene, const OperabilityCriteria& criteria);

}  // namespace ffrf::study
