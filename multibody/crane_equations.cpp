// The crane's rows for the static solver: which body's balance a residual row is, and what to check
// in the scene when it stays out of balance (multibody/crane_equations.hpp).
#include "multibody/crane_equations.hpp"

#include <string>

namespace ffrf::multibody {

solve::ResidualRow CraneEquations::residual_row(int row) const {
  const CraneLayout& rows = layout();
  int free_body = -1, pinned_body = -1;  // the rigid body whose rows these are
  for (std::size_t i = 0; i < rows.bodies.size(); ++i) {
    const BodyBlock& block = rows.bodies[i];
    if (!block.pinned && row >= block.minimal && row < block.minimal + 3) free_body = static_cast<int>(i);
    if (block.pinned && row == block.minimal) pinned_body = static_cast<int>(i);
  }
  solve::ResidualRow meaning;
  meaning.moment = (rows.hull >= 0 && row == rows.hull + 2) || (free_body >= 0 && row == rows.bodies[free_body].minimal + 2) ||
                   pinned_body >= 0 || (rows.heel >= 0 && row == rows.heel);
  meaning.rigid = row < rows.elastic;
  if (rows.hull >= 0 && row == rows.hull) {
    meaning.what = "the hull's surge force";
    meaning.check = "check the mooring's surge stiffness (mooring.surge_stiffness > 0 holds the hull)";
  } else if (rows.hull >= 0 && row == rows.hull + 1) {
    meaning.what = "the hull's heave force (buoyancy against the weight)";
    meaning.check =
        "the hull cannot float the load: hull + boom + cargo must weigh less than the water the box displaces "
        "up to its deck (hull.mass, cargo.mass, hull.length/width/depth)";
  } else if (rows.hull >= 0 && row == rows.hull + 2) {
    meaning.what = "the hull's pitch moment (trim)";
    meaning.check =
        "the hull cannot trim to balance the load moment before a deck edge or the keel leaves its waterline: "
        "lighten the load, shorten the outreach or move G1 (hull.g1_aft_of_mid_length)";
  } else if (free_body >= 0 && free_body == cargo_body()) {
    static const char* const names[] = {"the cargo's horizontal force", "the cargo's vertical force (wire tension against weight)",
                                        "the cargo's pitch moment about its hook"};
    meaning.what = names[row - rows.bodies[free_body].minimal];
    meaning.check =
        "the cargo cannot hang still below the boom tip: check the wire (wire.stiffness, wire.unstretched_length) "
        "and the hook (cargo.hook_x, cargo.hook_y)";
  } else if (free_body >= 0) {
    static const char* const names[] = {"horizontal force", "vertical force", "pitch moment about its centre of mass"};
    meaning.what = "the " + body_name(free_body) + "'s " + names[row - rows.bodies[free_body].minimal];
    meaning.check = "the " + body_name(free_body) + " cannot hang still on its wires: check their lengths and stiffnesses";
  } else if (pinned_body >= 0) {
    meaning.what = "the " + body_name(pinned_body) + "'s moment about its pin";
    meaning.check = "the " + body_name(pinned_body) +
                    " cannot stand on its pin: check that the wires that hold it are taut at rest (the backstays' "
                    "unstretched length against the A-frame's geometry) and stiff enough";
  } else if (rows.heel >= 0 && row == rows.heel) {
    meaning.what = "the boom's moment about its pinned heel";
    meaning.check =
        "the luffing wires cannot hold the boom: check that they are taut at rest (luffing wire unstretched length "
        "against the heel-to-A-frame geometry) and stiff enough";
  } else {
    meaning.what = "the boom's elastic force (coordinate " + std::to_string(row - rows.elastic) + ")";
    meaning.check =
        "the boom cannot carry its load: compare its root compression with the Euler load (ffrf check), or "
        "stiffen the boom (boom.second_moment, boom.area)";
  }
  return meaning;
}

std::string CraneEquations::static_model_check() const {
  return "check that the hull floats with its deck above the water and the cargo hangs below the boom tip";
}

std::vector<int> CraneEquations::rigid_body_blocks() const {
  const CraneLayout& rows = layout();
  std::vector<int> blocks;
  if (rows.hull >= 0) blocks.push_back(rows.hull);
  for (const BodyBlock& block : rows.bodies) {
    if (!block.pinned) blocks.push_back(block.minimal);
  }
  return blocks;
}

}  // namespace ffrf::multibody
