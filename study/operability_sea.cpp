// The sea of an operability cell: steepness, band, components and repetition (see operability_sea.hpp).
#include "study/operability_sea.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hydro/wave_synthesis.hpp"

namespace ffrf::study {

CellSea cell_sea(const hydro::WaveSpectrum& spectrum, double gravity, double record_length, double ramp, int components,
                 double variance_share) {
  CellSea sea;
  sea.steepness = hydro::sea_steepness(spectrum.significant_height, spectrum.peak_period, gravity);
  sea.band = hydro::variance_band(spectrum, variance_share);
  const double lo = sea.band.lower, hi = sea.band.upper;
  const double m0 = hydro::spectral_moment(spectrum, 0);
  const double m0_band = hydro::spectral_moment(spectrum, 0, lo, hi);
  sea.variance_share = m0_band / m0;
  sea.zero_crossing_period = 2.0 * std::numbers::pi * std::sqrt(m0_band / hydro::spectral_moment(spectrum, 2, lo, hi));
  // The component grid of the synthesis itself (hydro::synthesize), so that the count and the repeat
  // period are the records' own.
  hydro::SynthesisOptions options;
  options.record_length = record_length;
  options.omega_min = lo;
  options.omega_max = hi;
  if (components > 0) options.frequency_step = (hi - lo) / components;
  const hydro::SeaRealisation realisation = hydro::synthesize(spectrum, options);
  sea.frequency_step = realisation.components.frequency_step;
  sea.components = realisation.components.size();
  sea.repeat_period = realisation.repeat_period;
  sea.record_repeats = record_length / sea.repeat_period;
  sea.independent_wave_cycles = std::min(sea.repeat_period, std::max(record_length - ramp, 0.0)) / sea.zero_crossing_period;
  return sea;
}

std::string not_physical_reason(double significant_height, double peak_period, const hydro::SeaSteepness& steepness) {
  return fmt::format("Hs = {:g} m at Tp = {:g} s is steeper than a sea can be: Hs/λp = {:.3g} exceeds DNV-RP-C205's "
                     "breaking limit {:.4g} (λp = {:.4g} m; at this Tp Hs ≤ {:.3g} m)",
                     significant_height, peak_period, steepness.steepness, steepness.limit, steepness.peak_wavelength,
                     steepness.largest_height());
}

}  // namespace ffrf::study
