// The frequency domain (`ffrf rao`, docs/theory.md §12): response amplitude operators of the crane
// linearised about its static equilibrium (multibody/linearisation.hpp) — the linearised time
// domain, the cheap second method that checks it. At each angular frequency ω
//   X(ω) = (−ω² (M + A'(ω)) + iω (C + B'(ω)) + K)⁻¹ F̂(ω),    Y(ω) = (G + iω H) X(ω),
// per metre of wave amplitude, phase relative to the elevation at x = 0 (ζ = a cos ωt; response
// Re(Y e^{iωt}) a: a positive phase leads the wave). A'(ω), B'(ω) are frequency-dependent hull
// terms added to the model's constant added mass and radiation damping, and F̂ may be replaced by a
// given excitation, through a provider (HullHydrodynamics): constant coefficients by default; a [bem]
// hull adds its impedance Z(iω) beyond the linearisation's constant part (study/rao_bem.hpp: the
// files' A(ω), B(ω), or the radiation model's kernel), its excitation is the .3 file's through the
// waved crane, and its natural modes are the memory hull's roots of det(s²M + sC + K + Z(s)). Natural frequencies and damping ratios of the coupled system from
// the eigenvalues λ of the first-order form of M ẍ + C ẋ + K x = 0: ω_n = |λ|, ζ = −Re λ / |λ|.
// Rigid, nodal and modal booms side by side (rao_models(scene)); with a request to, each model's grid refined around its resonance peaks
// (study/rao_peaks.hpp) and its significant responses in a sea spectrum (study/rao_spectrum.hpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "multibody/linearisation.hpp"
#include "modal/mode_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"
#include "study/natural_mode.hpp"
#include "study/rao_bem.hpp"
#include "study/rao_peaks.hpp"
#include "study/rao_spectrum.hpp"

