// Statistics of irregular-sea runs and their comparison with a reference (see irregular_statistics.hpp).
#include "study/irregular_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "hydro/record_statistics.hpp"
#include "hydro/wave_synthesis.hpp"
#include "scene/irregular_sea.hpp"
#include "study/output_series.hpp"

namespace ffrf::study {

namespace {

constexpr std::size_t kMinimumSamples = 32;

std::vector<double> column_record(std::string_view column, const std::vector<multibody::CraneOutputs>& samples,
                                  const multibody::CraneOutputs& statics, std::size_t first) {
  const SeriesSpec& spec = crane_series()[series_index(column)];
  std::vector<double> record;
  record.reserve(samples.size() - first);
  for (std::size_t i = first; i < samples.size(); ++i) record.push_back(series_value(spec, samples[i], statics));
  return record;
}

ResponseStatistics response_statistics(std::string_view column, std::string_view unit, const std::vector<double>& record,
                                       double dt, std::string& note) {
  ResponseStatistics r;
  r.column = column;
  r.unit = unit;
  const hydro::RecordStatistics stats = hydro::record_statistics(record, dt);
  r.mean = stats.mean;
  r.standard_deviation = stats.standard_deviation;
  r.significant = stats.significant_from_variance;
  r.zero_crossing_period = stats.mean_period;
  r.observed_maximum = stats.maximum;
  if (stats.standard_deviation > 0.0) {
    r.spectrum = hydro::welch_spectrum(record, dt);
    r.peak_frequency = hydro::peak_frequency(r.spectrum);
    // A record too short for segments that resolve its own zero-crossing frequency has no peak.
    if (!(stats.mean_period > 0.0) || r.spectrum.resolution > 0.25 * 2.0 * std::numbers::pi / stats.mean_period) {
      r.peak_frequency = std::numeric_limits<double>::quiet_NaN();
    }
    try {
      const hydro::ExtremeEstimates extremes = hydro::most_probable_maxima(record, dt);
      r.rayleigh = stats.mean + extremes.rayleigh;
      r.weibull = stats.mean + extremes.weibull;
      r.gumbel = stats.mean + extremes.gumbel;
      r.weibull_shape = extremes.weibull_fit.shape;
      r.extremes = true;
    } catch (const std::invalid_argument& error) {
      note = std::string("most probable maxima need a longer record: ") + error.what();
    }
  }
  return r;
}

}  // namespace

std::vector<std::string_view> statistics_columns() {
  std::vector<std::string_view> columns;
  for (const SeriesSpec& spec : crane_series())
    if (spec.judged) columns.push_back(spec.column);
  return columns;
}

std::optional<IrregularStatistics> irregular_statistics(const scene::Scene& scene, const std::vector<double>& time,
                                                        const std::vector<multibody::CraneOutputs>& samples,
                                                        const multibody::CraneOutputs& statics, std::size_t first,
                                                        double dt) {
  if (!scene.sea || !scene.is_crane() || samples.size() < first + kMinimumSamples || !(dt > 0.0)) return std::nullopt;
  IrregularStatistics out;
  out.window_start = time[first];
  out.record_length = time.back() - time[first];
  out.ramp_end = scene::wave_ramp_duration(scene);
  out.after_ramp = time[first] >= out.ramp_end;
  out.sample_interval = dt;
  const hydro::WaveComponents sea = scene::sea_components(scene);
  if (sea.size() > 0) {
    out.band_lower = *std::min_element(sea.frequency.begin(), sea.frequency.end());
    out.band_upper = *std::max_element(sea.frequency.begin(), sea.frequency.end());
  }
  out.components = sea.size();
  out.band_share = 1.0;
  if (scene.sea->spectrum != scene::SeaSpectrum::components) {
    const hydro::SeaRealisation realisation =
        hydro::synthesize(scene::sea_spectrum(*scene.sea), scene::synthesis_options(*scene.sea, scene.simulation.duration));
    out.band_share = realisation.band_m0 / realisation.spectrum_m0;
  }
  const std::vector<double> eta = hydro::elevation_record(sea, time[first], dt, samples.size() - first);
  out.elevation = response_statistics("wave_elevation_m", "m", eta, dt, out.note);
  for (std::string_view column : statistics_columns()) {
    const SeriesSpec& spec = crane_series()[series_index(column)];
    out.responses.push_back(response_statistics(column, spec.unit, column_record(column, samples, statics, first), dt, out.note));
  }
  if (statics.wire_tension > 0.0) {
    const std::vector<double> tension = column_record("wire_tension_N", samples, statics, first);
    out.wire = hydro::tension_amplification(tension, dt, statics.wire_tension);
  }
  return out;
}

std::optional<IrregularErrors> irregular_errors(const scene::Scene& scene, const std::vector<multibody::CraneOutputs>& run,
                                                const multibody::CraneOutputs& run_statics,
                                                const std::vector<multibody::CraneOutputs>& reference,
                                                const multibody::CraneOutputs& reference_statics, std::size_t first,
                                                double dt) {
  const std::size_t count = std::min(run.size(), reference.size());
  if (!scene.sea || !scene.is_crane() || count < first + kMinimumSamples || !(dt > 0.0)) return std::nullopt;
  IrregularErrors out;
  for (std::string_view column : statistics_columns()) {
    std::vector<double> x = column_record(column, run, run_statics, first);
    std::vector<double> y = column_record(column, reference, reference_statics, first);
    x.resize(count - first);
    y.resize(count - first);
    hydro::IrregularComparison c;
    try {
      c = hydro::compare_irregular(x, y, dt);
    } catch (const std::invalid_argument&) {
      c.sigma_error = std::numeric_limits<double>::quiet_NaN();  // a reference without variance: not comparable
      out.responses.push_back(c);
      continue;
    }
    out.worst_statistic = std::max(out.worst_statistic, c.worst_statistic());
    out.responses.push_back(c);
  }
  return out;
}

}  // namespace ffrf::study
