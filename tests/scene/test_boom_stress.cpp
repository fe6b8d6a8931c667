// Stresses along the boom (multibody/boom_stress.hpp) against beam statics and against themselves:
//  * the reference crane with its hull held level, at rest: the clamped boom is a cantilever under
//    its weight q = ρAg and the hanging cargo's W at the tip, so N(x) = −(q(L − x) + W) sin α and
//    M(x) = −cos α (q(L − x)²/2 + W(L − x)) — the recovered nodal values exactly those (the element
//    end forces with the elements' loads: no fixed-end shift);
//  * a rigid boom's stresses (by mode acceleration: the static response to its loads) at rest equal
//    the nodal boom's on the same mesh;
//  * a modal basis that spans the whole nodal space leaves no residual: mode acceleration equals mode
//    displacement at every sample of a run in a wave, in minimal coordinates (CVODE) and in full
//    coordinates with the heel's multipliers (IDA) — so the residual's inertia, coupling and
//    load terms are those of the modal equations, term by term;
//  * the stresses' envelope over a run holds every sample's profile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "crane_test_support.hpp"
#include "multibody/boom_stress.hpp"
#include "scene/luffing_wires.hpp"

namespace ffrf {
namespace boom_stress_test {

// The reference crane with its hull held at its support pose (level), no water.
std::unique_ptr<multibody::CraneEquations> held_crane(const scene::Scene& scene, const scene::BoomChoice& choice) {
  return test::build_with(scene, choice, [](multibody::HullModel& hull, multibody::WireModel&) {
    hull.fixed = true;
    hull.hydrostatics = false;
    hull.support_pose = Eigen::Vector3d::Zero();
  });
}

// The profile at the static equilibrium of `equations` (the outputs at rest recover it).
multibody::BoomStressProfile stress_at_rest(multibody::CraneEquations& equations) {
  const multibody::StaticEquilibrium rest = multibody::solve_static_equilibrium(equations, equations.initial_guess());
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(equations.minimal_size());
  (void)equations.minimal_outputs(0.0, rest.z, zero);
  return *equations.boom_stress_profile();
}

TEST(BoomStress, ClampedBoomAtRestIsACantileverUnderItsWeightAndTheCargo) {
  const scene::Scene scene = test::reference_scene();
  auto equations = held_crane(scene, {scene::BoomKind::nodal, 16});
  const multibody::BoomStressProfile profile = stress_at_rest(*equations);
  const double alpha = scene.boom.mount->angle, length = scene.boom.mesh.length;
  const double q = scene.boom.mesh.section.mass_per_length * scene.environment.gravity;
  const double weight = scene.cargo->mass * scene.environment.gravity;
  // The sections: the 17 nodes and three points inside each element (a uniform load: N and M are
  // exactly linear and quadratic there too).
  ASSERT_EQ(profile.forces.position.size(), 4 * 16 + 1);
  const double scale = (q * length + weight) * length;
  for (int node = 0; node <= 4 * 16; ++node) {
    const double x = profile.forces.position(node), arm = length - x;
    EXPECT_NEAR(x, length * node / 64.0, 1e-12 * length) << "section " << node;
    const double axial = -(q * arm + weight) * std::sin(alpha);
    const double moment = -std::cos(alpha) * (0.5 * q * arm * arm + weight * arm);
    EXPECT_NEAR(profile.forces.axial_force(node), axial, 1e-7 * (q * length + weight)) << "node " << node;
    EXPECT_NEAR(profile.forces.bending_moment(node), moment, 1e-7 * scale) << "node " << node;
    const fem::FibreStress fibre = fem::fibre_stress(scene.boom.mesh.section, scene.boom.fibre_distance, axial, moment);
    EXPECT_NEAR(profile.top(node), fibre.top, 1e-6 * fibre.extreme()) << "node " << node;
    EXPECT_NEAR(profile.bottom(node), fibre.bottom, 1e-6 * fibre.extreme()) << "node " << node;
  }
  // Hogging: the top fibre is in tension, the bottom one compressed, the peak at the root.
  EXPECT_EQ(profile.peak_position, 0.0);
  EXPECT_GT(profile.top(0), 0.0);
  EXPECT_LT(profile.bottom(0), 0.0);
}

TEST(BoomStress, RigidBoomAtRestCarriesTheNodalBoomsStaticStresses) {
  const scene::Scene scene = test::reference_scene();
  auto nodal = held_crane(scene, {scene::BoomKind::nodal, 16});
  auto rigid = held_crane(scene, {scene::BoomKind::rigid, 1});
  const multibody::BoomStressProfile elastic = stress_at_rest(*nodal), quasi_static = stress_at_rest(*rigid);
  ASSERT_EQ(elastic.forces.position.size(), quasi_static.forces.position.size());
  const double scale = elastic.forces.bending_moment.cwiseAbs().maxCoeff();
  EXPECT_LT((elastic.forces.bending_moment - quasi_static.forces.bending_moment).cwiseAbs().maxCoeff(), 1e-8 * scale);
  EXPECT_LT((elastic.forces.axial_force - quasi_static.forces.axial_force).cwiseAbs().maxCoeff(),
            1e-8 * elastic.forces.axial_force.cwiseAbs().maxCoeff());
  EXPECT_NEAR(quasi_static.peak, elastic.peak, 1e-8 * elastic.peak);
}

multibody::RunSettings wave_run(solve::Integrator kind) {
  multibody::RunSettings s;
  s.kind = kind;
  s.relative_tolerance = s.absolute_tolerance = 1e-7;
  s.duration = 30.0;
  s.output_interval = 0.5;
  return s;
}

// A modal basis of N = 5 elements (15 free DOFs): 12 vibration modes and the static modes fill it.
TEST(BoomStress, ACompleteModalBasisLeavesModeAccelerationNothingToAdd) {
  for (const char* file : {"paper_floating_crane.toml", "pinned_luffing_crane.toml"}) {
    const scene::Scene scene = scene::load_scene(std::string(FFRF_SOURCE_DIR "/cases/") + file);
    scene::BoomChoice choice{scene::BoomKind::modal, 5, 12, true};
    for (const solve::Integrator kind : {solve::Integrator::cvode, solve::Integrator::ida}) {
      auto equations = scene::build_crane_equations(scene, choice);
      ASSERT_EQ(equations->elastic_size(), 15) << file;
      const multibody::StaticEquilibrium rest = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
      const multibody::RunResult run = multibody::simulate(*equations, rest.z, wave_run(kind));
      ASSERT_GT(run.samples.size(), 50u);
      double largest_difference = 0.0, largest_swing = 0.0;
      for (const multibody::CraneOutputs& o : run.samples) {
        largest_difference = std::max(largest_difference, std::abs(o.boom_peak_stress_by[0] - o.boom_peak_stress_by[1]));
        largest_swing = std::max(largest_swing, std::abs(o.boom_peak_stress_by[0] - run.samples.front().boom_peak_stress_by[0]));
      }
      EXPECT_GT(largest_swing, 1e5) << file << ": the wave moves the stresses (Pa)";
      EXPECT_LT(largest_difference, 1e-6 * run.samples.front().boom_peak_stress) << file << ", " << solve::to_string(kind);
    }
  }
}

TEST(BoomStress, TheEnvelopeHoldsEverySample) {
  const scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/pinned_luffing_crane.toml");
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::modal, 16, 2, true});
  const multibody::StaticEquilibrium rest = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
  const multibody::RunResult run = multibody::simulate(*equations, rest.z, wave_run(solve::Integrator::cvode));
  const multibody::BoomStressEnvelope& envelope = run.boom_stress;
  ASSERT_EQ(envelope.samples, static_cast<long>(run.samples.size()));
  double largest = 0.0;
  for (const multibody::CraneOutputs& o : run.samples) largest = std::max(largest, o.boom_peak_stress);
  EXPECT_DOUBLE_EQ(envelope.at_peak.peak, largest);
  // The peak is sought between the nodes too: the nodes' envelope lies at most a little below it.
  const double at_nodes = std::max(envelope.stress_max.maxCoeff(), -envelope.stress_min.minCoeff());
  EXPECT_LE(at_nodes, largest * (1.0 + 1e-12));
  EXPECT_GE(at_nodes, largest * 0.99);
  EXPECT_TRUE((envelope.stress_min.array() <= envelope.stress_max.array()).all());
}