namespace ffrf::study {

// Frequency-dependent hull terms at ω in the hull's (surge, heave, pitch) rows and columns at G1.
struct HullFrequencyTerms {
  Eigen::Matrix3d added_mass = Eigen::Matrix3d::Zero();  // added to the model's mass matrix [kg, kg m, kg m²]
  Eigen::Matrix3d damping = Eigen::Matrix3d::Zero();     // added to the model's damping matrix
  // Given: the wave excitation per metre of amplitude on the hull [N/m, N m/m], replacing the
  // model's own (derived from its hull pressure); empty: the model's.
  std::optional<Eigen::Vector3cd> excitation;
};
// ω [rad/s] → the hull's frequency-dependent terms. Empty function: the model's constant coefficients.
using HullHydrodynamics = std::function<HullFrequencyTerms(double angular_frequency)>;

// M, C, K: the natural modes, lowest first (one per complex pair; overdamped ones as real roots).
std::vector<NaturalMode> natural_modes(const multibody::LinearisedCrane& linear);
// With a hull impedance Z(s) (a memory hull, study/rao_bem.hpp): the roots of
// det(s²M + sC + K + Z(s)) = 0, each found by Newton's method on log det, s ← s − 1/tr(D⁻¹D′), from
// the constant system's eigenvalue (modes up to `refine_below` rad/s; faster ones, which the hull's
// frequency-dependent part barely moves, stay the constant system's), at most `max_newton_steps`
// steps each. A start that does not converge keeps the constant system's root and says why
// (NaturalMode::unrefined).
std::vector<NaturalMode> natural_modes(const multibody::LinearisedCrane& linear, const HullImpedance& impedance,
                                       double refine_below, int max_newton_steps = 40);

// X = (−ω²M + iωC + K)⁻¹ F by Eigen's complex LU; throws std::runtime_error when singular (at an
// undamped resonance).
Eigen::VectorXcd frequency_response(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& damping,
                                    const Eigen::MatrixXd& stiffness, const Eigen::VectorXcd& force,
                                    double angular_frequency);

// The natural modes of the crane of `choice` linearised about its static equilibrium in calm water.
// Throws as response_amplitude_operators().
std::vector<NaturalMode> coupled_natural_modes(const scene::Scene& scene, const scene::BoomChoice& choice,
                                               modal::ModeCache* modes = nullptr);

struct RaoRequest {
  std::vector<scene::BoomChoice> models;  // empty: rao_models(scene)
  std::vector<double> angular_frequencies;  // [rad/s], each > 0
  HullHydrodynamics hydrodynamics;        // empty: the constant coefficients of the scene, or its [bem] files
  // A [bem] scene without `hydrodynamics`: the hull's radiation from the files (the physical RAO) or as
  // the scene's radiation model realises it (the time domain's own; study/rao_bem.hpp).
  BemRadiationSource bem_radiation = BemRadiationSource::file;
  // false: a [bem] hull's natural modes are the constant system's (A_model, ∂μ/∂ẋ(0) only: wrong for a
  // memory hull; kept to show what the time-domain check's fit needs, docs/hydrodynamics.md §6.1).
  bool memory_natural_modes = true;
  double excitation_amplitude = 0.01;     // wave amplitude of the excitation's central difference [m]
  // Refine each model's grid around its resonance peaks (study/rao_peaks.hpp); false: the requested
  // frequencies only, in the order given.
  bool refine_peaks = false;
  PeakSearch peak_search;
  // A sea spectrum to weigh the RAOs with: each model's significant responses (study/rao_spectrum.hpp).
  std::optional<hydro::WaveSpectrum> sea_spectrum;
};

// The frequencies of `ffrf rao` and `ffrf.rao` when none are given: default_rao_period_count wave
// periods evenly from default_rao_shortest_period to default_rao_longest_period [s] (the heave and
// pitch resonances of a floating crane and the swell), and the range a requested one must lie in.
inline constexpr double default_rao_shortest_period = 3.0, default_rao_longest_period = 30.0;  // [s]
inline constexpr int default_rao_period_count = 109;
inline constexpr double max_rao_period = 1000.0;    // [s]
inline constexpr double max_rao_frequency = 100.0;  // [rad/s]
// `count` periods evenly from `shortest` to `longest` [s] as angular frequencies, longest period first.
std::vector<double> period_grid(double shortest, double longest, int count);
std::vector<double> default_rao_frequencies();  // period_grid of the defaults
// The angular frequencies of wave periods [s], in their order; throws SettingError (wave_periods) for
// none, or a period not in (0, max_rao_period].
std::vector<double> frequencies_of_periods(const std::vector<double>& periods);
// Throws SettingError (wave_frequencies) for none, or a frequency not in (0, max_rao_frequency] rad/s.
void validate_frequencies(const std::vector<double>& angular_frequencies);

// The front ends' defaults (`ffrf rao`, `ffrf.rao`): each model's grid refined around its resonance
// peaks, and the scene's own sea spectrum over the RAOs when it has a parametric irregular sea
// (JONSWAP or Pierson–Moskowitz; none for calm water, a regular wave or given components).
inline constexpr bool default_refine_peaks = true;
std::optional<hydro::WaveSpectrum> default_sea_spectrum(const scene::Scene& scene);

// rigid; nodal N; modal k = 2 + static modes on N, with N the scene's boom.elements (as `ffrf run`
// builds the boom unless told otherwise).
std::vector<scene::BoomChoice> rao_models(const scene::Scene& scene);

struct ModelRao {
  scene::BoomChoice choice;
  int coordinates = 0;  // minimal coordinates n
  std::vector<NaturalMode> modes;
  // The model's frequencies [rad/s]: the requested ones (in their order), or with refine_peaks the
  // requested ones and the refinement's, ascending.
  std::vector<double> angular_frequencies;
  // response[output][frequency index], per metre of wave amplitude (LinearOutput order)
  std::array<std::vector<std::complex<double>>, multibody::linear_output_count> response;
  std::vector<ResonancePeak> peaks;  // refine_peaks: each output's peak at each resonant mode in the band (output = LinearOutput)
  std::size_t added_frequencies = 0;  // refine_peaks: frequencies the refinement added
  // sea_spectrum: 4 √(∫ |Y(ω)|² S(ω) dω) per output over the model's frequencies (LinearOutput order)
  std::array<double, multibody::linear_output_count> significant_response{};
  double wall_seconds = 0.0;
};

struct RaoResult {
  std::vector<double> angular_frequencies;  // [rad/s], as requested (each model's own grid: ModelRao)
  double excitation_amplitude = 0.0;
  bool frequency_dependent_hydrodynamics = false;
  // [bem] scenes: where A(ω), B(ω) came from, and the time domain's radiation model (whose kernel gives
  // the natural modes).
  std::optional<BemRadiationSource> bem_radiation;
  std::string bem_radiation_model;  // "convolution", "state-space", "constant"; empty without [bem]
  std::string bem_radiation_file;   // the .1 file
  std::string bem_excitation_file;  // the .3 file when it owns the excitation (excitation = "bem"), else empty
  std::vector<ModelRao> models;
  std::optional<PeakSearch> peak_search;  // refine_peaks: the search's settings; empty: not refined
  std::optional<SeaWeighting> sea;  // sea_spectrum: the spectrum and its share inside the frequencies
};

// The scene must float a crane (hull) in water. Throws scene::SceneError (the scene cannot make
// the crane), solve::SolverFailure (static equilibrium), std::invalid_argument (no frequency, or
// one ≤ 0), std::runtime_error (a singular system at some ω). `progress` is told each model's label.
RaoResult response_amplitude_operators(const scene::Scene& scene, const RaoRequest& request,
                                       const std::function<void(const std::string&)>& progress = {},
                                       modal::ModeCache* modes = nullptr);

// The scene with a regular wave of this amplitude and ω (no ramp; the scene's direction, following
// when it has none): the wave the excitation is derived in, and the time-domain check runs in.
scene::Scene with_regular_wave(const scene::Scene& scene, double height, double period, double ramp_periods);

}  // namespace ffrf::study
