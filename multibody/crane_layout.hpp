// The crane's index map: where each body's coordinates and each joint's coordinate sit in the
// minimal coordinates z and the full coordinates q. Every loop over components reads its block
// from here, so a component added to the crane is a new entry, not a new offset written by hand.
//   minimal z = (hull x, y, θ | cargo x, y, θ | heel β | η)
//   full    q = (hull x, y, θ | cargo x, y, θ | boom frame R_B, θ_B | η)
// The hull block is absent when the base is held or driven, the cargo block without a cargo, the
// heel angle β when the boom is clamped (its frame then follows the hull: no coordinate of its own).
#pragma once

namespace ffrf::multibody {

struct CraneLayout {
  int hull = -1;     // hull pose in z and q (−1: held or driven base)
  int cargo = -1;    // cargo pose in z and q (−1: no cargo)
  int heel = -1;     // z only: the pinned heel's luffing angle β (−1: clamped)
  int elastic = 0;   // z: the elastic coordinates η
  int frame = 0;     // q: the boom frame (R_B, θ_B); η follows at frame + 3
  int elastic_size = 0;

  int minimal_size() const { return elastic + elastic_size; }
  int full_size() const { return frame + 3 + elastic_size; }
  // The minimal coordinates that move the boom frame — the hull's, then the heel's — which the
  // Schur complement on the constant elastic mass keeps (crane_equations_minimal.ipp).
  int rigid_size() const { return (hull >= 0 ? 3 : 0) + (heel >= 0 ? 1 : 0); }
};

inline CraneLayout crane_layout(bool hull_free, bool cargo, bool pinned_heel, int elastic_size) {
  CraneLayout layout;
  int next = 0;
  if (hull_free) {
    layout.hull = next;
    next += 3;
  }
  if (cargo) {
    layout.cargo = next;
    next += 3;
  }
  layout.frame = next;
  if (pinned_heel) layout.heel = next++;
  layout.elastic = next;
  layout.elastic_size = elastic_size;
  return layout;
}

}  // namespace ffrf::multibody
