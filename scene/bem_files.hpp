// Reading the WAMIT files a scene's [bem] section names (scene/scene.hpp BemHull;
// hydro/wamit_reader.hpp), with ULEN from the scene and ρ, g from [environment], and the checks that
// tie them to the scene: a crane hull, the excitation file when bem.excitation = "bem", the .hst
// hydrostatics against the box hull's waterplane (C33 = ρ g L B within 2 %).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace ffrf::scene {

struct BemProblem {
  std::string key;      // the scene key the problem is reported at
  std::string message;  // with the WAMIT file and line when the file itself is wrong
};

// A path written in the scene, relative to the scene file's folder (absolute paths unchanged).
std::string resolve_scene_path(const std::string& scene_file, const std::string& written);

// Reads the files into scene.bem (radiation, excitation_table, hydrostatics); the problems found
// (none: the scene is consistent).
std::vector<BemProblem> load_bem_files(Scene& scene);

}  // namespace ffrf::scene
