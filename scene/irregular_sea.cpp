// A scene's waves as components and as the coupling wave field; a scene put into a sea state (see
// irregular_sea.hpp).
#include "scene/irregular_sea.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "scene/scene_checks.hpp"
#include "scene/scene_key.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_schema.hpp"

namespace ffrf::scene {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kTailFraction = 1e-3;  // of m0 left outside the automatic band (the schema's help says 0.1 %)

double direction_sign(hydro::WaveHeading heading) { return heading == hydro::WaveHeading::following ? 1.0 : -1.0; }
}  // namespace

hydro::WaveSpectrum sea_spectrum(const IrregularSea& sea) {
  if (sea.spectrum == SeaSpectrum::pierson_moskowitz) return hydro::pierson_moskowitz(sea.significant_height, sea.peak_period);
  if (sea.spectrum == SeaSpectrum::jonswap) {
    return hydro::jonswap(sea.significant_height, sea.peak_period, sea.peak_enhancement,
                          hydro::JonswapNormalisation::exact, sea.sigma_below, sea.sigma_above);
  }
  throw std::logic_error("sea_spectrum: a components sea has no parametric spectrum");
}

hydro::SynthesisOptions synthesis_options(const IrregularSea& sea, double record_length) {
  hydro::SynthesisOptions options;
  options.record_length = record_length;
  options.tail_fraction = kTailFraction;
  options.seed = sea.seed;
  options.random_amplitudes = sea.random_amplitudes;
  options.heading = sea.heading;
  options.omega_min = sea.frequency_min;
  options.omega_max = sea.frequency_max;
  if (sea.component_count > 0) {
    if (options.omega_min == 0.0 && options.omega_max == 0.0) {
      const hydro::FrequencyBand band = hydro::energy_band(sea_spectrum(sea), kTailFraction);
      options.omega_min = band.lower;
      options.omega_max = band.upper;
    }
    options.frequency_step = (options.omega_max - options.omega_min) / sea.component_count;
  }
  return options;
}

hydro::WaveComponents sea_components(const Scene& scene) {
  if (scene.wave) {
    const Wave& wave = *scene.wave;
    const hydro::WaveHeading heading = wave.direction;
    if (wave.height <= 0.0) return hydro::WaveComponents{{}, {}, {}, heading, 0.0};
    return hydro::user_components({kTwoPi / wave.period}, {0.5 * wave.height}, {0.0}, heading);
  }
  if (!scene.sea) return {};
  const IrregularSea& sea = *scene.sea;
  if (sea.spectrum == SeaSpectrum::components) {
    return hydro::user_components(sea.component_frequencies, sea.component_amplitudes, sea.component_phases, sea.heading);
  }
  return hydro::synthesize(sea_spectrum(sea), synthesis_options(sea, scene.simulation.duration)).components;
}

std::optional<sea::WaveField> scene_wave_field(const Scene& scene) {
  if (!scene.wave && !scene.sea) return std::nullopt;
  const hydro::WaveComponents components = sea_components(scene);
  const double direction = direction_sign(components.heading);
  std::vector<sea::ComponentSpec> specs;
  specs.reserve(components.size());
  for (std::size_t n = 0; n < components.size(); ++n) {
    specs.push_back({components.frequency[n], components.amplitude[n], -direction * components.phase[n]});
  }
  if (scene.wave) {
    // The regular wave exactly as before: one component, ramp over ramp_periods · T.
    return sea::WaveField::regular(scene.wave->height, scene.wave->period, direction, scene.wave->ramp_periods,
                                        scene.environment.water_depth, scene.environment.gravity);
  }
  return sea::WaveField::from_components(specs, direction, wave_ramp_duration(scene), scene.environment.water_depth,
                                              scene.environment.gravity);
}

double characteristic_wave_period(const Scene& scene) {
  if (scene.wave) return scene.wave->period;
  if (!scene.sea) return 0.0;
  const IrregularSea& sea = *scene.sea;
  if (sea.spectrum != SeaSpectrum::components) return sea.peak_period;
  const auto largest = std::max_element(sea.component_amplitudes.begin(), sea.component_amplitudes.end());
  return kTwoPi / sea.component_frequencies[static_cast<std::size_t>(largest - sea.component_amplitudes.begin())];
}

