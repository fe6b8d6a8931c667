// The static equilibrium of one crane model on its own (`ffrf statics`): the equilibrium the run
// pipeline solves (the same model and solve as prepare_run, so it equals `ffrf run`'s), with what a lift planner reads — the
// hull's offsets from its rest-pose guess (even keel at the mean draft), draft and trim, the cargo's
// position, the wire's tension and stretch, the boom's root moment and tip deflection, the largest
// out-of-balance force and moment, and how KINSOL reached it (Newton directly or by continuation in
// the load) — and the still-water checks of that pose: a deck edge or the cargo below still water
// is not a lift the model describes (no green water, no water forces on the cargo), so it fails by
// name (deck submerged, cargo in water); compression beyond half the boom's Euler load is noted.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "solve/failure.hpp"
#include "multibody/crane_statics.hpp"
#include "modal/mode_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"

namespace ffrf::study {

struct StaticsResult {
  scene::BoomChoice choice;
  int elastic_dof = 0;
  multibody::StaticEquilibrium statics;
  multibody::StaticSolvePath path;  // Newton or continuation; the out-of-balance force and moment left
  Eigen::Vector3d rest_pose = Eigen::Vector3d::Zero();  // the hull's (or hub's) pose before the solve: x, y [m], pitch [rad]
  Eigen::Vector3d hull_offset = Eigen::Vector3d::Zero();  // equilibrium − rest pose (surge, heave, pitch)
  double draft = 0.0;           // keel depth at mid-length [m] (NaN: a hub)
  double wire_stretch = 0.0;    // ℓ − L0 [m] (NaN: no wire)
  double cargo_weight = 0.0;    // m g [N] (0: no cargo)
  double buckling_ratio = 0.0;  // root compression / Euler load
  std::vector<solve::Detection> notes;  // non-fatal findings at rest (buckling)
};

// Solves the static equilibrium of `choice` in `scene` (calm water). Throws what prepare_run throws
// (SettingError, scene::SceneError, solve::SolverFailure) and SolverFailure(deck_submerged /
// cargo_in_water) when the equilibrium puts a deck edge or the cargo below still water.
StaticsResult solve_statics(const scene::Scene& scene, const scene::BoomChoice& choice, modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
