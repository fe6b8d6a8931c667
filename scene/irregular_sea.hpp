// The crane in an irregular sea (docs/hydrodynamics.md §2.2): a scene's [wave] becomes
// the coupling wave field. A regular wave is the one-component field; a JONSWAP or Pierson–Moskowitz
// sea is synthesized by hydro::synthesize with ω_n = n Δω, Δω = 2π / record length (or the band over
// wave.components), random phases from the seed (a pure function of seed and harmonic number n, so
// the same realisation on any thread or process count); user components are taken as given. The
// phase convention of hydro (η(0, t) = Σ a cos(ω t + φ)) maps onto the wave field's
// θ = k x − δ ω t + φ_field as φ_field = −δ φ (δ = +1 following, −1 head).
// Also: in_irregular_sea, the interface of the operability tables (docs/operability.md), and the sea's
// summary values that studies need (ramp end, amplitude bound, the shortest period of interest).
#pragma once

#include <cstdint>
#include <string>

#include "sea/wave_field.hpp"
#include "hydro/wave_synthesis.hpp"
#include "scene/scene.hpp"

namespace ffrf::scene {

// A sea state for tables and sweeps: a parametric spectrum and its record.
struct IrregularSeaState {
  std::string spectrum = "jonswap";  // "jonswap" | "pierson-moskowitz"
  double significant_height = 0;     // Hs [m]
  double peak_period = 0;            // Tp [s]
  double peak_enhancement = 3.3;     // γ (jonswap)
  hydro::WaveHeading heading = hydro::WaveHeading::following;
  std::uint64_t seed = 1;
  double duration = 0;  // s, record length
};

// The scene in that sea: [wave] replaced (σa, σb, band, component count, amplitudes and ramp kept
// when the base already has an irregular sea, else their defaults), simulation.duration set to the
// record length. Throws SceneError naming the scene file, the key (wave.significant_height, ...),
// the value and the valid range — the same ranges and physics checks (steepness, repeat period) as
// a scene file's; warnings go to the returned scene's warnings.
Scene in_irregular_sea(const Scene& base, const IrregularSeaState& sea);

// The spectrum of a parametric sea (std::invalid_argument from hydro for bad parameters).
hydro::WaveSpectrum sea_spectrum(const IrregularSea& sea);
// The synthesis options of a parametric sea over a record of `record_length` seconds.
hydro::SynthesisOptions synthesis_options(const IrregularSea& sea, double record_length);
// The components of the scene's sea (regular: one; spectra: synthesized over simulation.duration;
// components: as given), in hydro's convention. Empty for calm water.
hydro::WaveComponents sea_components(const Scene& scene);
// The wave field of the scene (calm water: none), with the scene's depth, gravity and ramp.
std::optional<sea::WaveField> scene_wave_field(const Scene& scene);

// Summary values of the scene's waves (0 in calm water).
double wave_ramp_duration(const Scene& scene);       // [s] end of the ramp-in
double wave_amplitude_bound(const Scene& scene);     // Σ a_n [m]: no elevation exceeds it
double characteristic_wave_period(const Scene& scene);  // T (regular), Tp (spectra), longest-energy period (components) [s]
double shortest_wave_period(const Scene& scene);     // 2π / highest component frequency [s]
bool has_waves(const Scene& scene);                  // a non-zero regular wave or an irregular sea

}  // namespace ffrf::scene
