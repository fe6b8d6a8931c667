// Lift criteria and the statistics behind them (see operability_criteria.hpp).
#include "study/operability_criteria.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "hydro/extreme_values.hpp"
#include "hydro/record_statistics.hpp"

namespace ffrf::study {
namespace {

struct Rayleigh {
  double mean = 0.0, mpm = 0.0, cycles = 0.0;  // mpm above the mean
};

// Mean and the Rayleigh most probable maximum above it (σ, N = zero up-crossing cycles).
Rayleigh rayleigh_of(const std::vector<double>& record, double dt, const char* what) {
  const hydro::RecordStatistics stats = hydro::record_statistics(record, dt);
  if (stats.waves < 10) {
    throw std::invalid_argument(fmt::format("the {} record has {} response cycles after the transient, fewer than the 10 a "
                                            "most probable maximum needs: lengthen the record",
                                            what, stats.waves));
  }
  const double cycles = static_cast<double>(stats.waves);
  return {stats.mean, hydro::rayleigh_most_probable_maximum(stats.standard_deviation, cycles), cycles};
}

}  // namespace

std::string_view to_string(Criterion criterion) {
  switch (criterion) {
    case Criterion::daf: return "daf";
    case Criterion::slack: return "slack";
    case Criterion::snap: return "snap";
    case Criterion::cargo_motion: return "cargo_motion";
    case Criterion::root_moment: return "root_moment";
    case Criterion::boom_stress: return "boom_stress";
    case Criterion::buckling: return "buckling";
  }
  return "?";
}

double offshore_daf_limit(double hook_load_tonnes) {
  const double w = std::max(hook_load_tonnes, 3.0);
  if (w <= 100.0) return 1.0 + 0.25 * std::sqrt(100.0 / w);
  if (w <= 300.0) return 1.25;
  if (w <= 1000.0) return 1.20;
  if (w <= 2500.0) return 1.15;
  return 1.10;
}

void validate(const OperabilityCriteria& c) {
  const auto bad = [](const char* name, double value, const char* range) {
    throw std::invalid_argument(fmt::format("criterion {} = {}: out of range (valid range {})", name, value, range));
  };
  if (!(c.daf_limit == 0.0 || (c.daf_limit > 1.0 && c.daf_limit <= 5.0))) bad("daf_limit", c.daf_limit, "(1, 5], 0: from the hook load");
  if (!(c.slack_margin >= 0.0 && c.slack_margin < 1.0)) bad("slack_margin", c.slack_margin, "[0, 1)");
  if (!(c.cargo_motion_limit > 0.0 && std::isfinite(c.cargo_motion_limit))) bad("cargo_motion_limit", c.cargo_motion_limit, "(0, inf) m");
  if (!(c.root_moment_capacity >= 0.0 && std::isfinite(c.root_moment_capacity))) {
    bad("root_moment_capacity", c.root_moment_capacity, "(0, inf) N m, 0: DAF limit x static moment");
  }
  if (!(c.allowable_stress >= 0.0 && std::isfinite(c.allowable_stress))) {
    bad("allowable_stress", c.allowable_stress, "(0, inf) Pa, 0: not judged");
  }
  if (!(c.buckling_ratio > 0.0 && c.buckling_ratio <= 1.0)) bad("buckling_ratio", c.buckling_ratio, "(0, 1]");
}

SeedExtremes seed_extremes(const SeedRecords& records, double start) {
  const std::vector<double>& time = records.time;
  const std::size_t n = time.size();
  if (records.tension.size() != n || records.cargo_heave.size() != n || records.root_moment.size() != n ||
      records.root_axial_force.size() != n || records.peak_stress.size() != n || n < 3) {
    throw std::invalid_argument("seed_extremes: records of different lengths or fewer than 3 samples");
  }
  const auto first = static_cast<std::size_t>(std::lower_bound(time.begin(), time.end(), start) - time.begin());
  if (n - first < 3) throw std::invalid_argument(fmt::format("seed_extremes: no record after t = {} s", start));
  const double dt = time[first + 1] - time[first];
  const auto window = [&](const std::vector<double>& v) { return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(first), v.end()); };
  SeedExtremes s;
  s.static_tension = records.static_tension;
  s.static_root_moment = records.static_root_moment;
  s.static_peak_stress = records.static_peak_stress;
  const std::vector<double> t = window(records.tension);
  const Rayleigh tr = rayleigh_of(t, dt, "wire tension");
  s.tension_mpm = tr.mean + tr.mpm;
  s.cycles = tr.cycles;
  s.tension_max = *std::max_element(t.begin(), t.end());
  s.tension_min = *std::min_element(t.begin(), t.end());
  // Slack episodes and the largest tension within snap_window after each one ends.
  for (std::size_t i = 0; i < t.size();) {
    if (t[i] > 0.0) {
      ++i;
      continue;
    }
    s.slack_episodes += 1.0;
    while (i < t.size() && t[i] <= 0.0) ++i;
    const double end_time = i < t.size() ? time[first + i] : time.back();
    for (std::size_t j = i; j < t.size() && time[first + j] <= end_time + snap_window && t[j] > 0.0; ++j) {
      s.snap_peak = std::max(s.snap_peak, t[j]);
    }
  }
  const Rayleigh heave = rayleigh_of(window(records.cargo_heave), dt, "cargo heave");
  s.cargo_heave_mpm = heave.mpm;
  std::vector<double> moment = window(records.root_moment);
  const double sign = records.static_root_moment < 0.0 ? -1.0 : 1.0;
  for (double& m : moment) m *= sign;
  const Rayleigh mr = rayleigh_of(moment, dt, "boom root moment");
  s.root_moment_mpm = std::abs(mr.mean + mr.mpm);
  std::vector<double> compression = window(records.root_axial_force);
  for (double& c : compression) c = -c;
  const Rayleigh cr = rayleigh_of(compression, dt, "boom axial force");
  s.compression_mpm = cr.mean + cr.mpm;
  const Rayleigh stress = rayleigh_of(window(records.peak_stress), dt, "boom peak stress");
  s.peak_stress_mpm = stress.mean + stress.mpm;
  return s;
}