// The heel moment of a pinned boom shows what the linear floating-frame boom leaves out. Its motion
// about the pin is the frame's, balanced with the loads at their deformed positions, while its
// finite elements balance them undeformed: in the heel's tangent frame (clamped-free set) the root
// element therefore carries, as a moment at the pin, the moment of every load about B through its
// elastic displacement u — ΔM = ∫ u × q dx + Σ u_p × F_p (the P-δ moment of the wires' pulls at the
// tip and of the weight) — until geometric stiffening puts the compression's share into the elements.
// In the chord frame (pinned-pinned set) the heel's rotation is an elastic coordinate and the tip lies
// on the frame's axis: the heel moment is zero.
TEST(BoomStress, ThePinnedHeelsMomentIsTheLinearBoomsMissingPDeltaMoment) {
  scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/pinned_luffing_crane.toml");
  const auto held = [](multibody::HullModel& hull, multibody::WireModel&) {
    hull.fixed = true;
    hull.hydrostatics = false;
    hull.support_pose = Eigen::Vector3d::Zero();
  };
  auto tangent = test::build_with(scene, {scene::BoomKind::nodal, 16}, held);
  const multibody::StaticEquilibrium rest = multibody::solve_static_equilibrium(*tangent, tangent->initial_guess());
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(tangent->minimal_size());
  const multibody::CraneOutputs at_rest = tangent->minimal_outputs(0.0, rest.z, zero);
  const multibody::BoomStressProfile profile = *tangent->boom_stress_profile();
  // ΔM from the static state: the boom frame's angle, the elastic coordinates, the wires' pulls at the tip.
  const double frame_angle = scene.boom.mount->angle + rest.z(tangent->heel_offset());
  const Eigen::Matrix2d a = Eigen::Rotation2Dd(frame_angle).toRotationMatrix();
  const auto beam = scene::boom_beam(scene, 16);
  const Eigen::VectorXd eta = rest.z.tail(tangent->elastic_size());
  const Eigen::Vector2d weight_shape = beam->invariants.shape_integral * eta;  // ∫ρA u dx
  const Eigen::Vector2d gravity = a.transpose() * Eigen::Vector2d(0.0, -scene.environment.gravity);
  const scene::LuffingGeometry luffing = scene::luffing_geometry(scene);
  const Eigen::Vector2d heel(scene.boom.mount->root_x, scene.boom.mount->root_y);
  const Eigen::Vector2d tip_local = Eigen::Vector2d(scene.boom.mesh.length, 0.0) + at_rest.tip_deflection;
  const Eigen::Vector2d tip = heel + a * tip_local;
  const Eigen::Vector2d pull = at_rest.luffing_tension * (luffing.a_frame - tip).normalized() +
                               Eigen::Vector2d(0.0, -at_rest.wire_tension);  // luffing wires and the hanging cargo
  const Eigen::Vector2d pull_local = a.transpose() * pull;
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& f) { return u.x() * f.y() - u.y() * f.x(); };
  const double missing = cross(weight_shape, gravity) + cross(at_rest.tip_deflection, pull_local);
  const double span = profile.forces.bending_moment.cwiseAbs().maxCoeff();
  std::printf("heel moment %.6g N m, the loads' moment through u %.6g N m (span moment %.4g N m)\n",
              profile.forces.bending_moment(0), missing, span);
  EXPECT_GT(std::abs(missing), 0.03 * span);  // not small: 6 % of the span's moment here
  EXPECT_NEAR(profile.forces.bending_moment(0), -missing, 1e-3 * std::abs(missing));

  // With static stiffening the compression's share is in the elements: the heel moment is what is left.
  auto stiffened_parameters =
      scene::build_crane_parameters(scene, nodal::NodalCoordinates(scene::boom_beam(scene, 16)), scene::Stiffening::static_load);
  held(stiffened_parameters.hull, test::hoist_rope(stiffened_parameters));
  auto stiffened = multibody::make_crane_equations(std::move(stiffened_parameters));
  EXPECT_LT(std::abs(stress_at_rest(*stiffened).forces.bending_moment(0)), 0.1 * std::abs(missing));
  // The chord frame: no moment at the pin at all.
  scene::BoomChoice chord{scene::BoomKind::modal, 16, 40, true};
  chord.mode_set = fem::Boundary::pinned_pinned;
  auto chord_frame = test::build_with(scene, chord, held);
  EXPECT_LT(std::abs(stress_at_rest(*chord_frame).forces.bending_moment(0)), 1e-6 * span);
}

}  // namespace boom_stress_test
}  // namespace ffrf
