// The beam's planar rigid motions in its nodal coordinates (u, v, φ at each node, x along the beam):
// the translations along the axis (u = 1) and across it (v = 1), and the small turn about the root
// (u = 0, v = x, φ = 1; u = −θy vanishes on the axis). A rigid motion stores no strain: K r = 0 on
// the free-free beam.
#pragma once

#include <Eigen/Dense>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::fem {

enum class RigidMotion { axial_translation, transverse_translation, turn_about_root };

// The motion on the free DOFs of `dofs` (the fixed ones dropped).
Eigen::VectorXd rigid_motion(const BeamMesh& mesh, const DofMap& dofs, RigidMotion motion);

}  // namespace ffrf::fem
