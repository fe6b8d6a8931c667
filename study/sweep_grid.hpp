// The configurations of `ffrf sweep`: boom model × integrator × tolerance or step, enumerated in a
// fixed order so that every configuration has a stable id (its index) and `--shard i/n` selects a
// deterministic slice (id % n == i).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "distributed/shard.hpp"

#include "hydro/radiation_memory.hpp"
#include "scene/crane_builder.hpp"
#include "multibody/crane_run.hpp"

namespace ffrf::study {

enum class SweepGrid { quick, medium, full };
std::string_view to_string(SweepGrid grid);
// "quick", "medium", "full"; throws SettingError (Setting::grid) naming the choices.
SweepGrid parse_sweep_grid(std::string_view name);
// One paragraph saying what the grid contains.
std::string grid_description(SweepGrid grid);

struct SweepConfig {
  int id = 0;
  scene::BoomChoice choice;
  solve::Integrator integrator = solve::Integrator::cvode;
  double rtol = 0.0;               // 0: none (fixed-step explicit RK)
  double step = 0.0;               // fixed step [s] (generalized-α); 0: adaptive or by stability_factor
  double stability_factor = 0.0;   // > 0: ARKODE fixed step = factor × the explicit stability limit
  // The hull's radiation model (a scene with [bem]); empty: the scene's own.
  std::optional<hydro::RadiationKind> radiation;
};

// Every configuration of the grid, ids 0, 1, 2, ... in order. With `radiation_axis` (a scene with
// [bem]) every boom/integrator configuration is crossed with the three radiation models
// (constant, state-space, convolution: consecutive ids); without it the ids are those of the plain grid.
// The adaptive integrators run at `choice_rtol` too (study::model_choice_rtol of the verdict's τ; the
// grids' own tolerances include 1e-6, that of τ = 1 %), appended after the grid's own. With
// `mode_set_axis` (a pinned boom) the modal models are repeated with the free-free mode set, then
// with the pinned-pinned one, after all the others.
std::vector<SweepConfig> sweep_grid(SweepGrid grid, bool radiation_axis = false, double choice_rtol = 1e-6,
                                    bool mode_set_axis = false);
// "constant", "state-space", "convolution"; empty when the configuration keeps the scene's model.
std::string radiation_name(const SweepConfig& config);

// "rigid", "nodal", "modal", "modal+static": the marker style of the charts.
std::string model_family(const scene::BoomChoice& choice);
// "cvode rtol 1e-06", "generalized-alpha h 0.01 s", "arkode h 2x limit": for tables.
std::string integrator_label(const SweepConfig& config);

// Whether the configuration is in the shard (distributed/shard.hpp): id % count == index.
inline bool in_shard(const SweepConfig& config, const distributed::Shard& shard) {
  return static_cast<std::size_t>(config.id) % shard.count == shard.index;
}

}  // namespace ffrf::study
