// Statistics of an irregular record (docs/hydrodynamics.md §5): zero up-crossing analysis about the
// record's mean (a wave is the record between two successive up-crossings, crossing times by
// linear interpolation; its height is max − min within it, its crest max − mean), the significant
// value H1/3 (mean of the highest third of the wave heights), the spectral significant value
// 4 sqrt(m0) = 4σ (Hm0: equal to H1/3 for a narrow-band Gaussian record within 0.1 %,
// Longuet-Higgins 1952: H1/3 = 4.004 σ), the mean zero up-crossing period Tz, and the peaks
// (crests) that feed the extreme-value estimates (extreme_values.hpp).
#pragma once

#include <cstddef>
#include <vector>

namespace ffrf::hydro {

struct RecordStatistics {
  double mean = 0.0;
  double standard_deviation = 0.0;  // σ (about the mean)
  double significant_from_variance = 0.0;  // 4σ
  double significant_height = 0.0;  // H1/3 from the zero up-crossing waves
  double maximum_height = 0.0;      // largest wave height
  double maximum = 0.0, minimum = 0.0;  // of the record
  double mean_period = 0.0;         // Tz: (last − first up-crossing) / waves
  std::size_t waves = 0;            // complete zero up-crossing waves
  std::vector<double> heights;      // per wave
  std::vector<double> crests;       // per wave: max − mean (the peaks)
};

// Throws std::invalid_argument when dt ≤ 0, a sample is not finite (index named) or the record has
// fewer than 3 samples. A record with fewer than 2 up-crossings has waves = 0 and zero heights.
RecordStatistics record_statistics(const std::vector<double>& record, double dt);

}  // namespace ffrf::hydro
