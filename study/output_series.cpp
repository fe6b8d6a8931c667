// The crane run's output table and its statistics (see output_series.hpp).
#include "study/output_series.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "study/error_measure.hpp"

namespace ffrf::study {
namespace {

using multibody::CraneOutputs;

}  // namespace

std::span<const SeriesSpec> crane_series() { return multibody::output_channels(); }

std::size_t series_index(std::string_view column) {
  const std::span<const SeriesSpec> series = crane_series();
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (series[i].column == column) return i;
  }
  throw std::out_of_range("no output column " + std::string(column));
}

double series_value(const SeriesSpec& spec, const CraneOutputs& sample, const CraneOutputs& statics) {
  return spec.about_static ? spec.value(sample) - spec.value(statics) : spec.value(sample);
}

double series_reference(const SeriesSpec& spec, const CraneOutputs& statics) {
  return spec.about_static ? 0.0 : spec.value(statics);
}

StatsWindow stats_window(const scene::Scene& scene, const std::vector<double>& time) {
  StatsWindow window;
  if ((!scene.wave && !scene.sea) || time.empty()) return window;
  window.ramp_end_s = ramp_end(scene);
  const auto first = std::upper_bound(time.begin(), time.end(), ramp_end(scene));
  if (first == time.end()) return window;  // the run ends before the ramp does
  window.first = static_cast<std::size_t>(first - time.begin());
  window.start_s = *first;
  window.after_ramp = true;
  return window;
}

std::vector<SeriesStats> series_stats(const std::vector<CraneOutputs>& samples, const CraneOutputs& statics,
                                      const StatsWindow& window) {
  std::vector<SeriesStats> stats;
  for (const SeriesSpec& spec : crane_series()) {
    SeriesStats s;
    s.static_value = series_reference(spec, statics);
    s.min = INFINITY;
    s.max = -INFINITY;
    double sum = 0.0, sum_squares = 0.0;
    for (std::size_t i = window.first; i < samples.size(); ++i) {
      const double v = series_value(spec, samples[i], statics);
      s.min = std::min(s.min, v);
      s.max = std::max(s.max, v);
      sum += v;
      sum_squares += (v - s.static_value) * (v - s.static_value);
    }
    const std::size_t count = samples.size() - std::min(window.first, samples.size());
    s.rms = count > 0 ? std::sqrt(sum_squares / static_cast<double>(count)) : NAN;
    s.mean = count > 0 ? sum / static_cast<double>(count) : NAN;
    // Second pass about the mean (no cancellation of a large static part, e.g. the wire tension).
    double sum_deviations = 0.0;
    for (std::size_t i = window.first; i < samples.size(); ++i) {
      const double d = series_value(spec, samples[i], statics) - s.mean;
      sum_deviations += d * d;
    }
    s.standard_deviation = count > 0 ? std::sqrt(sum_deviations / static_cast<double>(count)) : NAN;
    stats.push_back(s);
  }
  return stats;
}

}  // namespace ffrf::study