std::string encode(const SeedExtremes& s) {
  return fmt::format(
      "{:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}",
      s.static_tension, s.static_root_moment, s.tension_mpm, s.tension_max, s.tension_min, s.snap_peak, s.slack_episodes,
      s.cargo_heave_mpm, s.root_moment_mpm, s.compression_mpm, s.cycles, s.work, s.rhs_evaluations, s.static_peak_stress,
      s.peak_stress_mpm);
}

SeedExtremes decode_seed_extremes(const std::string& text) {
  std::istringstream in(text);
  SeedExtremes s;
  double* fields[] = {&s.static_tension, &s.static_root_moment, &s.tension_mpm, &s.tension_max, &s.tension_min,
                      &s.snap_peak, &s.slack_episodes, &s.cargo_heave_mpm, &s.root_moment_mpm, &s.compression_mpm,
                      &s.cycles, &s.work, &s.rhs_evaluations, &s.static_peak_stress, &s.peak_stress_mpm};
  for (double* field : fields) {
    if (!(in >> *field) || !std::isfinite(*field)) throw std::invalid_argument("not a seed record: '" + text + "'");
  }
  std::string rest;
  if (in >> rest) throw std::invalid_argument("not a seed record (extra fields): '" + text + "'");
  return s;
}

MeanAndError over_seeds(const std::vector<double>& values) {
  MeanAndError r;
  if (values.empty()) return r;
  double sum = 0.0;
  for (double v : values) sum += v;
  const double n = static_cast<double>(values.size());
  r.mean = sum / n;
  if (values.size() < 2) return r;
  double squares = 0.0;
  for (double v : values) squares += (v - r.mean) * (v - r.mean);
  r.standard_deviation = std::sqrt(squares / (n - 1.0));
  r.standard_error = r.standard_deviation / std::sqrt(n);
  return r;
}

