// Static equilibrium of the reference scene (KINSOL) against independent statics:
// Archimedes (draft at mid-length · L / cos θ = displaced mass / (ρ B) for the box at any small trim),
// the wire stretch = cargo weight / stiffness, the boom tip deflection = linear cantilever theory
// (tip force P L³/3EI + self weight w L⁴/8EI transversally, P L/EA + w L²/2EA axially, resolved in
// the boom frame at the equilibrium trim), and the joint reaction = weight of boom + cargo.
#include <gtest/gtest.h>

#include "multibody/planar.hpp"
#include "crane_test_support.hpp"

namespace crane_statics_test {

using namespace ffrf;

TEST(CraneStatics, ReferenceSceneEquilibriumMatchesStatics) {
  const scene::Scene scene = test::reference_scene();
  scene::BoomChoice choice;
  choice.kind = scene::BoomKind::nodal;
  choice.elements = 32;
  auto equations = scene::build_crane_equations(scene, choice);
  const multibody::StaticEquilibrium eq = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
  const multibody::CraneOutputs& out = eq.outputs;
  const auto& hull = *scene.hull;
  const double g = scene.environment.gravity, rho = scene.environment.water_density;
  const double boom_mass = scene.boom.mesh.total_mass(), cargo_mass = scene.cargo->mass;
  const double displaced = hull.mass + boom_mass + cargo_mass;

  // Archimedes: keel depth at mid-length.
  const Eigen::Vector2d keel_mid = out.hull.head<2>() + multibody::rotation(out.hull(2)) * Eigen::Vector2d(hull.g1_aft_of_mid_length, -hull.g1_above_keel);
  // The trimmed box's submerged area is L · (−y_keel,mid) / cos θ (the waterline's height above the
  // keel varies linearly along the hull; at mid-length it is the vertical depth over cos θ).
  EXPECT_NEAR(-keel_mid.y() / std::cos(out.hull(2)), displaced / (rho * hull.length * hull.width), 1e-9);
  EXPECT_LT(std::abs(out.hull(2)), 0.01) << "the loaded crane floats nearly level";

  // Wire: tension = cargo weight, stretch = weight / stiffness.
  EXPECT_NEAR(out.wire_tension, cargo_mass * g, 1e-8 * cargo_mass * g);
  EXPECT_NEAR(out.wire_length - scene.wire->unstretched_length, cargo_mass * g / scene.wire->stiffness, 1e-10);

  // Boom tip: linear cantilever under the wire force (vertical at rest) and self weight.
  const double angle = out.hull(2) + scene.boom.mount->angle;
  const Eigen::Vector2d wire_force_local = multibody::rotation(angle).transpose() * Eigen::Vector2d(0.0, -out.wire_tension);
  const Eigen::Vector2d weight_local = multibody::rotation(angle).transpose() * Eigen::Vector2d(0.0, -scene.boom.mesh.section.mass_per_length * g);
  const double length = scene.boom.mesh.length;
  const double ei = scene.boom.mesh.section.bending_rigidity(), ea = scene.boom.mesh.section.axial_rigidity();
  const double transverse = wire_force_local.y() * std::pow(length, 3) / (3 * ei) + weight_local.y() * std::pow(length, 4) / (8 * ei);
  const double axial = wire_force_local.x() * length / ea + weight_local.x() * length * length / (2 * ea);
  EXPECT_NEAR(out.tip_deflection.y(), transverse, 5e-3 * std::abs(transverse)) << "required bound 0.5 %";
  EXPECT_NEAR(out.tip_deflection.y(), transverse, 1e-8 * std::abs(transverse)) << "Hermite elements are exact here";
  EXPECT_NEAR(out.tip_deflection.x(), axial, 1e-8 * std::abs(axial));

  // Joint reaction on the boom at B carries boom and cargo weight.
  EXPECT_NEAR(out.joint_reaction.y(), (boom_mass + cargo_mass) * g, 1e-8 * (boom_mass + cargo_mass) * g);
  EXPECT_NEAR(out.joint_reaction.x(), 0.0, 1e-6 * out.joint_reaction.y());
}

TEST(CraneStatics, RigidAndModalBoomsReachTheSameFloatingPose) {
  const scene::Scene scene = test::reference_scene();
  scene::BoomChoice nodal{scene::BoomKind::nodal, 16, 0, false};
  scene::BoomChoice modal{scene::BoomKind::modal, 16, 0, true};  // static modes only: exact static tip
  auto nodal_eq = scene::build_crane_equations(scene, nodal);
  auto modal_eq = scene::build_crane_equations(scene, modal);
  const auto a = multibody::solve_static_equilibrium(*nodal_eq, nodal_eq->initial_guess());
  const auto b = multibody::solve_static_equilibrium(*modal_eq, modal_eq->initial_guess());
  EXPECT_NEAR(a.outputs.tip_deflection.y(), b.outputs.tip_deflection.y(), 1e-10 * std::abs(a.outputs.tip_deflection.y()));
  EXPECT_NEAR(a.outputs.cargo.y(), b.outputs.cargo.y(), 1e-9);
}

}  // namespace crane_statics_test
