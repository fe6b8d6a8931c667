// The beam's rigid motions (fem/rigid_motion.hpp) store no strain: K r = 0 for the assembled
// free-free stiffness (a property of the element's stiffness, not of how the motions are written),
// while a motion that is not rigid (v = x², a bend) does strain it; and a clamp's DOFs drop out.
#include <gtest/gtest.h>

#include "fem/beam_model.hpp"
#include "fem/rigid_motion.hpp"

namespace {

using namespace ffrf;

TEST(RigidMotion, EachStoresNoStrainInTheFreeBeam) {
  const fem::BeamMesh mesh{120.0, 8, {2.1e11, 1.27, 11.4, 1.0e4}};
  const fem::BeamModel free = fem::make_beam_model(mesh, fem::Boundary::free_free);
  const double scale = Eigen::MatrixXd(free.stiffness).cwiseAbs().maxCoeff();
  for (const auto motion : {fem::RigidMotion::axial_translation, fem::RigidMotion::transverse_translation,
                            fem::RigidMotion::turn_about_root}) {
    const Eigen::VectorXd r = fem::rigid_motion(mesh, free.dofs, motion);
    EXPECT_LT((free.stiffness * r).norm(), 1e-12 * scale * mesh.length * r.norm()) << static_cast<int>(motion);
  }
  Eigen::VectorXd bend = Eigen::VectorXd::Zero(mesh.full_dof_count());
  for (int node = 0; node < mesh.node_count(); ++node) {
    const double x = mesh.node_position(node);
    bend(fem::full_dof(node, fem::NodeDof::transverse)) = x * x;
    bend(fem::full_dof(node, fem::NodeDof::rotation)) = 2.0 * x;
  }
  EXPECT_GT(bend.dot(free.stiffness * bend), 0.0);
  const fem::DofMap clamped = fem::make_dof_map(mesh, fem::Boundary::clamped_free);
  EXPECT_EQ(fem::rigid_motion(mesh, clamped, fem::RigidMotion::turn_about_root).size(), clamped.free_count());
}

}  // namespace
