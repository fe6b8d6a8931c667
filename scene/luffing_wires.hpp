// The luffing wires of a pinned boom, from the scene's [luffing] section: where they attach (the
// A-frame top on the hull, a point on the boom), their unstretched length — given, or the one that
// holds the rigid boom and the cargo at boom.angle on the level hull — and their tension at rest.
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_checks.hpp"

namespace ffrf::scene {

struct LuffingGeometry {
  Eigen::Vector2d a_frame;     // A-frame top relative to G1, hull frame [m]
  Eigen::Vector2d heel;        // B relative to G1, hull frame [m]
  double attachment = 0.0;     // boom point's distance from B along the boom [m]
  Eigen::Vector2d boom_point;  // that point at boom.angle, relative to G1, hull frame [m]
  double length = 0.0;         // wire length from the boom point to the A-frame at boom.angle [m]
  double lever = 0.0;          // the wires' lever about B per unit tension, (P − B) × d [m] (> 0: they hold the boom up)
  double total_tension = 0.0;  // all wires' tension holding the rigid boom and the cargo at boom.angle [N]
  double unstretched_length = 0.0;  // each wire's (given or derived) [m]
};

// Each luffing wire's stiffness between the A-frame and the boom: its tackle's, luffing.parts parts
// of line of luffing.stiffness each, p k₁ [N/m].
double tackle_stiffness(const Luffing& luffing);

// The geometry and rest tension of a pinned crane scene's luffing wires (scene.luffing set).
LuffingGeometry luffing_geometry(const Scene& scene);

// What keeps the luffing wires from holding the boom (errors naming the keys): a boom point beyond
// the boom, an A-frame that cannot lift it (lever ≤ 0), wires too soft to carry the rest tension.
std::vector<SceneFinding> luffing_findings(const Scene& scene);

}  // namespace ffrf::scene
