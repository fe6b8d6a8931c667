// A scene's Capytaine dataset (bem.capytaine_file; hydro/capytaine_reader.hpp, docs/hydrodynamics.md
// §4.5) read into scene.bem and tied to the scene:
//  * ρ: the dataset's dimensional values are scaled from its ρ to environment.water_density (linear
//    potential flow at fixed ω, g and geometry is proportional to ρ);
//  * g and the water depth must be the scene's (g within 10⁻⁶, the depth within 1 % or both deep):
//    the wave numbers, and with them every coefficient, depend on them;
//  * hydrostatics: the box hull's pressure integration owns them (as with WAMIT files); a dataset's
//    hydrostatic_stiffness is checked against the waterplane (C33 = ρgLB within 2 %); without one the
//    box hull's geometry gives the stiffness;
//  * bem.excitation = "bem" needs the dataset's Froude–Krylov and diffraction forces;
//  * A∞: the dataset's ω = ∞ row, else estimated by bem.infinite_frequency_added_mass
//    (hydro/infinite_frequency.hpp), reported as a warning that names the method and both estimates.
#pragma once

#include <vector>

#include "scene/bem_files.hpp"

namespace ffrf::scene {

// Fills scene.bem (radiation, excitation_table, hydrostatics, infinite_frequency_estimate) from
// scene.bem->radiation_file; the problems (and warnings) found.
std::vector<BemProblem> load_capytaine_dataset(Scene& scene);

}  // namespace ffrf::scene
