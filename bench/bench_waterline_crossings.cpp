// Benchmark of the waterline-crossing search (sea/waterline_crossings.hpp) and of the whole hull
// pressure integral (sea/hull_pressure.hpp) on the reference hull's four box edges (90 m × 8 m,
// loaded draft, random heave ±1 m and pitch ±1.5°) in the reference crane's JONSWAP sea (Hs 2 m,
// Tp 8 s, γ 3.3 on Δω = 2π/record over [ωp/2, 3ωp], cases/irregular_sea_crane.toml, synthesized by
// hydro::synthesize: tests/sea/jonswap_test_sea.hpp) for records of 20 minutes, 1 hour and
// 3 hours. Side by side in one run: the search with the wave field's global bounds
// (tests/sea/waterline_crossings_global_bounds.hpp, direct sums), the search and the hull load
// with every component sum by the direct formula (WaveField::with_direct_sums) and by the harmonic-grid
// recurrence (sea/component_phasors.hpp, what the crane uses). Prints the time per hull (four
// edges) and the ratios; all searches must find the same number of crossings and both hull loads must
// agree to 1e-10 of the box's buoyancy (checked, else exit 1).
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "../tests/sea/jonswap_test_sea.hpp"
#include "../tests/sea/waterline_crossings_global_bounds.hpp"
#include "sea/hull_pressure.hpp"
#include "sea/waterline_crossings.hpp"
#include "sea/wave_field.hpp"

namespace {

using ffrf::sea::WaveField;

struct Pose {
  double heave, pitch, t;
};

template <class Search>
double seconds_per_hull(const std::vector<Pose>& poses, Search&& search, long& crossings) {
  const auto start = std::chrono::steady_clock::now();
  crossings = 0;
  for (const Pose& p : poses) {
    const double c = std::cos(p.pitch), s = std::sin(p.pitch);
    const auto place = [&](double x, double y) { return Eigen::Vector2d(c * x - s * y, 1.91 + p.heave + s * x + c * y); };
    const Eigen::Vector2d corner[4] = {place(-32.0, -6.0), place(58.0, -6.0), place(58.0, 2.0), place(-32.0, 2.0)};
    for (int e = 0; e < 4; ++e) crossings += search(p.t, corner[e], corner[(e + 1) % 4] - corner[e]).count;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / static_cast<double>(poses.size());
}

const ffrf::sea::BoxHullSection hull{-32.0, 58.0, -6.0, 2.0, 40.0};

double seconds_per_load(const std::vector<Pose>& poses, const WaveField& wave, std::vector<double>& heave_forces) {
  heave_forces.clear();
  const auto start = std::chrono::steady_clock::now();
  for (const Pose& p : poses) {
    heave_forces.push_back(ffrf::sea::hull_pressure_load(hull, &wave, 1025.0, 9.81, Eigen::Vector2d(0.0, 1.91 + p.heave), p.pitch, p.t).force.y());
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / static_cast<double>(poses.size());
}

}  // namespace

int main() {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> heave(-1.0, 1.0), pitch(-0.026, 0.026), time(100.0, 10000.0);
  std::vector<Pose> poses(64);
  for (Pose& p : poses) p = {heave(random), pitch(random), time(random)};
  fmt::print("per hull evaluation (4 edges, mean of {} poses) [ms]; crossings: the search alone; load: the whole "
             "hull pressure integral\n", poses.size());
  fmt::print("{:>8} {:>6} | {:>9} {:>9} {:>9} {:>6} | {:>9} {:>9} {:>6}\n", "record", "comps", "global", "direct",
             "recur.", "ratio", "direct", "recur.", "ratio");
  const auto search_with = [](const WaveField& wave) {
    return [&wave](double t, const Eigen::Vector2d& a, const Eigen::Vector2d& d) {
      return ffrf::sea::waterline_crossings(wave, t, a, d);
    };
  };
  int status = 0;
  for (const double record : {1200.0, 3600.0, 10800.0}) {
    const WaveField wave = ffrf::test_support::jonswap_test_sea(record, std::numeric_limits<double>::infinity(), 1);
    const WaveField direct = wave.with_direct_sums();
    if (!wave.harmonic_grid().active) {
      fmt::print("the synthesized sea is not recognised as a harmonic grid\n");
      status = 1;
    }
    long global_count = 0, direct_count = 0, recurrence_count = 0;
    const double global_time = seconds_per_hull(poses, [&](double t, const Eigen::Vector2d& a, const Eigen::Vector2d& d) {
      return ffrf::test_support::waterline_crossings_global_bounds(wave, t, a, d);
    }, global_count);
    const double direct_time = seconds_per_hull(poses, search_with(direct), direct_count);
    const double recurrence_time = seconds_per_hull(poses, search_with(wave), recurrence_count);
    std::vector<double> direct_forces, recurrence_forces;
    const double direct_load = seconds_per_load(poses, direct, direct_forces);
    const double recurrence_load = seconds_per_load(poses, wave, recurrence_forces);
    double worst = 0.0;
    for (std::size_t i = 0; i < poses.size(); ++i) worst = std::max(worst, std::abs(direct_forces[i] - recurrence_forces[i]));
    worst /= 1025.0 * 9.81 * 40.0 * 90.0 * 8.0;  // the box's full buoyancy
    fmt::print("{:>6.0f} s {:>6} | {:>9.3f} {:>9.3f} {:>9.3f} {:>6.1f} | {:>9.3f} {:>9.3f} {:>6.1f}   (heave force "
               "direct − recurrence: {:.1e} of the buoyancy)\n", record, wave.components().size(), 1e3 * global_time,
               1e3 * direct_time, 1e3 * recurrence_time, direct_time / recurrence_time, 1e3 * direct_load,
               1e3 * recurrence_load, direct_load / recurrence_load, worst);
    if (global_count != direct_count || direct_count != recurrence_count || !(worst <= 1e-10)) {
      fmt::print("MISMATCH: {} / {} / {} crossings (global / direct / recurrence), forces {:.1e}\n", global_count,
                 direct_count, recurrence_count, worst);
      status = 1;
    }
  }
  return status;
}
