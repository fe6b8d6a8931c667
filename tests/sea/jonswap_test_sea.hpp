// The reference crane's sea (cases/irregular_sea_crane.toml) for tests and benchmarks: JONSWAP
// Hs 2 m, Tp 8 s, γ 3.3 (σa 0.07, σb 0.09), synthesized by the library (hydro::synthesize: ω_n = n Δω,
// Δω = 2π / record, over [ωp/2, 3ωp], deterministic amplitudes, random phases from `seed`),
// following (+x), without ramp, as the coupling wave field, built the way scene/irregular_sea.cpp
// builds it (phase −δ φ_n: the hydro convention is cos(ω t − δ k x + φ)). A 20-minute record has 376
// components, 1 hour 1 126, 3 hours 3 376.
#pragma once

#include <cstdint>
#include <numbers>
#include <vector>

#include "sea/wave_field.hpp"
#include "hydro/wave_spectrum.hpp"
#include "hydro/wave_synthesis.hpp"

namespace ffrf::test_support {

inline sea::WaveField jonswap_test_sea(double record, double depth, std::uint64_t seed) {
  const double peak_frequency = 2.0 * std::numbers::pi / 8.0;
  hydro::SynthesisOptions options;
  options.record_length = record;
  options.omega_min = 0.5 * peak_frequency;
  options.omega_max = 3.0 * peak_frequency;
  options.seed = seed;
  const hydro::WaveComponents sea = hydro::synthesize(hydro::jonswap(2.0, 8.0, 3.3), options).components;
  std::vector<sea::ComponentSpec> specs;
  for (std::size_t n = 0; n < sea.size(); ++n) specs.push_back({sea.frequency[n], sea.amplitude[n], -sea.phase[n]});
  return sea::WaveField::from_components(specs, 1.0, 0.0, depth, 9.81);
}

}  // namespace ffrf::test_support