CellStatistics cell_statistics(const std::vector<SeedExtremes>& seeds) {
  if (seeds.empty()) throw std::invalid_argument("cell_statistics: no seeds");
  CellStatistics c;
  c.seeds = seeds.size();
  c.static_tension = seeds.front().static_tension;
  c.static_root_moment = seeds.front().static_root_moment;
  c.static_peak_stress = seeds.front().static_peak_stress;
  if (!(c.static_tension > 0.0)) throw std::invalid_argument("cell_statistics: the wire carries no static tension");
  std::vector<double> tension, heave, moment, compression, stress;
  c.minimum_tension = std::numeric_limits<double>::infinity();
  for (const SeedExtremes& s : seeds) {
    if (std::abs(s.static_tension - c.static_tension) > 1e-9 * c.static_tension) {
      throw std::invalid_argument("cell_statistics: seeds of one cell with different static tensions");
    }
    tension.push_back(s.tension_mpm);
    heave.push_back(s.cargo_heave_mpm);
    moment.push_back(s.root_moment_mpm);
    compression.push_back(s.compression_mpm);
    stress.push_back(s.peak_stress_mpm);
    c.minimum_tension = std::min(c.minimum_tension, s.tension_min);
    c.snap_peak = std::max(c.snap_peak, s.snap_peak);
    c.slack_episodes += s.slack_episodes;
    c.work += s.work;
    c.rhs_evaluations += s.rhs_evaluations;
  }
  c.tension_mpm = over_seeds(tension);
  c.cargo_heave_mpm = over_seeds(heave);
  c.root_moment_mpm = over_seeds(moment);
  c.compression_mpm = over_seeds(compression);
  c.peak_stress_mpm = over_seeds(stress);
  c.daf = c.tension_mpm.mean / c.static_tension;
  c.daf_standard_error = c.tension_mpm.standard_error / c.static_tension;
  return c;
}

CellVerdict judge_cell(const CellStatistics& cell, const OperabilityCriteria& limits, double euler_load) {
  if (!(limits.daf_limit > 1.0 && limits.root_moment_capacity > 0.0 && euler_load > 0.0)) {
    throw std::invalid_argument("judge_cell: criteria not resolved for the scene (DAF limit, moment capacity, Euler load)");
  }
  CellVerdict v;
  const double ts = cell.static_tension;
  const auto set = [&](Criterion c, double value, double limit, double utilisation, double error) {
    v.results[static_cast<std::size_t>(c)] = {c, value, limit, utilisation, error, true};
  };
  const auto not_judged = [&](Criterion c, double value) { v.results[static_cast<std::size_t>(c)] = {c, value, 0.0, 0.0, 0.0, false}; };
  set(Criterion::daf, cell.daf, limits.daf_limit, cell.daf / limits.daf_limit, cell.daf_standard_error / limits.daf_limit);
  const double unloading = 1.0 - cell.minimum_tension / ts;
  set(Criterion::slack, cell.minimum_tension / ts, limits.slack_margin, unloading / (1.0 - limits.slack_margin), 0.0);
  set(Criterion::snap, cell.snap_peak / ts, limits.daf_limit, cell.snap_peak / (ts * limits.daf_limit), 0.0);
  set(Criterion::cargo_motion, cell.cargo_heave_mpm.mean, limits.cargo_motion_limit,
      cell.cargo_heave_mpm.mean / limits.cargo_motion_limit, cell.cargo_heave_mpm.standard_error / limits.cargo_motion_limit);
  if (std::isfinite(limits.root_moment_capacity)) {
    set(Criterion::root_moment, cell.root_moment_mpm.mean, limits.root_moment_capacity,
        cell.root_moment_mpm.mean / limits.root_moment_capacity,
        cell.root_moment_mpm.standard_error / limits.root_moment_capacity);
  } else {
    not_judged(Criterion::root_moment, cell.root_moment_mpm.mean);
  }
  if (limits.allowable_stress > 0.0) {
    set(Criterion::boom_stress, cell.peak_stress_mpm.mean, limits.allowable_stress, cell.peak_stress_mpm.mean / limits.allowable_stress,
        cell.peak_stress_mpm.standard_error / limits.allowable_stress);
  } else {
    not_judged(Criterion::boom_stress, cell.peak_stress_mpm.mean);
  }
  const double buckling_limit = limits.buckling_ratio * euler_load;
  set(Criterion::buckling, cell.compression_mpm.mean, buckling_limit, cell.compression_mpm.mean / buckling_limit,
      cell.compression_mpm.standard_error / buckling_limit);
  for (const CriterionResult& r : v.results) {
    if (r.utilisation > v[v.governing].utilisation) v.governing = r.criterion;
    v.pass = v.pass && r.utilisation <= 1.0;
  }
  return v;
}

}  // namespace ffrf::study
