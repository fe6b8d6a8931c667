// Statistical and spectral comparison of irregular records (see irregular_comparison.hpp).
#include "hydro/irregular_comparison.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hydro/extreme_values.hpp"
#include "hydro/record_statistics.hpp"

namespace ffrf::hydro {

double IrregularComparison::worst_statistic() const {
  return std::max({std::abs(sigma_error), std::abs(most_probable_maximum_error), std::abs(m0_error), std::abs(m2_error),
                   std::abs(zero_crossing_period_error), std::abs(peak_frequency_error)});
}

IrregularComparison compare_irregular(const std::vector<double>& run, const std::vector<double>& reference, double dt,
                                      const WelchOptions& welch) {
  if (run.size() != reference.size())
    throw std::invalid_argument(fmt::format("irregular comparison: {} samples against the reference's {}; valid: the same times",
                                            run.size(), reference.size()));
  const RecordStatistics a = record_statistics(run, dt), b = record_statistics(reference, dt);
  if (!(b.standard_deviation > 0.0)) throw std::invalid_argument("irregular comparison: the reference record is constant");
  IrregularComparison c;
  double sum = 0.0;
  for (std::size_t i = 0; i < run.size(); ++i) sum += (run[i] - reference[i]) * (run[i] - reference[i]);
  c.time_history_nrms = std::sqrt(sum / static_cast<double>(run.size())) / b.standard_deviation;
  c.mean_error = (a.mean - b.mean) / b.standard_deviation;
  c.sigma_error = a.standard_deviation / b.standard_deviation - 1.0;
  const double cycles = std::max(1.0, static_cast<double>(b.waves));
  c.most_probable_maximum_error = rayleigh_most_probable_maximum(a.standard_deviation, std::max(1.0, static_cast<double>(a.waves))) /
                                      rayleigh_most_probable_maximum(b.standard_deviation, cycles) - 1.0;
  const PowerSpectrum sa = welch_spectrum(run, dt, welch), sb = welch_spectrum(reference, dt, welch);
  const double m0a = spectral_moment(sa, 0), m0b = spectral_moment(sb, 0), m2a = spectral_moment(sa, 2), m2b = spectral_moment(sb, 2);
  c.m0_error = m0a / m0b - 1.0;
  c.m2_error = m2a / m2b - 1.0;
  c.zero_crossing_period_error = std::sqrt((m0a / m2a) / (m0b / m2b)) - 1.0;
  c.peak_frequency_error = peak_frequency(sa) / peak_frequency(sb) - 1.0;
  double difference = 0.0;
  for (std::size_t k = 0; k < sa.density.size(); ++k) difference += std::abs(sa.density[k] - sb.density[k]) * sa.resolution;
  c.spectral_distance = difference / (m0b > 0.0 ? m0b : 1.0);
  return c;
}

}  // namespace ffrf::hydro
