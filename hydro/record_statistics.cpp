// Zero up-crossing statistics of a record (see record_statistics.hpp).
#include "hydro/record_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace ffrf::hydro {

RecordStatistics record_statistics(const std::vector<double>& record, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument(fmt::format("record statistics: time step {} s; valid range > 0", dt));
  if (record.size() < 3) throw std::invalid_argument(fmt::format("record statistics: {} samples; valid: at least 3", record.size()));
  RecordStatistics s;
  for (std::size_t i = 0; i < record.size(); ++i) {
    if (!std::isfinite(record[i])) throw std::invalid_argument(fmt::format("record statistics: sample {} is {}; valid: finite", i, record[i]));
    s.mean += record[i];
  }
  s.mean /= static_cast<double>(record.size());
  double sum_sq = 0.0;
  for (double v : record) sum_sq += (v - s.mean) * (v - s.mean);
  s.standard_deviation = std::sqrt(sum_sq / static_cast<double>(record.size()));
  s.significant_from_variance = 4.0 * s.standard_deviation;
  s.maximum = *std::max_element(record.begin(), record.end());
  s.minimum = *std::min_element(record.begin(), record.end());

  std::vector<std::size_t> up;  // index i: the crossing lies in (i − 1, i]
  std::vector<double> up_time;
  for (std::size_t i = 1; i < record.size(); ++i) {
    const double a = record[i - 1] - s.mean, b = record[i] - s.mean;
    if (a < 0.0 && b >= 0.0) {
      up.push_back(i);
      up_time.push_back(dt * (static_cast<double>(i - 1) + (-a) / (b - a)));
    }
  }
  if (up.size() < 2) return s;
  for (std::size_t w = 0; w + 1 < up.size(); ++w) {
    const auto first = record.begin() + static_cast<std::ptrdiff_t>(up[w]), last = record.begin() + static_cast<std::ptrdiff_t>(up[w + 1]);
    const double high = *std::max_element(first, last), low = *std::min_element(first, last);
    s.heights.push_back(high - low);
    s.crests.push_back(high - s.mean);
  }
  s.waves = s.heights.size();
  s.mean_period = (up_time.back() - up_time.front()) / static_cast<double>(s.waves);
  std::vector<double> sorted = s.heights;
  std::sort(sorted.begin(), sorted.end(), std::greater<>());
  const std::size_t third = std::max<std::size_t>(1, sorted.size() / 3);
  double top = 0.0;
  for (std::size_t i = 0; i < third; ++i) top += sorted[i];
  s.significant_height = top / static_cast<double>(third);
  s.maximum_height = sorted.front();
  return s;
}

}  // namespace ffrf::hydro