double wave_ramp_duration(const Scene& scene) {
  if (scene.wave) return scene.wave->ramp_periods * scene.wave->period;
  if (!scene.sea) return 0.0;
  const IrregularSea& sea = *scene.sea;
  if (sea.spectrum != SeaSpectrum::components) return sea.ramp_periods * sea.peak_period;
  const double lowest = *std::min_element(sea.component_frequencies.begin(), sea.component_frequencies.end());
  return sea.ramp_periods * kTwoPi / lowest;
}

double wave_amplitude_bound(const Scene& scene) {
  if (scene.wave) return 0.5 * scene.wave->height;
  if (!scene.sea) return 0.0;
  const hydro::WaveComponents components = sea_components(scene);
  double sum = 0.0;
  for (double a : components.amplitude) sum += a;
  return sum;
}

double shortest_wave_period(const Scene& scene) {
  if (scene.wave) return scene.wave->period;
  if (!scene.sea) return 0.0;
  const hydro::WaveComponents components = sea_components(scene);
  if (components.size() == 0) return 0.0;
  return kTwoPi / *std::max_element(components.frequency.begin(), components.frequency.end());
}

bool has_waves(const Scene& scene) { return (scene.wave && scene.wave->height > 0.0) || scene.sea.has_value(); }

Scene in_irregular_sea(const Scene& base, const IrregularSeaState& state) {
  std::vector<SceneProblem> problems;
  const auto check = [&](std::string_view key, double value) {
    const KeySpec& spec = key_spec(key);
    if (!std::isfinite(value) || !accepts(spec, value)) {
      problems.push_back({base.file, 0, 0, std::string(key), fmt::format("{:g}", value),
                          fmt::format("out of range (valid range {})", format_range(spec))});
    }
  };
  IrregularSea sea = base.sea && base.sea->spectrum != SeaSpectrum::components ? *base.sea : IrregularSea{};
  if (state.spectrum == "jonswap") {
    sea.spectrum = SeaSpectrum::jonswap;
    check(scene_key("wave.peak_enhancement"), state.peak_enhancement);
  } else if (state.spectrum == "pierson-moskowitz") {
    sea.spectrum = SeaSpectrum::pierson_moskowitz;
  } else {
    problems.push_back({base.file, 0, 0, scene_key("wave.spectrum"), fmt::format("\"{}\"", state.spectrum),
                        "unknown sea-state spectrum; choose one of jonswap, pierson-moskowitz"});
  }
  check(scene_key("wave.significant_height"), state.significant_height);
  check(scene_key("wave.peak_period"), state.peak_period);
  check(scene_key("simulation.duration"), state.duration);
  if (state.seed > 2147483647u) check(scene_key("wave.seed"), static_cast<double>(state.seed));
  if (!problems.empty()) throw SceneError(std::move(problems));
  sea.significant_height = state.significant_height;
  sea.peak_period = state.peak_period;
  sea.peak_enhancement = sea.spectrum == SeaSpectrum::jonswap ? state.peak_enhancement : 1.0;
  sea.heading = state.heading;
  sea.seed = state.seed;
  Scene scene = base;
  scene.wave.reset();
  scene.sea = sea;
  scene.simulation.duration = state.duration;
  scene.warnings.clear();  // the checks below find the base's warnings again
  for (SceneFinding& finding : physics_findings(scene)) {
    const std::string& key = finding.keys.front();
    const std::string value = key == scene_key("wave.significant_height") ? fmt::format("{:g}", state.significant_height)
                              : key == scene_key("wave.peak_period")      ? fmt::format("{:g}", state.peak_period)
                              : key == scene_key("simulation.duration")   ? fmt::format("{:g}", state.duration)
                                                               : std::string();
    SceneProblem problem{base.file, 0, 0, key, value, std::move(finding.message)};
    if (finding.error) {
      problems.push_back(std::move(problem));
    } else {
      scene.warnings.push_back(format_problem(problem));
    }
  }
  if (!problems.empty()) throw SceneError(std::move(problems));
  return scene;
}

}  // namespace ffrf::scene
