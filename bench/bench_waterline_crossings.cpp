// Benchmark of the waterline-crossing search (coupling/waterline_crossings.hpp) with local curvature
// bounds against the search with the wave field's global bounds it replaced
// (tests/coupling/waterline_crossings_global_bounds.hpp), side by side in one run, on the reference
// hull's four box edges (90 m × 8 m, loaded draft, random heave ±1 m and pitch ±1.5°) in JONSWAP seas
// Hs 2 m, Tp 8 s, γ 3.3 on Δω = 2π/record over [ωp/2, 3ωp] (cases/irregular_sea_crane.toml) for
// records of 20 minutes, 1 hour and 3 hours, and the whole hull pressure integral (which uses the new
// search) for scale. Prints the time per hull (four edges) and the ratio old/new; both searches must
// find the same number of crossings (checked, else exit 1).
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "../tests/coupling/waterline_crossings_global_bounds.hpp"
#include "coupling/hull_pressure.hpp"
#include "coupling/waterline_crossings.hpp"
#include "coupling/wave_field.hpp"

namespace {

using ffrf::coupling::ComponentSpec;
using ffrf::coupling::WaveField;

WaveField jonswap_sea(double record) {
  const double hs = 2.0, wp = 2.0 * std::numbers::pi / 8.0, dw = 2.0 * std::numbers::pi / record;
  std::vector<ComponentSpec> list;
  double variance = 0.0;
  for (int n = 1;; ++n) {
    const double w = n * dw;
    if (w < 0.5 * wp) continue;
    if (w > 3.0 * wp) break;
    const double sigma = w <= wp ? 0.07 : 0.09;
    const double shape = std::pow(w, -5.0) * std::exp(-1.25 * std::pow(wp / w, 4.0)) *
                         std::pow(3.3, std::exp(-(w - wp) * (w - wp) / (2.0 * sigma * sigma * wp * wp)));
    list.push_back({w, std::sqrt(2.0 * shape * dw), 0.0});
    variance += shape * dw;
  }
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  const double scale = std::sqrt(hs * hs / 16.0 / variance);
  for (ComponentSpec& c : list) {
    c.amplitude *= scale;
    c.phase = phase(random);
  }
  return WaveField::from_components(list, 1.0, 0.0, std::numeric_limits<double>::infinity(), 9.81);
}

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

}  // namespace

int main() {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> heave(-1.0, 1.0), pitch(-0.026, 0.026), time(100.0, 10000.0);
  std::vector<Pose> poses(64);
  for (Pose& p : poses) p = {heave(random), pitch(random), time(random)};
  const ffrf::coupling::BoxHullSection hull{-32.0, 58.0, -6.0, 2.0, 40.0};
  fmt::print("waterline crossings on the reference hull's 4 edges, per hull evaluation (mean of {} poses)\n", poses.size());
  fmt::print("{:>10} {:>11} {:>14} {:>14} {:>8} {:>16}\n", "record", "components", "global [ms]", "local [ms]",
             "ratio", "hull load [ms]");
  int status = 0;
  for (const double record : {1200.0, 3600.0, 10800.0}) {
    const WaveField wave = jonswap_sea(record);
    long old_count = 0, new_count = 0;
    const double old_time = seconds_per_hull(poses, [&](double t, const Eigen::Vector2d& a, const Eigen::Vector2d& d) {
      return ffrf::test_support::waterline_crossings_global_bounds(wave, t, a, d);
    }, old_count);
    const double new_time = seconds_per_hull(poses, [&](double t, const Eigen::Vector2d& a, const Eigen::Vector2d& d) {
      return ffrf::coupling::waterline_crossings(wave, t, a, d);
    }, new_count);
    const auto start = std::chrono::steady_clock::now();
    double sink = 0.0;
    for (const Pose& p : poses) {
      sink += ffrf::coupling::hull_pressure_load(hull, &wave, 1025.0, 9.81, Eigen::Vector2d(0.0, 1.91 + p.heave), p.pitch, p.t).force.y();
    }
    const double load_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / static_cast<double>(poses.size());
    fmt::print("{:>8.0f} s {:>11} {:>14.3f} {:>14.3f} {:>8.1f} {:>16.3f}\n", record, wave.components().size(),
               1e3 * old_time, 1e3 * new_time, old_time / new_time, 1e3 * load_time);
    if (old_count != new_count || !std::isfinite(sink)) {
      fmt::print("MISMATCH: {} crossings with global bounds, {} with local bounds\n", old_count, new_count);
      status = 1;
    }
  }
  return status;
}
