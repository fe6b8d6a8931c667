// A sea spectrum laid over the RAOs (`ffrf rao --spectrum`, or the scene's irregular sea): the
// response spectrum of a linear output is S_Y(ω) = |Y(ω)|² S(ω), and its significant value (the
// significant wave height's analogue, 4 √m0 of the response) is
//   Y_s = 4 √(∫ |Y(ω)|² S(ω) dω),
// by the trapezoid rule over the model's frequencies (the requested grid with the refinement's
// points at the resonance peaks), so only the part of the sea inside the grid's band counts: the
// share of the spectrum's m0 inside it is stated beside the values.
#pragma once

#include <complex>
#include <vector>

#include "hydro/wave_spectrum.hpp"

namespace ffrf::study {

struct SeaWeighting {
  hydro::WaveSpectrum spectrum;
  double m0 = 0.0;       // ∫₀^∞ S dω [m²]
  double band_m0 = 0.0;  // ∫ S dω over the frequencies' band [m²]
  double band_share() const { return m0 > 0.0 ? band_m0 / m0 : 0.0; }
};

// The spectrum's m0 and its part in [low, high] [rad/s].
SeaWeighting sea_weighting(const hydro::WaveSpectrum& spectrum, double low, double high);

// 4 √(∫ |Y|² S dω) by the trapezoid rule over the frequencies (any order; sorted here) [unit of Y × m].
double significant_response(const std::vector<double>& angular_frequencies, const std::vector<std::complex<double>>& response,
                            const hydro::WaveSpectrum& spectrum);

}  // namespace ffrf::study
