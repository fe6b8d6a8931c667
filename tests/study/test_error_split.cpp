// Static and dynamic error (study/error_split.hpp) against a constructed pair of series with a known
// static offset and a known dynamic difference: reference x_ref = R_s + A sin ωt, model
// x = X_s + A sin ωt + δ cos ωt over whole periods. By hand: S = A/√2, static error |X_s − R_s|/S,
// dynamic error RMS(δ cos ωt)/S = δ/A, largest dynamic difference δ; the total error of
// multibody::compare_runs (computed there, not here) is √(static² + dynamic²) because mean(δ cos ωt)
// = 0; the chart's difference series (dynamic_difference) is δ cos ωt and its RMS over S is the
// dynamic error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "multibody/error_metrics.hpp"
#include "study/error_split.hpp"
#include "study/output_series.hpp"

namespace {

using namespace ffrf;

constexpr double amplitude = 0.6, delta = 0.015, model_static = -2.10, reference_static = -3.16;
constexpr double omega = 2.0 * std::numbers::pi / 10.0;  // 10 s period
constexpr double window = 19.99, duration = 120.0, interval = 0.05;  // the window starts at the sample t = 20 s

struct Pair {
  std::vector<double> time, model, reference;
};

Pair constructed_pair() {
  Pair p;
  // Samples at t = 0, 0.05, ... 120 s; the window t ≥ 20 s holds 10 whole periods (2000 samples: the
  // last sample, t = 120 s, repeats t = 20 s's phase, so leave it off).
  for (int i = 0; i * interval < duration - 1e-9; ++i) {
    const double t = i * interval;
    p.time.push_back(t);
    p.model.push_back(model_static + amplitude * std::sin(omega * t) + delta * std::cos(omega * t));
    p.reference.push_back(reference_static + amplitude * std::sin(omega * t));
  }
  return p;
}

TEST(ErrorSplit, KnownOffsetAndKnownDynamicDifference) {
  const Pair p = constructed_pair();
  const study::SplitError e = study::split_error(p.time, p.model, model_static, p.reference, reference_static, window);
  const double scale = amplitude / std::sqrt(2.0);
  EXPECT_NEAR(e.scale, scale, 1e-12);
  EXPECT_NEAR(e.static_offset, model_static - reference_static, 1e-15);
  EXPECT_NEAR(e.static_error, std::abs(model_static - reference_static) / scale, 1e-12);
  EXPECT_NEAR(e.dynamic_error, delta / amplitude, 1e-12);
  EXPECT_NEAR(e.dynamic_max, delta, 1e-12);
}

TEST(ErrorSplit, TotalErrorOfCompareRunsIsTheHypotenuseAndTheChartDifferenceIsTheDynamicError) {
  const Pair p = constructed_pair();
  // The same series as the cargo heave of two runs (absolute positions), statics at their offsets.
  study::ModelRun model, reference;
  model.statics.outputs.cargo.y() = model_static;
  reference.statics.outputs.cargo.y() = reference_static;
  for (std::size_t i = 0; i < p.time.size(); ++i) {
    multibody::CraneOutputs m, r;
    m.cargo.y() = p.model[i];
    r.cargo.y() = p.reference[i];
    model.result.time.push_back(p.time[i]);
    model.result.samples.push_back(m);
    reference.result.time.push_back(p.time[i]);
    reference.result.samples.push_back(r);
  }
  const auto heave = static_cast<std::size_t>(multibody::OutputChannel::cargo_heave);
  const study::SplitError split = study::split_errors(model, reference, window)[heave];
  const double total = multibody::compare_runs(model.result, reference.result, window)[multibody::OutputChannel::cargo_heave]
                           .normalized_rms;
  EXPECT_NEAR(total, std::hypot(split.static_error, split.dynamic_error), 1e-9 * total);
  EXPECT_LE(total, split.static_error + split.dynamic_error);
  // The difference panel's series: d − d_ref = δ cos ωt, whose RMS over the window / S is the dynamic error.
  const study::SeriesSpec& spec = study::crane_series()[study::series_index("cargo_heave_m")];
  const std::vector<double> difference = study::dynamic_difference(model, reference, spec);
  double squares = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < p.time.size(); ++i) {
    EXPECT_NEAR(difference[i], delta * std::cos(omega * p.time[i]), 1e-12);
    if (p.time[i] < window) continue;
    squares += difference[i] * difference[i];
    ++count;
  }
  EXPECT_NEAR(std::sqrt(squares / static_cast<double>(count)) / split.scale, split.dynamic_error, 1e-12);
}

TEST(ErrorSplit, MismatchedSeriesOrAnEmptyWindowAreRefused) {
  const Pair p = constructed_pair();
  std::vector<double> short_model(p.model.begin(), p.model.end() - 1);
  EXPECT_THROW(study::split_error(p.time, short_model, 0.0, p.reference, 0.0, window), std::invalid_argument);
  EXPECT_THROW(study::split_error(p.time, p.model, 0.0, p.reference, 0.0, duration + 1.0), std::invalid_argument);
}

}  // namespace
