// Failure detectors (see run_monitor.hpp).
#include "multibody/run_monitor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "multibody/crane_run.hpp"

namespace ffrf::multibody {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, a, b, c, d);
  return text;
}

// Least-squares slope of y over x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double denominator = n * sxx - sx * sx;
  return denominator > 0.0 ? (n * sxy - sx * sy) / denominator : 0.0;
}

// The lowest point of a box (half extents) centred at `centre` [m] and turned by `angle` [rad].
double lowest_point(const Eigen::Vector2d& centre, double angle, double half_length, double half_height) {
  return centre.y() - half_length * std::abs(std::sin(angle)) - half_height * std::abs(std::cos(angle));
}

// Capsize: the hull pitched past 90° (fatal: nothing the model describes follows).
void watch_capsize(const char* solver, double t, const CraneOutputs& sample) {
  constexpr double kDegree = 3.14159265358979323846 / 180.0;
  const double pitch = sample.hull.z();
  if (std::abs(pitch) >= 90.0 * kDegree) {
    throw SolverFailure(FailureKind::capsize, solver, format("the hull pitched to %.4g deg: it capsized", pitch / kDegree),
                        t,
                        "the crane is not stable under this load and sea: lower the load or the boom, enlarge the hull, "
                        "or reduce the wave",
                        pitch / kDegree);
  }
}

// How far a sample's deck edges (the deeper one; > 0: under water) and the cargo's lowest corner
// lie below the lowest wave trough −ζ_a (certainly wet there).
double deck_immersion(const WaterLimits& water, const CraneOutputs& sample, bool& bow) {
  const double pitch = sample.hull.z();
  double deepest = -std::numeric_limits<double>::infinity();
  for (const double x : {water.hull_stern_x, water.hull_bow_x}) {
    const double deck_y = sample.hull.y() + std::sin(pitch) * x + std::cos(pitch) * water.hull_deck_y;
    if (-water.wave_amplitude - deck_y > deepest) {
      deepest = -water.wave_amplitude - deck_y;
      bow = x > 0.0;
    }
  }
  return deepest;
}
double cargo_immersion(const WaterLimits& water, const CraneOutputs& sample) {
  return -water.wave_amplitude - lowest_point(sample.cargo.head<2>(), sample.cargo.z(), water.cargo_half_length,
                                              water.cargo_half_height);
}

// The post-run water detections: the first time a deck edge, and the cargo, went under water.
void water_detections(const RunResult& result, const WaterLimits& water, std::vector<Detection>& found) {
  double deck_first = -1.0, deck_deepest = 0.0, cargo_first = -1.0, cargo_deepest = 0.0;
  bool bow = true;
  for (std::size_t k = 0; k < result.samples.size(); ++k) {
    bool at_bow = true;
    const double deck = deck_immersion(water, result.samples[k], at_bow);
    if (deck > 0.0) {
      if (deck_first < 0.0) {
        deck_first = result.time[k];
        bow = at_bow;
      }
      deck_deepest = std::max(deck_deepest, deck);
    }
    if (water.cargo_half_length > 0.0) {
      const double cargo = cargo_immersion(water, result.samples[k]);
      if (cargo > 0.0) {
        if (cargo_first < 0.0) cargo_first = result.time[k];
        cargo_deepest = std::max(cargo_deepest, cargo);
      }
    }
  }
  if (deck_first >= 0.0) {
    found.push_back({FailureKind::deck_submerged, deck_first, false,
                     std::string(bow ? "the bow" : "the stern") +
                         format(" deck edge went under water at t = %.4g s, at most %.3g m below the lowest wave trough: "
                                "the box hull model has no water on deck or flooding, so the motions from then on are "
                                "outside the model",
                                deck_first, deck_deepest),
                     "lighten the load or shorten the outreach, enlarge the hull's depth, or reduce the wave",
                     deck_deepest});
  }
  if (cargo_first >= 0.0) {
    found.push_back({FailureKind::cargo_in_water, cargo_first, false,
                     format("the cargo dipped into the water at t = %.4g s, at most %.3g m below the lowest wave "
                            "trough: the model has no water forces on the cargo",
                            cargo_first, cargo_deepest),
                     "shorten the wire, raise the boom, or reduce the crane's motion", cargo_deepest});
  }
}

// The cargo turned past the limit about its hook: the first sample beyond it and the largest |pitch|.
void cargo_pitch_detection(const RunResult& result, double limit, std::vector<Detection>& found) {
  constexpr double kDegree = 3.14159265358979323846 / 180.0;
  double first = -1.0, largest = 0.0;
  for (std::size_t k = 0; k < result.samples.size(); ++k) {
    const double pitch = std::abs(result.samples[k].cargo.z());
    if (pitch > limit && first < 0.0) first = result.time[k];
    largest = std::max(largest, pitch);
  }
  if (first < 0.0) return;
  found.push_back({FailureKind::cargo_overturned, first, false,
                   format("the cargo pitched past %.0f deg about its hook at t = %.4g s (largest |pitch| %.0f deg",
                          limit / kDegree, first, largest / kDegree) +
                       (largest > std::acos(-1.0) ? ", over the top of the hook" : "") +
                       "): it hangs from a frictionless pin with a lightly damped rocking mode and no slings or tag "
                       "lines, so the record from then on is not a lift to plan with",
                   std::string(remedy(FailureKind::cargo_overturned)), largest});
}

}  // namespace

