// The crane's index map: where each body's coordinates and each joint's coordinate sit in the
// minimal coordinates z and the full coordinates q, and where each joint's rows sit among the
// constraints. Every loop over components reads its block from here, so a component added to the
// crane is a new entry, not a new offset written by hand.
//   minimal z = (hull x, y, θ | free bodies' x, y, θ | pinned bodies' γ | heel β | η)
//   full    q = (hull x, y, θ | every rigid body's x, y, θ | boom frame R_B, θ_B | η)
//   constraints (full coordinates) = (heel at B: 3 for a clamp, 2 for a pin | each pinned body's pin: 2)
// The rigid bodies are CraneParameters::bodies in their order (multibody/rigid_body_model.hpp). The hull
// block is absent when the base is held or driven, the heel angle β when the boom is clamped (its frame
// then follows the hull: no coordinate of its own). The rigid block — the minimal coordinates coupled
// by inertia with the boom frame and the hull, which the Schur complement on the constant elastic mass
// keeps (crane_equations_minimal.ipp) — is (hull | pinned bodies' γ | heel β); a free body's block is its
// own (its mass is diagonal and nothing else moves it).
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "multibody/rigid_body_model.hpp"

namespace ffrf::multibody {

// Rigid block sizes the equations hold on the stack: the hull's 3, the heel's angle and two pinned
// bodies (in full coordinates the joints' rows, at most solve::max_constraints = 6, allow two pinned
// bodies with a pinned heel, one with a clamped one: checked when the model is made).
inline constexpr int max_rigid_block = 6;

struct BodyBlock {
  int minimal = -1;     // its first coordinate in z (a free body's x, a pinned body's γ)
  int full = -1;        // its (x, y, θ) in q
  bool pinned = false;  // pinned to the hull (one coordinate in z, two constraint rows)
  int rigid = -1;       // pinned: its γ's place in the rigid block
  int constraint = -1;  // pinned: its first constraint row
};

struct CraneLayout {
  int hull = -1;                 // hull pose in z and q (−1: held or driven base)
  std::vector<BodyBlock> bodies;  // one per rigid body, in CraneParameters::bodies' order
  int pinned_count = 0;          // pinned bodies
  int heel = -1;                 // z only: the pinned heel's luffing angle β (−1: clamped)
  int elastic = 0;               // z: the elastic coordinates η
  int frame = 0;                 // q: the boom frame (R_B, θ_B); η follows at frame + 3
  int elastic_size = 0;
  // The z index of each coordinate of the rigid block, in its order.
  std::array<int, max_rigid_block> rigid_coordinates{};

  int minimal_size() const { return elastic + elastic_size; }
  int full_size() const { return frame + 3 + elastic_size; }
  int rigid_size() const { return (hull >= 0 ? 3 : 0) + pinned_count + (heel >= 0 ? 1 : 0); }
  // The rigid block is more than the hull's three coordinates: a pinned heel or a pinned body.
  bool articulated() const { return heel >= 0 || pinned_count > 0; }
  int heel_constraints() const { return heel >= 0 ? 2 : 3; }
  int constraint_count() const { return heel_constraints() + 2 * pinned_count; }
};

template <class Bodies>
CraneLayout crane_layout(bool hull_free, const Bodies& bodies, bool pinned_heel, int elastic_size) {
  CraneLayout layout;
  int next = 0, rigid = 0;
  if (hull_free) {
    layout.hull = next;
    next += 3;
    for (; rigid < 3; ++rigid) layout.rigid_coordinates[rigid] = rigid;
  }
  layout.bodies.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {  // free bodies' poses
    if (bodies[i].pinned()) continue;
    layout.bodies[i].minimal = next;
    next += 3;
  }
  int row = pinned_heel ? 2 : 3;  // the pinned bodies' rows follow the heel's
  for (std::size_t i = 0; i < bodies.size(); ++i) {  // pinned bodies' angles
    if (!bodies[i].pinned()) continue;
    if (rigid + 1 + (pinned_heel ? 1 : 0) > max_rigid_block) {
      throw std::invalid_argument("the crane has more bodies pinned to the hull than its rigid block holds (" +
                                  std::to_string(max_rigid_block) + " coordinates with the hull's and the heel's)");
    }
    BodyBlock& block = layout.bodies[i];
    block.pinned = true;
    block.minimal = next;
    block.rigid = rigid;
    block.constraint = row;
    row += 2;
    layout.rigid_coordinates[rigid++] = next++;
    ++layout.pinned_count;
  }
  int full = layout.hull >= 0 ? 3 : 0;
  for (BodyBlock& block : layout.bodies) {
    block.full = full;
    full += 3;
  }
  layout.frame = full;
  if (pinned_heel) {
    layout.heel = next++;
    layout.rigid_coordinates[rigid++] = layout.heel;
  }
  layout.elastic = next;
  layout.elastic_size = elastic_size;
  return layout;
}

}  // namespace ffrf::multibody
