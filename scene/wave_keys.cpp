// The [wave] section of a scene file (see wave_keys.hpp).
#include "scene/wave_keys.hpp"

#include <fmt/format.h>

#include "scene/scene_schema.hpp"

namespace ffrf::scene {

void check_wave_keys(WrittenKeys& keys, int wave_line) {
  const std::string& spectrum = keys.text("wave.spectrum");
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
  for (const char* key : {"wave.height", "wave.period"}) regular ? need(key) : refuse(key, "\"regular\"");
  for (const char* key : {"wave.significant_height", "wave.peak_period"}) {
    parametric ? need(key) : refuse(key, "\"jonswap\" or \"pierson-moskowitz\"");
  }
  if (spectrum != "jonswap") {
    for (const char* key : {"wave.peak_enhancement", "wave.sigma_below", "wave.sigma_above"})
      refuse(key, "\"jonswap\"");
  }
  for (const char* key : {"wave.component_frequencies", "wave.component_amplitudes", "wave.component_phases"}) {
    components ? need(key) : refuse(key, "\"components\"");
  }
  if (!parametric) {
    for (const char* key :
         {"wave.seed", "wave.components", "wave.frequency_min", "wave.frequency_max", "wave.amplitudes"}) {
      refuse(key, "\"jonswap\" or \"pierson-moskowitz\"");
    }
  }
  if (components && keys.has("wave.component_frequencies") && keys.has("wave.component_amplitudes") &&
      keys.has("wave.component_phases")) {
    const std::size_t count = keys.list("wave.component_frequencies").size();
    for (const char* key : {"wave.component_amplitudes", "wave.component_phases"}) {
      if (keys.list(key).size() != count) {
        keys.report(keys.line(key), key, keys.shown(key),
                    fmt::format("{} values for {} component frequencies (valid: one per frequency)",
                                keys.list(key).size(), count));
      }
    }
  }
  if (parametric && keys.has("wave.frequency_min") && keys.has("wave.frequency_max") &&
      !(keys.number("wave.frequency_max") > keys.number("wave.frequency_min"))) {
    keys.report(keys.line("wave.frequency_max"), "wave.frequency_max", keys.shown("wave.frequency_max"),
                fmt::format("not above wave.frequency_min = {:g} rad/s (valid range ({:g}, 100] rad/s)",
                            keys.number("wave.frequency_min"), keys.number("wave.frequency_min")));
  }
  if (parametric && keys.has("wave.frequency_min") != keys.has("wave.frequency_max")) {
    const char* given = keys.has("wave.frequency_min") ? "wave.frequency_min" : "wave.frequency_max";
    keys.report(keys.line(given), given, keys.shown(given),
                "give both wave.frequency_min and wave.frequency_max (a band), or neither (the energy band)");
  }
}

void build_wave(const WrittenKeys& keys, Scene& scene) {
  const std::string& spectrum = keys.text("wave.spectrum");
  const bool head = keys.text("wave.direction") == "head";
  if (spectrum == "regular") {
    scene.wave = Wave{keys.number("wave.height"), keys.number("wave.period"),
                      head ? hydro::WaveHeading::head : hydro::WaveHeading::following, keys.number("wave.ramp_periods")};
    return;
  }
  IrregularSea sea;
  sea.spectrum = spectrum == "jonswap"             ? SeaSpectrum::jonswap
                 : spectrum == "pierson-moskowitz" ? SeaSpectrum::pierson_moskowitz
                                                   : SeaSpectrum::components;
  sea.heading = head ? hydro::WaveHeading::head : hydro::WaveHeading::following;
  sea.ramp_periods = keys.number("wave.ramp_periods");
  sea.kinematics = keys.text("wave.kinematics") == "exact" ? WaveKinematics::exact : WaveKinematics::precomputed;
  sea.kinematics_tolerance = keys.number("wave.kinematics_tolerance");
  sea.kinematics_range = {keys.number("wave.kinematics_surge_range"), keys.number("wave.kinematics_heave_range"),
                          keys.number("wave.kinematics_pitch_range")};
  if (sea.spectrum == SeaSpectrum::components) {
    sea.component_frequencies = keys.list("wave.component_frequencies");
    sea.component_amplitudes = keys.list("wave.component_amplitudes");
    sea.component_phases = keys.list("wave.component_phases");
  } else {
    sea.significant_height = keys.number("wave.significant_height");
    sea.peak_period = keys.number("wave.peak_period");
    sea.peak_enhancement = sea.spectrum == SeaSpectrum::jonswap ? keys.number("wave.peak_enhancement") : 1.0;
    sea.sigma_below = keys.number("wave.sigma_below");
    sea.sigma_above = keys.number("wave.sigma_above");
    sea.seed = static_cast<std::uint64_t>(keys.number("wave.seed"));
    sea.component_count = static_cast<int>(keys.number("wave.components"));
    if (keys.has("wave.frequency_min")) sea.frequency_min = keys.number("wave.frequency_min");
    if (keys.has("wave.frequency_max")) sea.frequency_max = keys.number("wave.frequency_max");
    sea.random_amplitudes = keys.text("wave.amplitudes") == "rayleigh";
  }
  scene.sea = std::move(sea);
}

}  // namespace ffrf::scene
