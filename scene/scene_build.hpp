// The Scene value from a scene file's valid keys, once the loader (scene_loader.cpp) has checked
// every key and the keys across each other: the boom, the hull or the hub, cargo and wire, the
// environment, the wave or sea, radiation, [bem] (its files are read afterwards, bem_files.hpp),
// mooring and simulation.
#pragma once

#include <string>

#include "scene/scene.hpp"
#include "scene/wave_keys.hpp"

namespace ffrf::scene {

// The parts a scene file describes.
struct SceneParts {
  bool crane = false;  // a hull crane
  bool hub = false;    // a hub scene
  bool cargo = false;  // cargo and wire present
  bool wave = false;   // a [wave] section
  bool bem = false;    // a [bem] section
};

Scene build_scene(const WrittenKeys& keys, const std::string& file, const SceneParts& parts);

}  // namespace ffrf::scene
