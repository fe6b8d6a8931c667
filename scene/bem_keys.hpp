// Which [bem] keys go together (docs/scenes.md, docs/hydrodynamics.md §6): the coefficients come from
// WAMIT files (bem.radiation_file, with excitation_file, hydrostatics_file, length_scale) or from one
// Capytaine NetCDF dataset (bem.capytaine_file, with infinite_frequency_added_mass), never both.
#pragma once

#include "scene/wave_keys.hpp"

namespace ffrf::scene {

// Reports a [bem] with neither source, with both, and the keys of the other source; `bem_line` is
// the section's line.
void check_bem_keys(WrittenKeys& keys, int bem_line);

}  // namespace ffrf::scene
