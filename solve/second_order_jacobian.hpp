// The linearization the implicit integrators' Newton iterations need of a second-order system
// M(x) ẍ = Q(x, ẋ, t), in structured (bordered band) storage:
//   mass M(x), stiffness K = −∂(Q − M a)/∂x and damping D = −∂(Q − M a)/∂ẋ at a fixed a = ẍ.
// CVODE's Newton matrix on y = (x, ẋ) then reduces to the effective matrix M + γD + γ²K
// (solve/second_order_newton.hpp), IDA's and generalized-α's to the same blocks bordered by the
// constraint rows. K and D are "stiffness-like": a spring k gives +k, a dashpot c gives +c.
#pragma once

#include "solve/bordered_band_matrix.hpp"

namespace ffrf::solve {

struct SecondOrderJacobian {
  BorderedBandMatrix mass, stiffness, damping;

  SecondOrderJacobian() = default;
  explicit SecondOrderJacobian(const BandStructure& structure) : mass(structure), stiffness(structure), damping(structure) {}
  const BandStructure& structure() const { return mass.structure(); }
  void set_zero() {
    mass.set_zero();
    stiffness.set_zero();
    damping.set_zero();
  }
};

}  // namespace ffrf::solve
