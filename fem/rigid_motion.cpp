// The beam's planar rigid motions (see the header).
#include "fem/rigid_motion.hpp"

namespace ffrf::fem {

Eigen::VectorXd rigid_motion(const BeamMesh& mesh, const DofMap& dofs, RigidMotion motion) {
  Eigen::VectorXd out(dofs.free_count());
  for (int i = 0; i < dofs.free_count(); ++i) {
    const int full = dofs.free_to_full[static_cast<std::size_t>(i)];
    const int node = full / node_dofs;
    const auto dof = static_cast<NodeDof>(full % node_dofs);
    switch (motion) {
      case RigidMotion::axial_translation: out(i) = dof == NodeDof::axial ? 1.0 : 0.0; break;
      case RigidMotion::transverse_translation: out(i) = dof == NodeDof::transverse ? 1.0 : 0.0; break;
      case RigidMotion::turn_about_root:
        out(i) = dof == NodeDof::axial ? 0.0 : dof == NodeDof::transverse ? mesh.node_position(node) : 1.0;
        break;
    }
  }
  return out;
}

}  // namespace ffrf::fem
