// The A-frame pinned to the deck and its backstays, from the scene's [a_frame] and [backstay]
// sections: the A-frame a rigid bar from its foot pin to its top (where the luffing wires end), its
// mass halfway; the backstays from the top to a deck point aft. Their unstretched length is given, or
// the one that holds the A-frame at its built pose on the level hull against the luffing wires' pull
// at rest (scene/luffing_wires.hpp) and its own weight.
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_checks.hpp"

namespace ffrf::scene {

struct AFrameGeometry {
  Eigen::Vector2d pin;     // the foot pin relative to G1, hull frame [m]
  Eigen::Vector2d top;     // the top (luffing.a_frame_x, luffing.a_frame_y) [m]
  Eigen::Vector2d centre;  // its centre of mass, halfway [m]
  double height = 0.0;     // |top − pin| [m]
  double angle = 0.0;      // of the body frame (x from the pin to the top) relative to the hull [rad]
  double rotary_inertia = 0.0;       // about its centre of mass [kg m²]
  double inertia_about_pin = 0.0;    // [kg m²]
  Eigen::Vector2d deck;              // the backstays' deck point [m]
  double backstay_length = 0.0;      // from the top to the deck point at rest [m]
  double backstay_lever = 0.0;       // the backstays' lever about the pin per unit tension, (top − pin) × d [m] (> 0 holds it)
  double backstay_tension = 0.0;     // all backstays' tension at rest [N]
  double backstay_unstretched_length = 0.0;  // each backstay's (given or derived) [m]
  double backstay_damping = 0.0;     // each backstay's damping coefficient [N s/m]
};

// The geometry and rest tension of a scene's A-frame and backstays (scene.a_frame and scene.backstay set).
AFrameGeometry a_frame_geometry(const Scene& scene);

// What keeps the A-frame from standing (errors naming the keys): a pin at the top, backstays that
// cannot hold it against the luffing wires (their tension at rest would not be positive), backstays too
// soft to carry it.
std::vector<SceneFinding> a_frame_findings(const Scene& scene);

}  // namespace ffrf::scene
