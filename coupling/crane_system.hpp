// The floating crane's equations of motion for one choice of elastic coordinates: loads on the
// three bodies (gravity, hull pressure, radiation, mooring, wire, elastic and damping forces),
// the minimal-coordinate ODE (boom frame eliminated through the clamp at B, velocity
// transformation q̇_B = J ż, M_z = JᵀMJ, Q_z = Jᵀ(Q − M J̇ż); Shabana 2005 §6, "embedding
// technique") solved by a Schur complement on the constant elastic mass M_ff, and the full-
// coordinate DAE pieces (paper eqs. 22, 31–34). Implements CraneEquations.
#pragma once

#include <memory>

#include "coupling/crane_equations.hpp"
#include "coupling/crane_model.hpp"

namespace ffrf::coupling {

template <fem::ElasticCoordinates Coords>
std::unique_ptr<CraneEquations> make_crane_equations(CraneModel<Coords> model);

}  // namespace ffrf::coupling
