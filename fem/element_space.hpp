// The space fem/'s elements live in (linalg/space.hpp): planar two-node frame elements with
// (u, v, φ) per node — axial, transverse, small rotation — so 3 DOFs per node and 6 per element. A
// spatial element (12 DOFs with torsion and bending in two planes) belongs to the spatial space.
#pragma once

#include "linalg/space.hpp"

namespace ffrf::fem {

using Space = linalg::Planar;
inline constexpr int node_dofs = Space::node_dofs;
inline constexpr int element_dofs = 2 * node_dofs;

}  // namespace ffrf::fem
