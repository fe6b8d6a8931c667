// The static and the dynamic error of an output against the reference (see error_split.hpp).
#include "study/error_split.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ffrf::study {

SplitError split_error(const std::vector<double>& time, const std::vector<double>& x, double x_static,
                       const std::vector<double>& reference, double reference_static, double window_start) {
  if (x.size() != time.size() || reference.size() != time.size()) {
    throw std::invalid_argument("split_error: the series are not sampled at the same times (" + std::to_string(x.size()) +
                                " and " + std::to_string(reference.size()) + " samples at " + std::to_string(time.size()) +
                                " times)");
  }
  double mean = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < window_start) continue;
    mean += reference[i];
    ++count;
  }
  if (count == 0) throw std::invalid_argument("split_error: the window after t = " + std::to_string(window_start) + " s is empty");
  mean /= static_cast<double>(count);
  double signal = 0.0, dynamic = 0.0;
  SplitError e;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] < window_start) continue;
    const double difference = (x[i] - x_static) - (reference[i] - reference_static);
    signal += (reference[i] - mean) * (reference[i] - mean);
    dynamic += difference * difference;
    e.dynamic_max = std::max(e.dynamic_max, std::abs(difference));
  }
  e.scale = std::sqrt(signal / static_cast<double>(count));
  const double normalizer = e.scale > 0.0 ? e.scale : 1.0;
  e.static_offset = x_static - reference_static;
  e.static_error = std::abs(e.static_offset) / normalizer;
  e.dynamic_error = std::sqrt(dynamic / static_cast<double>(count)) / normalizer;
  return e;
}

namespace {

template <class Value>
std::vector<double> sampled(const multibody::RunResult& run, Value value) {
  std::vector<double> series;
  series.reserve(run.samples.size());
  for (const multibody::CraneOutputs& sample : run.samples) series.push_back(value(sample));
  return series;
}

}  // namespace

SplitErrors split_errors(const ModelRun& run, const ModelRun& reference, double window_start) {
  SplitErrors errors;
  for (std::size_t c = 0; c < multibody::all_channels.size(); ++c) {
    const multibody::OutputChannel channel = multibody::all_channels[c];
    const auto value = [channel](const multibody::CraneOutputs& o) { return multibody::channel_value(o, channel); };
    errors[c] = split_error(reference.result.time, sampled(run.result, value), value(run.static_outputs()),
                            sampled(reference.result, value), value(reference.static_outputs()), window_start);
  }
  return errors;
}

std::vector<double> dynamic_difference(const ModelRun& run, const ModelRun& reference, const SeriesSpec& spec) {
  if (run.result.samples.size() != reference.result.samples.size()) {
    throw std::invalid_argument("dynamic_difference: the runs are not sampled at the same times");
  }
  const double x_static = spec.value(run.static_outputs());
  const double reference_static = spec.value(reference.static_outputs());
  std::vector<double> difference;
  difference.reserve(run.result.samples.size());
  for (std::size_t i = 0; i < run.result.samples.size(); ++i) {
    difference.push_back((spec.value(run.result.samples[i]) - x_static) -
                         (spec.value(reference.result.samples[i]) - reference_static));
  }
  return difference;
}

}  // namespace ffrf::study
