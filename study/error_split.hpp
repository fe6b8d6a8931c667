// The static and the dynamic error of a model's output against the reference's, so a verdict can say which part is off.
// An output of a run is x(t) = x_s + d(t): the value at the model's own static equilibrium x_s and
// the displacement d(t) from it; the reference's is x_ref(t) = x_ref_s + d_ref(t). With the scale
// S = RMS(x_ref − mean x_ref) over the error window (the reference's dynamic amplitude, the
// normalization of multibody/error_metrics.hpp):
//  * static error  = |x_s − x_ref_s| / S: how far the model's equilibrium is off (the static table);
//  * dynamic error = RMS(d − d_ref) / S over the window: how far its motion about its own
//    equilibrium is off — the difference the charts' difference panels draw (dynamic_difference);
//  * total error   = RMS(x − x_ref) / S (multibody::compare_runs): the two together, which the
//    verdict judges — a design reads absolute positions and loads, so an equilibrium that is off
//    counts as much as a motion that is off. With e = d − d_ref and Δ = x_s − x_ref_s,
//    total² = (Δ² + 2 Δ mean(e) + RMS(e)²) / S², so total ≤ static + dynamic.
// An output that does not move in the reference (S = 0) is not normalized (its errors are in the
// output's unit), as compare_runs does.
#pragma once

#include <array>
#include <vector>

#include "multibody/error_metrics.hpp"
#include "study/output_series.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {

struct SplitError {
  double static_offset = 0.0;  // x_s − x_ref_s [output unit]
  double static_error = 0.0;   // |static_offset| / S
  double dynamic_error = 0.0;  // RMS(d − d_ref) / S over the window
  double dynamic_max = 0.0;    // max |d − d_ref| over the window [output unit]
  double scale = 0.0;          // S [output unit]
};

// One output sampled at the same times in both runs (the window: time >= window_start). Throws
// std::invalid_argument when the series differ in length or the window is empty.
SplitError split_error(const std::vector<double>& time, const std::vector<double>& x, double x_static,
                       const std::vector<double>& reference, double reference_static, double window_start);

// Every error channel of multibody/error_metrics.hpp (in all_channels order; pitch in rad), x_s from
// each run's static equilibrium.
using SplitErrors = std::array<SplitError, multibody::all_channels.size()>;
SplitErrors split_errors(const ModelRun& run, const ModelRun& reference, double window_start);

// d(t) − d_ref(t) of one time-series column (output_series.hpp; its unit, pitch in degrees) at
// every sample: what the difference panel of a chart draws, and what the dynamic error measures.
std::vector<double> dynamic_difference(const ModelRun& run, const ModelRun& reference, const SeriesSpec& spec);

}  // namespace ffrf::study