void DivergenceWatch::observe(double t, const CraneOutputs& sample) {
  const double deflection = sample.tip_deflection.norm();
  if (!std::isfinite(deflection) || !sample.cargo.allFinite() || !sample.hull.allFinite()) {
    throw SolverFailure(FailureKind::divergence, solver_, "the state is no longer finite", t,
                        "reduce the step or tighten the tolerances; check the scene's stiffness and mass values");
  }
  if (limits_.water.floating) watch_capsize(solver_, t, sample);
  if (limits_.boom_length <= 0.0) return;
  const double bound = limits_.deflection_limit * limits_.boom_length;
  // The window opens when |δ| first passes 10 % of the bound and closes only on a real decay below
  // 1 %, so the dips of a growing oscillation stay in it. Its record highs (samples above all before
  // them) are the envelope: the peaks of a growing oscillation, every sample of a monotone one.
  if (deflection < 0.01 * bound) {
    times_.clear();
    log_deflections_.clear();
    return;
  }
  if (times_.empty() && deflection < 0.1 * bound) return;
  if (log_deflections_.empty() || std::log(deflection) > log_deflections_.back()) {
    times_.push_back(t);
    log_deflections_.push_back(std::log(deflection));
  }
  if (deflection <= bound) return;
  double rate = std::numeric_limits<double>::quiet_NaN();  // unresolved: jumped past the bound at once
  if (times_.size() >= 3) {
    rate = slope(times_, log_deflections_);
  } else if (times_.size() == 2 && times_.back() > times_.front()) {
    rate = (log_deflections_.back() - log_deflections_.front()) / (times_.back() - times_.front());
  }
  char cause[320];
  if (std::isfinite(rate)) {
    std::snprintf(cause, sizeof cause,
                  "the boom tip deflection %.3g m passed the bound %.3g m (%.3g of the boom length), growing at "
                  "σ = %.3g 1/s (e-folding time %.3g s)",
                  deflection, bound, limits_.deflection_limit, rate, 1.0 / std::max(rate, 1e-300));
  } else {
    std::snprintf(cause, sizeof cause,
                  "the boom tip deflection %.3g m passed the bound %.3g m (%.3g of the boom length) within one output "
                  "interval: growth rate unresolved",
                  deflection, bound, limits_.deflection_limit);
  }
  throw SolverFailure(FailureKind::divergence, solver_, cause, t,
                      "the linear floating-frame boom lost its stiffness: switch on geometric stiffening "
                      "(centrifugal for a spinning boom, static near buckling), or lower the spin rate or load",
                      rate);
}

std::vector<SlackInterval> slack_intervals(const RunResult& result, const MonitorLimits& limits) {
  std::vector<SlackInterval> intervals;
  if (limits.wire_unstretched_length <= 0.0 || result.samples.empty()) return intervals;
  if (result.samples.front().wire_length <= limits.wire_unstretched_length) intervals.push_back({0.0});
  for (const WireEvent& event : result.wire_events) {
    if (event.slack) {
      if (intervals.empty() || std::isfinite(intervals.back().end)) intervals.push_back({event.time});
    } else if (!intervals.empty() && !std::isfinite(intervals.back().end)) {
      intervals.back().end = event.time;
    }
  }
  return intervals;
}

std::vector<SnapLoad> snap_loads(const RunResult& result, const MonitorLimits& limits) {
  std::vector<SnapLoad> snaps;
  const std::vector<SlackInterval> slack = slack_intervals(result, limits);
  for (std::size_t i = 0; i < slack.size(); ++i) {
    if (!std::isfinite(slack[i].end)) break;
    const double until = i + 1 < slack.size() ? slack[i + 1].start : std::numeric_limits<double>::infinity();
    SnapLoad snap;
    snap.time = slack[i].end;
    for (std::size_t k = 0; k < result.time.size(); ++k) {
      if (result.time[k] < snap.time || result.time[k] > until) continue;
      if (result.samples[k].wire_tension > snap.peak_tension) {
        snap.peak_tension = result.samples[k].wire_tension;
        snap.peak_time = result.time[k];
      }
    }
    snap.ratio = limits.static_tension > 0.0 ? snap.peak_tension / limits.static_tension : 0.0;
    if (limits.static_tension > 0.0 && !(snap.peak_tension > limits.snap_load_factor * limits.static_tension)) continue;
    snaps.push_back(snap);
  }
  return snaps;
}

double max_constraint_drift(const RunResult& result) {
  double drift = 0.0;
  for (const CraneOutputs& sample : result.samples) drift = std::max(drift, std::abs(sample.constraint_residual));
  return drift;
}

