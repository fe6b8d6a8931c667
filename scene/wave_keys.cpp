// The [wave] section of a scene file (see wave_keys.hpp).
#include "scene/wave_keys.hpp"

#include <fmt/format.h>

#include "scene/scene_key.hpp"
#include "scene/scene_schema.hpp"

namespace ffrf::scene {

void check_wave_keys(WrittenKeys& keys, int wave_line) {
  const std::string& spectrum = keys.text(scene_key("wave.spectrum"));
  const auto need = [&](const char* key) {
    if (!keys.written(key)) {
      keys.report(wave_line, key, "",
                  fmt::format("missing key: wave.spectrum = \"{}\" needs it ({}; valid range {})", spectrum,
                              key_spec(key).help, format_range(key_spec(key))));
    }
  };
  const auto refuse = [&](const char* key, std::string_view owner) {
    if (keys.written(key)) {
      keys.report(
          keys.line(key), key, keys.shown(key),
          fmt::format("belongs to wave.spectrum = {}, not \"{}\"; remove it or change wave.spectrum", owner, spectrum));
    }
  };
  const bool regular = spectrum == "regular", components = spectrum == "components";
  const bool parametric = !regular && !components;
  for (const char* key : {scene_key("wave.height"), scene_key("wave.period")}) regular ? need(key) : refuse(key, "\"regular\"");
  for (const char* key : {scene_key("wave.significant_height"), scene_key("wave.peak_period")}) {
    parametric ? need(key) : refuse(key, "\"jonswap\" or \"pierson-moskowitz\"");
  }
  if (spectrum != "jonswap") {
    for (const char* key : {scene_key("wave.peak_enhancement"), scene_key("wave.sigma_below"), scene_key("wave.sigma_above")})
      refuse(key, "\"jonswap\"");
  }
  for (const char* key : {scene_key("wave.component_frequencies"), scene_key("wave.component_amplitudes"), scene_key("wave.component_phases")}) {
    components ? need(key) : refuse(key, "\"components\"");
  }
  if (!parametric) {
    for (const char* key :
         {scene_key("wave.seed"), scene_key("wave.components"), scene_key("wave.frequency_min"), scene_key("wave.frequency_max"), scene_key("wave.amplitudes")}) {
      refuse(key, "\"jonswap\" or \"pierson-moskowitz\"");
    }
  }
  if (components && keys.has(scene_key("wave.component_frequencies")) && keys.has(scene_key("wave.component_amplitudes")) &&
      keys.has(scene_key("wave.component_phases"))) {
    const std::size_t count = keys.list(scene_key("wave.component_frequencies")).size();
    for (const char* key : {scene_key("wave.component_amplitudes"), scene_key("wave.component_phases")}) {
      if (keys.list(key).size() != count) {
        keys.report(keys.line(key), key, keys.shown(key),
                    fmt::format("{} values for {} component frequencies (valid: one per frequency)",
                                keys.list(key).size(), count));
      }
    }
  }
  if (parametric && keys.has(scene_key("wave.frequency_min")) && keys.has(scene_key("wave.frequency_max")) &&
      !(keys.number(scene_key("wave.frequency_max")) > keys.number(scene_key("wave.frequency_min")))) {
    keys.report(keys.line(scene_key("wave.frequency_max")), scene_key("wave.frequency_max"), keys.shown(scene_key("wave.frequency_max")),
                fmt::format("not above wave.frequency_min = {:g} rad/s (valid range ({:g}, 100] rad/s)",
                            keys.number(scene_key("wave.frequency_min")), keys.number(scene_key("wave.frequency_min"))));
  }
  if (parametric && keys.has(scene_key("wave.frequency_min")) != keys.has(scene_key("wave.frequency_max"))) {
    const char* given = keys.has(scene_key("wave.frequency_min")) ? scene_key("wave.frequency_min") : scene_key("wave.frequency_max");
    keys.report(keys.line(given), given, keys.shown(given),
                "give both wave.frequency_min and wave.frequency_max (a band), or neither (the energy band)");
  }
}

void build_wave(const WrittenKeys& keys, Scene& scene) {
  const std::string& spectrum = keys.text(scene_key("wave.spectrum"));
  const bool head = keys.text(scene_key("wave.direction")) == "head";
  if (spectrum == "regular") {
    scene.wave = Wave{keys.number(scene_key("wave.height")), keys.number(scene_key("wave.period")),
                      head ? hydro::WaveHeading::head : hydro::WaveHeading::following, keys.number(scene_key("wave.ramp_periods"))};
    return;
  }
  IrregularSea sea;
  sea.spectrum = spectrum == "jonswap"             ? SeaSpectrum::jonswap
                 : spectrum == "pierson-moskowitz" ? SeaSpectrum::pierson_moskowitz
                                                   : SeaSpectrum::components;
  sea.heading = head ? hydro::WaveHeading::head : hydro::WaveHeading::following;
  sea.ramp_periods = keys.number(scene_key("wave.ramp_periods"));
  sea.kinematics = keys.text(scene_key("wave.kinematics")) == "exact" ? WaveKinematics::exact : WaveKinematics::precomputed;
  sea.kinematics_tolerance = keys.number(scene_key("wave.kinematics_tolerance"));
  sea.kinematics_range = {keys.number(scene_key("wave.kinematics_surge_range")), keys.number(scene_key("wave.kinematics_heave_range")),
                          keys.number(scene_key("wave.kinematics_pitch_range"))};
  if (sea.spectrum == SeaSpectrum::components) {
    sea.component_frequencies = keys.list(scene_key("wave.component_frequencies"));
    sea.component_amplitudes = keys.list(scene_key("wave.component_amplitudes"));
    sea.component_phases = keys.list(scene_key("wave.component_phases"));
  } else {
    sea.significant_height = keys.number(scene_key("wave.significant_height"));
    sea.peak_period = keys.number(scene_key("wave.peak_period"));
    sea.peak_enhancement = sea.spectrum == SeaSpectrum::jonswap ? keys.number(scene_key("wave.peak_enhancement")) : 1.0;
    sea.sigma_below = keys.number(scene_key("wave.sigma_below"));
    sea.sigma_above = keys.number(scene_key("wave.sigma_above"));
    sea.seed = static_cast<std::uint64_t>(keys.number(scene_key("wave.seed")));
    sea.component_count = static_cast<int>(keys.number(scene_key("wave.components")));
    if (keys.has(scene_key("wave.frequency_min"))) sea.frequency_min = keys.number(scene_key("wave.frequency_min"));
    if (keys.has(scene_key("wave.frequency_max"))) sea.frequency_max = keys.number(scene_key("wave.frequency_max"));
    sea.random_amplitudes = keys.text(scene_key("wave.amplitudes")) == "rayleigh";
  }
  scene.sea = std::move(sea);
}

}  // namespace ffrf::scene
