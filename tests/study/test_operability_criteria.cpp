// The operability criteria against hand-computed values on synthetic records (no crane): the DAF
// table's bands, the slack, snap, DAF and structural utilisations of records whose extremes are
// known in closed form, the most probable maximum against a brute-force maximisation of the density
// of the largest of N Rayleigh peaks, the statistics over seeds, and the record's text round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "study/operability_criteria.hpp"

namespace ffrf::study {
namespace operability_criteria_test {

constexpr double pi = std::numbers::pi;

// T = Ts (1 + a sin ωt) clipped at 0 (a slack wire carries nothing), heave = h sin ωt,
// M = M0 (1 + m sin ωt), axial = −P0 (1 + p sin ωt), peak stress σ0 (1 + 0.2 sin ωt) with
// σ0 = 5e7 Pa, sampled at dt over [0, duration]; static values Ts, M0, σ0.
SeedRecords sinusoids(double ts, double a, double h, double m0, double m, double p0, double p, double period,
                      double duration, double dt = 0.01) {
  SeedRecords r;
  const double omega = 2.0 * pi / period;
  for (double t = 0.0; t <= duration + 1e-9; t += dt) {
    const double s = std::sin(omega * t);
    r.time.push_back(t);
    r.tension.push_back(std::max(0.0, ts * (1.0 + a * s)));
    r.cargo_heave.push_back(h * s);
    r.root_moment.push_back(m0 * (1.0 + m * s));
    r.root_axial_force.push_back(-p0 * (1.0 + p * s));
    r.peak_stress.push_back(5.0e7 * (1.0 + 0.2 * s));
  }
  r.static_tension = ts;
  r.static_root_moment = m0;
  r.static_peak_stress = 5.0e7;
  return r;
}

// Mode of the largest of N Rayleigh peaks (σ), by scanning its density N f F^(N−1) on a fine grid:
// a second method beside the library's Newton solution.
double brute_force_mpm(double sigma, double n) {
  double best_x = 0.0, best_density = -1.0;
  for (double x = 0.0; x < 10.0 * sigma; x += 1e-5 * sigma) {
    const double u = x * x / (2.0 * sigma * sigma);
    const double log_density = std::log(n) + std::log(x / (sigma * sigma)) - u + (n - 1.0) * std::log1p(-std::exp(-u));
    if (x > 0.0 && log_density > best_density) {
      best_density = log_density;
      best_x = x;
    }
    if (x == 0.0) best_density = -1e300;
  }
  return best_x;
}

TEST(OperabilityCriteria, OffshoreDafLimitFollowsTheTableBands) {
  EXPECT_DOUBLE_EQ(offshore_daf_limit(1300.0), 1.15);  // the reference crane's 1 300 t cargo
  EXPECT_DOUBLE_EQ(offshore_daf_limit(2500.0), 1.15);
  EXPECT_DOUBLE_EQ(offshore_daf_limit(2500.1), 1.10);
  EXPECT_DOUBLE_EQ(offshore_daf_limit(1000.0), 1.20);
  EXPECT_DOUBLE_EQ(offshore_daf_limit(300.0), 1.25);
  EXPECT_NEAR(offshore_daf_limit(50.0), 1.0 + 0.25 * std::sqrt(2.0), 1e-12);   // 1.3536
  EXPECT_NEAR(offshore_daf_limit(100.0), 1.25, 1e-12);                          // the formula meets the next band
  EXPECT_NEAR(offshore_daf_limit(1.0), 1.0 + 0.25 * std::sqrt(100.0 / 3.0), 1e-12);  // below 3 t counts as 3 t
}

TEST(OperabilityCriteria, SinusoidalTensionGivesItsKnownExtremes) {
  const double ts = 1.0e7, a = 0.2, period = 10.0, duration = 1002.5;
  const SeedRecords r = sinusoids(ts, a, 0.8, -2.0e8, 0.1, 5.0e6, 0.3, period, duration);
  // The window starts and ends off a zero crossing (crests at t = 2.5 s and 1002.5 s: 100 whole periods), so that every record counts the same cycles and its mean is exact.
  const SeedExtremes s = seed_extremes(r, 2.5);
  EXPECT_NEAR(s.tension_max, ts * (1.0 + a), 1e-6 * ts);
  EXPECT_NEAR(s.tension_min, ts * (1.0 - a), 1e-6 * ts);
  EXPECT_EQ(s.slack_episodes, 0.0);
  EXPECT_EQ(s.snap_peak, 0.0);
  // 100 periods of a 10 s sine: 99 complete up-crossing cycles; σ = a Ts / √2.
  EXPECT_NEAR(s.cycles, 99.0, 1.0);
  const double sigma = a * ts / std::sqrt(2.0);
  EXPECT_NEAR(s.tension_mpm, ts + brute_force_mpm(sigma, s.cycles), 1e-4 * ts);
  // The moment's magnitude grows on the side of its (negative) mean: |M0| + MPM of the magnitude.
  EXPECT_NEAR(s.root_moment_mpm, 2.0e8 + brute_force_mpm(0.1 * 2.0e8 / std::sqrt(2.0), s.cycles), 1e-4 * 2.0e8);
  EXPECT_NEAR(s.compression_mpm, 5.0e6 + brute_force_mpm(0.3 * 5.0e6 / std::sqrt(2.0), s.cycles), 1e-4 * 5.0e6);
  EXPECT_NEAR(s.cargo_heave_mpm, brute_force_mpm(0.8 / std::sqrt(2.0), s.cycles), 1e-4);
  EXPECT_NEAR(s.peak_stress_mpm, 5.0e7 + brute_force_mpm(0.2 * 5.0e7 / std::sqrt(2.0), s.cycles), 1e-4 * 5.0e7);
  EXPECT_EQ(s.static_peak_stress, 5.0e7);
}

TEST(OperabilityCriteria, SlackEpisodesAndTheSnapPeakAfterEach) {
  // a = 1.5: the wire is slack while sin ωt < −1/1.5, once per cycle; after each episode the tension
  // rises to Ts (1 + 1.5) = 2.5 Ts a quarter period plus later — within the 5 s window for T = 8 s
  // only if it comes within 5 s of the episode's end: it does (≈ 3.3 s).
  const double ts = 1.0e7, period = 8.0;
  const SeedRecords r = sinusoids(ts, 1.5, 0.5, 1.0e8, 0.1, 1.0e6, 0.1, period, 400.0);
  const SeedExtremes s = seed_extremes(r, 0.0);
  EXPECT_EQ(s.tension_min, 0.0);
  EXPECT_NEAR(s.slack_episodes, 400.0 / period, 1.0);
  EXPECT_NEAR(s.snap_peak, 2.5 * ts, 1e-5 * ts);
}

TEST(OperabilityCriteria, TooShortARecordIsRefused) {
  const SeedRecords r = sinusoids(1.0e7, 0.2, 0.5, 1.0e8, 0.1, 1.0e6, 0.1, 10.0, 80.0);  // 7 cycles
  EXPECT_THROW(seed_extremes(r, 0.0), std::invalid_argument);
}

TEST(OperabilityCriteria, StatisticsOverSeeds) {
  const MeanAndError m = over_seeds({1.0, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_NEAR(m.standard_deviation, std::sqrt(5.0 / 3.0), 1e-15);  // Σ(x − 2.5)² = 5, n − 1 = 3
  EXPECT_NEAR(m.standard_error, std::sqrt(5.0 / 3.0) / 2.0, 1e-15);
  const MeanAndError one = over_seeds({7.0});
  EXPECT_DOUBLE_EQ(one.mean, 7.0);
  EXPECT_DOUBLE_EQ(one.standard_error, 0.0);
}

TEST(OperabilityCriteria, UtilisationsGoverningAndVerdictByHand) {
  SeedExtremes a, b;
  a.static_tension = b.static_tension = 1.0e7;
  a.static_root_moment = b.static_root_moment = -3.0e8;
  a.tension_mpm = 1.10e7;
  b.tension_mpm = 1.14e7;  // mean 1.12e7: DAF 1.12
  a.tension_min = 0.30e7;
  b.tension_min = 0.25e7;  // the smaller counts: 0.25
  a.cargo_heave_mpm = 0.4;
  b.cargo_heave_mpm = 0.6;
  a.root_moment_mpm = 3.2e8;
  b.root_moment_mpm = 3.4e8;
  a.compression_mpm = b.compression_mpm = 2.0e7;
  a.peak_stress_mpm = 1.6e8;
  b.peak_stress_mpm = 1.8e8;  // mean 1.7e8 Pa
  const CellStatistics cell = cell_statistics({a, b});
  EXPECT_DOUBLE_EQ(cell.daf, 1.12);
  EXPECT_DOUBLE_EQ(cell.minimum_tension, 0.25e7);
  OperabilityCriteria limits;
  limits.daf_limit = 1.15;
  limits.slack_margin = 0.10;
  limits.cargo_motion_limit = 1.0;
  limits.root_moment_capacity = 1.15 * 3.0e8;
  limits.buckling_ratio = 0.5;
  const CellVerdict v = judge_cell(cell, limits, 1.0e8);
  EXPECT_NEAR(v[Criterion::daf].utilisation, 1.12 / 1.15, 1e-12);
  EXPECT_NEAR(v[Criterion::daf].utilisation_error, (0.02e7 / 1.0e7) / 1.15, 1e-12);  // sd 0.02828e7 / √2
  EXPECT_NEAR(v[Criterion::slack].utilisation, (1.0 - 0.25) / 0.9, 1e-12);          // 0.8333
  EXPECT_DOUBLE_EQ(v[Criterion::snap].utilisation, 0.0);
  EXPECT_NEAR(v[Criterion::cargo_motion].utilisation, 0.5, 1e-12);
  EXPECT_NEAR(v[Criterion::root_moment].utilisation, 3.3e8 / 3.45e8, 1e-12);  // 0.9565
  EXPECT_NEAR(v[Criterion::buckling].utilisation, 2.0e7 / 5.0e7, 1e-12);
  EXPECT_FALSE(v[Criterion::boom_stress].judged);  // no allowable stress given
  EXPECT_EQ(v[Criterion::boom_stress].utilisation, 0.0);
  EXPECT_EQ(v.governing, Criterion::daf);  // 0.9739 > 0.9565 > 0.8333
  EXPECT_TRUE(v.pass);

  // A pinned boom: no root moment judged (an infinite capacity), the peak fibre stress against its
  // allowable value instead — 1.7e8 / 1.75e8 = 0.9714, just below the DAF's 0.9739.
  OperabilityCriteria pinned = limits;
  pinned.root_moment_capacity = std::numeric_limits<double>::infinity();
  pinned.allowable_stress = 1.75e8;
  const CellVerdict p = judge_cell(cell, pinned, 1.0e8);
  EXPECT_FALSE(p[Criterion::root_moment].judged);
  EXPECT_EQ(p[Criterion::root_moment].utilisation, 0.0);
  EXPECT_TRUE(p[Criterion::boom_stress].judged);
  EXPECT_NEAR(p[Criterion::boom_stress].utilisation, 1.7e8 / 1.75e8, 1e-12);
  EXPECT_NEAR(p[Criterion::boom_stress].utilisation_error, 1.0e7 / 1.75e8, 1e-12);  // s.e. = sd 0.1414e8 / √2
  EXPECT_EQ(p.governing, Criterion::daf);
  pinned.allowable_stress = 1.65e8;  // now the boom's stress governs, and fails the cell
  const CellVerdict over = judge_cell(cell, pinned, 1.0e8);
  EXPECT_EQ(over.governing, Criterion::boom_stress);
  EXPECT_FALSE(over.pass);

  b.tension_min = 0.05e7;  // below the 10 % margin: slack governs and the cell fails
  const CellVerdict slack = judge_cell(cell_statistics({a, b}), limits, 1.0e8);
  EXPECT_NEAR(slack[Criterion::slack].utilisation, 0.95 / 0.9, 1e-12);
  EXPECT_EQ(slack.governing, Criterion::slack);
  EXPECT_FALSE(slack.pass);
}

TEST(OperabilityCriteria, RecordTextRoundTripsExactly) {
  SeedExtremes s;
  s.static_tension = 1.2753e7 / 3.0;
  s.tension_mpm = std::nextafter(1.4e7, 2e7);
  s.root_moment_mpm = 1.0 / 3.0;
  s.work = 123456789.0;
  s.peak_stress_mpm = 2.0e8 / 7.0;
  s.static_peak_stress = std::nextafter(5.0e7, 0.0);
  const SeedExtremes back = decode_seed_extremes(encode(s));
  EXPECT_EQ(back.peak_stress_mpm, s.peak_stress_mpm);
  EXPECT_EQ(back.static_peak_stress, s.static_peak_stress);
  EXPECT_EQ(back.static_tension, s.static_tension);
  EXPECT_EQ(back.tension_mpm, s.tension_mpm);
  EXPECT_EQ(back.root_moment_mpm, s.root_moment_mpm);
  EXPECT_EQ(back.work, s.work);
  EXPECT_THROW(decode_seed_extremes("1 2 3"), std::invalid_argument);
}

TEST(OperabilityCriteria, LimitsOutOfRangeAreNamed) {
  OperabilityCriteria c;
  c.slack_margin = 1.2;
  try {
    validate(c);
    FAIL() << "accepted a slack margin of 1.2";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("slack_margin = 1.2"), std::string::npos) << error.what();
  }
}

}  // namespace operability_criteria_test
}  // namespace ffrf::study