double max_buckling_load_ratio(const RunResult& result, const MonitorLimits& limits) {
  if (!std::isfinite(limits.buckling_load)) return 0.0;
  double compression = 0.0;
  for (const CraneOutputs& sample : result.samples) compression = std::max(compression, -sample.root_axial_force);
  return compression / limits.buckling_load;
}

// Each supporting wire that went slack (a luffing wire: the boom then hung on its heel pin alone; a
// backstay: the A-frame on its deck pin): when first, how often.
static void support_detections(const RunResult& result, const std::vector<WireEvent>& events, FailureKind kind,
                               const char* consequence, std::vector<Detection>& found) {
  for (std::size_t wire = 0; wire < result.wire_names.size(); ++wire) {
    int count = 0;
    double first = 0.0;
    for (const WireEvent& event : events) {
      if (event.wire != static_cast<int>(wire) || !event.slack) continue;
      if (count++ == 0) first = event.time;
    }
    if (count == 0) continue;
    found.push_back({kind, first, false,
                     fmt::format("the {} went slack {} times (first at t = {:.4g} s): {}", result.wire_names[wire], count, first,
                                 consequence),
                     std::string(solve::remedy(kind)), static_cast<double>(count)});
  }
}

std::vector<Detection> post_run_detections(const RunResult& result, const MonitorLimits& limits) {
  std::vector<Detection> found;
  const std::vector<SlackInterval> slack = slack_intervals(result, limits);
  if (!slack.empty()) {
    double total = 0.0;
    for (const SlackInterval& s : slack) total += std::min(s.end, result.time.back()) - s.start;
    found.push_back({FailureKind::wire_slack, slack.front().start, false,
                     format("the wire went slack %.0f times, %.3g s in all (first at t = %.4g s)",
                            static_cast<double>(slack.size()), total, slack.front().start),
                     "the cargo lost its support: expect snap loads; reduce the wave or the crane motion, or lower the "
                     "cargo's excursion (hoisting, a stiffer/longer wire)",
                     total});
  }
  support_detections(result, result.luffing_events, FailureKind::luffing_slack, "the boom swung on its heel pin", found);
  support_detections(result, result.backstay_events, FailureKind::backstay_slack, "the A-frame swung on its deck pin", found);
  for (const SnapLoad& snap : snap_loads(result, limits)) {
    found.push_back({FailureKind::snap_load, snap.time, false,
                     format("the wire snapped taut at t = %.4g s: peak tension %.4g N at t = %.4g s (%.3g x the static tension)",
                            snap.time, snap.peak_tension, snap.peak_time, snap.ratio),
                     "check the wire and boom against the peak; the sampled peak is resolved to the output interval",
                     snap.peak_tension});
  }
  const double drift = max_constraint_drift(result);
  if (drift > limits.constraint_drift_limit) {
    double when = 0.0;
    for (std::size_t k = 0; k < result.samples.size(); ++k) {
      if (std::abs(result.samples[k].constraint_residual) > limits.constraint_drift_limit) {
        when = result.time[k];
        break;
      }
    }
    found.push_back({FailureKind::constraint_drift, when, false,
                     format("the clamp residual |C| reached %.3g m (bound %.3g m)", drift, limits.constraint_drift_limit),
                     std::string(remedy(FailureKind::constraint_drift)),
                     drift});
  }
  const double ratio = max_buckling_load_ratio(result, limits);
  if (ratio >= limits.buckling_warning_ratio) {
    std::size_t largest = 0;  // the sample of the largest compression
    for (std::size_t k = 1; k < result.samples.size(); ++k) {
      if (result.samples[k].root_axial_force < result.samples[largest].root_axial_force) largest = k;
    }
    found.push_back({FailureKind::buckling, result.time.empty() ? 0.0 : result.time[largest], false,
                     format("the boom's root compression reached %.3g of its Euler buckling load %.4g N", ratio,
                            limits.buckling_load),
                     ratio >= 1.0 ? "the boom buckles: the linear model is invalid; reduce the load"
                                  : "switch on geometric stiffening (static) so the bending stiffness "
                                    "loss under compression is modelled",
                     ratio});
  }
  if (limits.water.floating) water_detections(result, limits.water, found);
  cargo_pitch_detection(result, limits.cargo_pitch_limit, found);
  const SolverStats& stats = result.stats;
  if (stats.steps > 10 && static_cast<double>(stats.error_test_failures) > limits.error_test_failure_ratio * static_cast<double>(stats.steps)) {
    found.push_back({FailureKind::error_test_failures, result.time.empty() ? 0.0 : result.time.back(), false,
                     format("%.0f error-test failures in %.0f steps", static_cast<double>(stats.error_test_failures),
                            static_cast<double>(stats.steps)),
                     std::string(remedy(FailureKind::error_test_failures)), 0.0});
  }
  return found;
}

}  // namespace ffrf::multibody
