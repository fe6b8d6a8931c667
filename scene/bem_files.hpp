// Reading the WAMIT files (or the Capytaine dataset) a scene's [bem] section names (scene/scene.hpp BemHull;
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
  bool warning = false;  // doubtful but not wrong (the scene's warnings), e.g. an estimated A∞
};

// A path written in the scene, relative to the scene file's folder (absolute paths unchanged).
std::string resolve_scene_path(const std::string& scene_file, const std::string& written);

// Reads the files into scene.bem (radiation, excitation_table, hydrostatics); the problems found
// (none: the scene is consistent). A Capytaine dataset goes through load_capytaine_dataset
// (scene/capytaine_files.hpp).
std::vector<BemProblem> load_bem_files(Scene& scene);

// "" when the BEM hydrostatic stiffness of `file` (at the scene's ρ) has the box hull's heave
// stiffness C33 = ρ·g·L·B within 2 %; else the problem.
std::string waterplane_mismatch(const Scene& scene, const hydro::PlanarMatrix& hydrostatics, const std::string& file);

// The scene key that names the file of the radiation coefficients (bem.radiation_file or
// bem.capytaine_file) and of the excitation (bem.excitation_file or bem.capytaine_file).
std::string bem_radiation_key(const BemHull& bem);
std::string bem_excitation_key(const BemHull& bem);

}  // namespace ffrf::scene
