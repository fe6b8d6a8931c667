// The lift criteria of an operability table (docs/operability.md §2) and the statistics behind them.
// One seed's record gives SeedExtremes (most probable maxima by the Rayleigh distribution of peaks,
// DNV-RP-C205 §3.5.8–3.5.11, via hydro/extreme_values); a cell's seeds give CellStatistics (the mean
// over seeds of each most probable maximum, its standard error, the extremes over seeds); the
// criteria turn them into utilisations (1 = at the limit) and a verdict:
//   DAF        u = (MPM tension / static tension) / DAF limit           (DNV-ST-N001 §16 / 0027/ND Table 5-1)
//   slack wire u = (1 − T_min / T_static) / (1 − slack margin)          (DNV-RP-H103 §3.4.3: F_dyn ≤ 0.9 F_static)
//   snap load  u = largest tension after a slack episode / (DAF limit · T_static)   (0 without slack)
//   cargo      u = MPM cargo heave amplitude about its mean / limit
//   boom root  u = MPM |root moment| / moment capacity                 (a clamped boom's; a pin carries none)
//   boom stress u = MPM peak fibre stress along the boom / allowable stress   (when the scene gives one)
//   buckling   u = MPM axial compression / (buckling ratio · Euler load: π²EI/(4L²) clamped, π²EI/L² pinned)
// The governing criterion is the largest utilisation; a cell passes when every one is ≤ 1.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "multibody/crane_run.hpp"

namespace ffrf::study {

enum class Criterion { daf, slack, snap, cargo_motion, root_moment, boom_stress, buckling };
inline constexpr std::array<Criterion, 7> all_criteria{Criterion::daf,         Criterion::slack,       Criterion::snap,
                                                        Criterion::cargo_motion, Criterion::root_moment, Criterion::boom_stress,
                                                        Criterion::buckling};
std::string_view to_string(Criterion criterion);  // "daf", "slack", "snap", "cargo_motion", ...

// Limits; 0 in a field with a scene-dependent default means "use the default" (resolve_criteria).
struct OperabilityCriteria {
  double daf_limit = 0.0;            // 0: the offshore in-air DAF of the hook load (offshore_daf_limit)
  double slack_margin = 0.10;        // T_min ≥ margin · T_static
  double cargo_motion_limit = 1.0;   // [m] MPM heave amplitude of the cargo (user default; no standard value)
  double root_moment_capacity = 0.0; // [N m]; 0: DAF limit × |static root moment| (the rated dynamic moment);
                                     // infinite once resolved for a pinned boom (the criterion does not apply)
  double allowable_stress = 0.0;     // [Pa] of the boom's extreme fibre: boom.allowable_stress; 0: not judged
  double buckling_ratio = 0.5;       // axial compression ≤ ratio · Euler load (user default)
};

// The offshore column of the in-air DAF table (GL Noble Denton 0027/ND Rev 11 Table 5-1; DNV-ST-N001
// Table 16-x has the same bands): W ≤ 100 t: 1 + 0.25 sqrt(100/W); ≤ 300 t: 1.25; ≤ 1000 t: 1.20;
// ≤ 2500 t: 1.15; above: 1.10. W = static hook load [t] (3 t at least, the table's note 1).
double offshore_daf_limit(double hook_load_tonnes);

// Throws std::invalid_argument naming the limit, its value and the valid range.
void validate(const OperabilityCriteria& criteria);

// One seed's record reduced to what the criteria need (deterministic: no timing).
struct SeedExtremes {
  double static_tension = 0.0;       // [N]
  double static_root_moment = 0.0;   // [N m] signed
  double tension_mpm = 0.0;          // level [N]: mean + Rayleigh MPM of (T − mean)
  double tension_max = 0.0, tension_min = 0.0;  // observed [N]
  double snap_peak = 0.0;            // largest tension within snap_window after a slack episode [N] (0: none)
  double slack_episodes = 0.0;       // runs of samples with T ≤ 0
  double cargo_heave_mpm = 0.0;      // [m] MPM amplitude about the mean
  double root_moment_mpm = 0.0;      // [N m] MPM level of |M| (on the side of the mean moment)
  double compression_mpm = 0.0;      // [N] MPM level of the root's axial compression
  double static_peak_stress = 0.0;   // [Pa] the boom's peak fibre stress at rest
  double peak_stress_mpm = 0.0;      // [Pa] MPM level of the boom's peak fibre stress
  double cycles = 0.0;               // zero up-crossing cycles of the tension (N of the MPM)
  double work = 0.0;                 // solver work: RHS evaluations × state size
  double rhs_evaluations = 0.0;
};

inline constexpr double snap_window = 5.0;  // [s] after a slack episode in which the snap peak is sought

// One seed's sampled records (equal lengths) and its state at rest.
struct SeedRecords {
  std::vector<double> time, tension, cargo_heave, root_moment, root_axial_force, peak_stress;
  double static_tension = 0.0, static_root_moment = 0.0, static_peak_stress = 0.0;
};

// Statistics of sampled records over t ≥ start. Throws std::invalid_argument when fewer than 10
// tension cycles lie in the window (the MPM would be meaningless: lengthen the record).
SeedExtremes seed_extremes(const SeedRecords& records, double start);

std::string encode(const SeedExtremes& seed);  // one line of numbers, round-trip exact
SeedExtremes decode_seed_extremes(const std::string& text);  // throws std::invalid_argument

struct MeanAndError {
  double mean = 0.0, standard_deviation = 0.0, standard_error = 0.0;  // over seeds (n − 1); 0 for one seed
};
MeanAndError over_seeds(const std::vector<double>& values);

struct CellStatistics {
  std::size_t seeds = 0;
  double static_tension = 0.0, static_root_moment = 0.0, static_peak_stress = 0.0;
  MeanAndError tension_mpm, cargo_heave_mpm, root_moment_mpm, compression_mpm, peak_stress_mpm;
  double daf = 0.0;             // mean MPM tension / static
  double daf_standard_error = 0.0;
  double minimum_tension = 0.0;  // over all seeds [N]
  double snap_peak = 0.0;        // over all seeds [N]
  double slack_episodes = 0.0;   // summed over seeds
  double work = 0.0, rhs_evaluations = 0.0;  // summed over seeds
};
// Throws std::invalid_argument for no seeds or seeds with different static states.
CellStatistics cell_statistics(const std::vector<SeedExtremes>& seeds);

struct CriterionResult {
  Criterion criterion = Criterion::daf;
  double value = 0.0, limit = 0.0;   // in the criterion's terms (DAF, T_min/T_s, snap/T_s, m, N m, Pa, N)
  double utilisation = 0.0;          // 1 at the limit
  double utilisation_error = 0.0;    // standard error over seeds (0 for extremes over seeds)
  bool judged = true;                // false: the criterion does not apply (a pin's root moment, no allowable stress)
};

struct CellVerdict {
  std::array<CriterionResult, all_criteria.size()> results{};
  Criterion governing = Criterion::daf;
  bool pass = true;
  const CriterionResult& operator[](Criterion c) const { return results[static_cast<std::size_t>(c)]; }
};

// Judges a cell against limits resolved for the scene (no 0 defaults left); euler_load [N].
CellVerdict judge_cell(const CellStatistics& cell, const OperabilityCriteria& resolved, double euler_load);

}  // namespace ffrf::study
