// A scene's incident sea recorded once per record for its box hull, shared through a cache of weak
// references (see recorded_sea.hpp).
#include "scene/recorded_sea.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "scene/scene_key.hpp"
#include "sea/hull_pressure_recorded.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf::scene {

namespace {

// Everything the record depends on, as bits: the components, the hull section and pose, the settings.
std::vector<std::uint64_t> record_key(const sea::WaveField& wave, const sea::BoxHullSection& section,
                                      double g1_height, const IrregularSea& sea, double duration) {
  std::vector<std::uint64_t> key;
  const auto add = [&](double v) { key.push_back(std::bit_cast<std::uint64_t>(v)); };
  for (const sea::WaveComponent& c : wave.components()) {
    add(c.amplitude);
    add(c.angular_frequency);
    add(c.phase);
  }
  for (const double v : {wave.direction(), wave.gravity(), section.aft_x, section.fore_x, section.keel_y, section.deck_y,
                         section.width, g1_height, sea.kinematics_tolerance, sea.kinematics_range.surge,
                         sea.kinematics_range.heave, sea.kinematics_range.pitch, duration})
    add(v);
  return key;
}

std::mutex cache_mutex;
std::map<std::vector<std::uint64_t>, std::weak_ptr<const sea::IncidentWaveRecord>> cache;

}  // namespace

WaveKinematicsChoice wave_kinematics_choice(const Scene& scene) {
  WaveKinematicsChoice choice;
  if (!scene.sea) {
    choice.reason = scene.wave ? "a regular wave: one component" : "calm water";
  } else if (scene.sea->kinematics == WaveKinematics::exact) {
    choice.reason = "wave.kinematics = \"exact\"";
  } else if (!scene.hull) {
    choice.reason = "no floating hull";
  } else if (scene.bem && scene.bem->excitation == ExcitationModel::bem) {
    choice.reason = "the BEM excitation carries the incident wave (its history recorded once); the hull pressure is "
                    "hydrostatic";
  } else if (std::isfinite(scene.environment.water_depth)) {
    choice.reason = "finite water depth (the record holds deep-water kinematics)";
  } else {
    choice.method = "precomputed";
  }
  return choice;
}

std::shared_ptr<const sea::IncidentWaveRecord> recorded_sea(const Scene& scene, const multibody::HullModel& hull,
                                                                 const sea::WaveField& wave, WaveKinematicsChoice* choice) {
  WaveKinematicsChoice chosen = wave_kinematics_choice(scene);
  const auto give = [&](std::shared_ptr<const sea::IncidentWaveRecord> record) {
    if (choice) *choice = chosen;
    return record;
  };
  if (chosen.method != "precomputed" || !hull.hydrostatics || hull.bem_excitation) {
    if (chosen.method == "precomputed") chosen = {"exact", "the hull pressure is not integrated in the wave"};
    return give(nullptr);
  }
  const IrregularSea& sea = *scene.sea;
  const double g1_height = hull.support_pose(1);
  const double duration = scene.simulation.duration;
  const std::vector<std::uint64_t> key = record_key(wave, hull.section, g1_height, sea, duration);
  {
    const std::lock_guard<std::mutex> lock(cache_mutex);
    if (auto found = cache[key].lock()) return give(found);
  }
  const sea::HullMotionRange range{sea.kinematics_range.surge, sea.kinematics_range.heave, sea.kinematics_range.pitch};
  sea::IncidentWaveRecordOptions options;
  options.duration = duration;
  options.tolerance = sea.kinematics_tolerance;
  sea::box_hull_x_range(hull.section, g1_height, range, options.x_min, options.x_max);
  std::string why;
  std::optional<sea::IncidentWaveRecord> built;
  try {
    built = sea::IncidentWaveRecord::build(wave, sea::box_hull_patches(hull.section, g1_height, range), options, &why);
  } catch (const std::length_error& e) {
    throw SceneError({SceneProblem{scene.file, 0, 0, scene_key("wave.kinematics"), "\"precomputed\"",
                                   fmt::format("the recorded sea would not fit in memory ({}); use wave.kinematics = "
                                               "\"exact\", a looser wave.kinematics_tolerance, smaller "
                                               "wave.kinematics_*_range or a shorter simulation.duration",
                                               e.what())}});
  } catch (const std::invalid_argument& e) {
    throw SceneError({SceneProblem{scene.file, 0, 0, scene_key("wave.kinematics"), "\"precomputed\"", e.what()}});
  }
  if (!built) {
    chosen = {"exact", why};
    return give(nullptr);
  }
  auto record = std::make_shared<const sea::IncidentWaveRecord>(std::move(*built));
  {
    const std::lock_guard<std::mutex> lock(cache_mutex);
    for (auto it = cache.begin(); it != cache.end();) it = it->second.expired() ? cache.erase(it) : std::next(it);
    cache[key] = record;
  }
  return give(record);
}

}  // namespace ffrf::scene
