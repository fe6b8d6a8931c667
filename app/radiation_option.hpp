// `--radiation constant|state-space|convolution` of run, compare, sweep and recommend: overrides
// bem.radiation_model of a scene with BEM coefficients ([bem]; docs/hydrodynamics.md §6).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "scene/scene.hpp"

namespace ffrf::app {

void add_radiation_option(CLI::App& sub, std::string& radiation);
// Applies a given --radiation to the scene (nothing when empty); throws BadOption for an unknown
// name or a scene without [bem].
void apply_radiation_option(scene::Scene& scene, const std::string& radiation);

}  // namespace ffrf::app
