// Response spectra of the RAOs in a sea spectrum (study/rao_spectrum.hpp).
#include "study/rao_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace ffrf::study {

SeaWeighting sea_weighting(const hydro::WaveSpectrum& spectrum, double low, double high) {
  SeaWeighting weighting;
  weighting.spectrum = spectrum;
  weighting.m0 = hydro::spectral_moment(spectrum, 0);
  // A single frequency (or none) spans no band: none of the sea's variance lies inside it.
  weighting.band_m0 = high > low ? hydro::spectral_moment(spectrum, 0, low, high) : 0.0;
  return weighting;
}

double significant_response(const std::vector<double>& angular_frequencies, const std::vector<std::complex<double>>& response,
                            const hydro::WaveSpectrum& spectrum) {
  if (angular_frequencies.size() != response.size()) {
    throw std::invalid_argument("significant_response: one response per frequency is needed");
  }
  std::vector<std::size_t> order(angular_frequencies.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return angular_frequencies[a] < angular_frequencies[b]; });
  const auto density = [&](std::size_t i) { return std::norm(response[i]) * hydro::spectral_density(spectrum, angular_frequencies[i]); };
  double m0 = 0.0;
  for (std::size_t n = 1; n < order.size(); ++n) {
    m0 += 0.5 * (density(order[n - 1]) + density(order[n])) * (angular_frequencies[order[n]] - angular_frequencies[order[n - 1]]);
  }
  return 4.0 * std::sqrt(m0);
}

}  // namespace ffrf::study
