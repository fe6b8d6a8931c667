// Helpers for the study tests: the shipped scenes by file name.
#pragma once

#include <string>

#include "scene/scene_loader.hpp"

namespace ffrf::test {

inline scene::Scene scene_file(const std::string& name) { return scene::load_scene(FFRF_SOURCE_DIR "/cases/" + name); }

}  // namespace ffrf::test
