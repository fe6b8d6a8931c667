// What a record of the incident sea is and what it cost (sea/incident_wave_record.hpp): the
// figures a run states in its header and summary.json. Its own header so that the studies and
// reports that carry it do not depend on the record's machinery.
#pragma once

#include <cstddef>

namespace ffrf::sea {

// What the record is and what it cost: stated in the run header and summary.json.
struct IncidentWaveRecordStats {
  std::size_t patches = 0, degree = 0, channels = 0, samples = 0, components = 0;
  double time_step = 0.0;            // [s] of the Hermite segments
  double truncation_bound = 0.0;     // [m] Taylor remainder bound of F in a patch
  double interpolation_error = 0.0;  // [m] measured at segment midpoints (F units)
  double elevation_bound = 0.0;      // [m] |ζ| ≤ this over [x_min, x_max] × record, before the ramp
  double slope_bound = 0.0;          // [-] |∂ζ/∂x| ≤ this, likewise
  std::size_t line_degree = 0;       // D of the Chebyshev series along still water
  double line_truncation_bound = 0.0;  // [m]
  double bound_window = 0.0;         // [s] the bounds are also kept per window of this length
  double memory_bytes = 0.0;
  double build_seconds = 0.0;
};

}  // namespace ffrf::sea
