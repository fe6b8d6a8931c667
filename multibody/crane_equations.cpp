// The crane's rows for the static solver: which body's balance a residual row is, and what to check
// in the scene when it stays out of balance (multibody/crane_equations.hpp).
#include "multibody/crane_equations.hpp"

#include <string>

namespace ffrf::multibody {
namespace {

// The rows of the minimal coordinates: hull (surge, heave, pitch) when it floats, cargo (x, y, θ),
// the pinned heel's moment, then the boom's elastic coordinates.
struct RowLayout {
  int hull = -1, cargo = -1, heel = -1, elastic = 0;
  explicit RowLayout(const CraneEquations& equations)
      : cargo(equations.cargo_offset()), heel(equations.heel_offset()), elastic(equations.minimal_size() - equations.elastic_size()) {
    if (elastic - (cargo >= 0 ? 3 : 0) - (heel >= 0 ? 1 : 0) == 3) hull = 0;
  }
  bool is_moment(int row) const {
    return (hull >= 0 && row == hull + 2) || (cargo >= 0 && row == cargo + 2) || (heel >= 0 && row == heel);
  }
  bool is_rigid(int row) const { return row < elastic; }
};

}  // namespace

solve::ResidualRow CraneEquations::residual_row(int row) const {
  const RowLayout rows(*this);
  solve::ResidualRow meaning;
  meaning.moment = rows.is_moment(row);
  meaning.rigid = rows.is_rigid(row);
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
  } else if (rows.cargo >= 0 && row >= rows.cargo && row < rows.cargo + 3) {
    static const char* const names[] = {"the cargo's horizontal force", "the cargo's vertical force (wire tension against weight)",
                                        "the cargo's pitch moment about its hook"};
    meaning.what = names[row - rows.cargo];
    meaning.check =
        "the cargo cannot hang still below the boom tip: check the wire (wire.stiffness, wire.unstretched_length) "
        "and the hook (cargo.hook_x, cargo.hook_y)";
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
  const RowLayout rows(*this);
  std::vector<int> blocks;
  for (const int body : {rows.hull, rows.cargo}) {
    if (body >= 0) blocks.push_back(body);
  }
  return blocks;
}

}  // namespace ffrf::multibody
