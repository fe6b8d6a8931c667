// The pinned boom on a luffing wire against an independent model (tests/multibody/
// pinned_boom_reference.hpp: its own frame finite elements and the exact Euler–Bernoulli frequency
// equation and deflection, nothing of fem/ or multibody/): the crane of cases/pinned_luffing_crane.toml
// with its hull held, no cargo and one luffing wire from the tip, linearised about rest
// (multibody/linearisation.hpp) and solved for its static equilibrium under its own weight.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "../multibody/pinned_boom_reference.hpp"
#include "held_boom.hpp"
#include "slack_detections.hpp"
#include "multibody/crane_model.hpp"
#include "multibody/crane_run.hpp"
#include "multibody/crane_statics.hpp"
#include "multibody/linearisation.hpp"
#include "modal/modal_coordinates.hpp"
#include "nodal/nodal_coordinates.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf {
namespace {

constexpr double taut = 1e-6;  // the linearisations' pretension stretch [m]

struct HeldPinnedBoom {
  std::unique_ptr<multibody::CraneEquations> equations;
  test::PinnedBoom reference;
  double angle = 0.0;
};

// The crane's parameters with the hull held (turned so that the boom lies level), no water, no
// cargo and its hoist wire, gravity g.
template <class Parameters>
std::unique_ptr<multibody::CraneEquations> held_equations(Parameters model, double gravity) {
  model.gravity = gravity;
  const Eigen::Vector3d pose = test::level_boom_pose(model);
  return test::held_boom(std::move(model), pose);
}

// The shipped pinned crane's boom, pinned to a held hull turned by −boom.angle so that the boom lies
// level (its weight all transverse: no axial load to couple with the sag), with one luffing wire of
// stiffness k and length 20 m leaving the tip along `direction` (boom frame, towards the anchor),
// stretched by `pretension_stretch` (a linearisation needs a taut wire: the tension-only law has a
// kink at zero stretch; the pretension's geometric stiffness goes to the reference); gravity g, no
// cargo.
HeldPinnedBoom held_pinned_boom(int elements, const Eigen::Vector2d& direction, double stiffness, double gravity,
                                double pretension_stretch, const scene::BoomChoice* modal = nullptr) {
  scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/pinned_luffing_crane.toml");
  const double angle = scene.boom.mount->angle, length = scene.boom.mesh.length, wire_length = 20.0;
  const Eigen::Matrix2d frame = Eigen::Rotation2Dd(angle).toRotationMatrix();
  const Eigen::Vector2d heel(scene.boom.mount->root_x, scene.boom.mount->root_y);
  const Eigen::Vector2d anchor = heel + frame * (Eigen::Vector2d(length, 0.0) + wire_length * direction.normalized());
  scene.luffing->a_frame_x = anchor.x();
  scene.luffing->a_frame_y = anchor.y();
  scene.luffing->wires = 1;
  scene.luffing->stiffness = stiffness;
  scene.luffing->unstretched_length = wire_length - pretension_stretch;
  scene.luffing->damping_ratio = 0.0;
  scene.boom.damping_ratio = 0.0;
  HeldPinnedBoom held;
  if (modal != nullptr) {
    held.equations = held_equations(scene::build_crane_parameters(scene, scene::modal_coordinates(scene, *modal)), gravity);
  } else {
    held.equations = held_equations(scene::build_crane_parameters(scene, nodal::NodalCoordinates(scene::boom_beam(scene, elements))),
                                    gravity);
  }
  held.angle = angle;
  held.reference.length = length;
  held.reference.EI = scene.boom.mesh.section.youngs_modulus * scene.boom.mesh.section.second_moment;
  held.reference.EA = scene.boom.mesh.section.youngs_modulus * scene.boom.mesh.section.area;
  held.reference.mass_per_length = scene.boom.mesh.section.mass_per_length;
  held.reference.wire_stiffness = stiffness;
  held.reference.wire_direction_local = direction.normalized();
  held.reference.wire_tension = stiffness * pretension_stretch;
  held.reference.wire_length = wire_length;
  return held;
}

// The crane's natural frequencies about rest: K φ = ω² M φ of its linearisation.
Eigen::VectorXd crane_frequencies(multibody::CraneEquations& equations) {
  return test::natural_frequencies(equations, Eigen::VectorXd::Zero(equations.minimal_size()));
}

TEST(PinnedBoom, FrequenciesOnAnObliqueWireMatchAnIndependentFrameModel) {
  // The wire 30° off the boom's normal: bending and axial motion couple through it.
  const int elements = 16;
  const Eigen::Vector2d direction(-std::sin(30.0 * M_PI / 180.0), std::cos(30.0 * M_PI / 180.0));
  HeldPinnedBoom held = held_pinned_boom(elements, direction, 2.0e8, 0.0, taut);
  const Eigen::VectorXd crane = crane_frequencies(*held.equations);
  const Eigen::VectorXd reference = test::natural_frequencies_fe(held.reference, elements, 6);
  ASSERT_EQ(crane.size(), 3 * elements + 1);  // the heel angle and the clamped-free frame's 3N
  double worst = 0.0;
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(crane(i), reference(i), 1e-6 * reference(i)) << "mode " << i + 1;
    worst = std::max(worst, std::abs(crane(i) / reference(i) - 1.0));
  }
  std::printf("oblique wire, N = %d: f1 = %.6f Hz, worst relative error of 6 frequencies %.2e\n", elements,
              reference(0) / (2.0 * M_PI), worst);
}

TEST(PinnedBoom, FrequenciesOnATransverseWireMatchTheExactFrequencyEquation) {
  const int elements = 64;
  HeldPinnedBoom held = held_pinned_boom(elements, Eigen::Vector2d(0.0, 1.0), 2.0e8, 0.0, taut);
  const Eigen::VectorXd crane = crane_frequencies(*held.equations);
  test::PinnedBoom exact_boom = held.reference;  // the exact equation has no pretension: its 200 N
  exact_boom.wire_tension = 0.0;                 // stiffen the axial modes only, by ~1e-8
  const Eigen::VectorXd exact = test::natural_frequencies_analytic(exact_boom, 3);
  double worst = 0.0;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(crane(i), exact(i), 1e-6 * exact(i)) << "bending mode " << i + 1;
    worst = std::max(worst, std::abs(crane(i) / exact(i) - 1.0));
  }
  std::printf("transverse wire, N = %d: worst relative error of 3 frequencies against the exact equation %.2e\n",
              elements, worst);
}

TEST(PinnedBoom, StaticDeflectionUnderItsWeightMatchesTheExactBeam) {
  // A small load (g = 0.01 m/s²: the boom turns by ~3e-7 rad about its heel and sags by ~0.1 mm,
  // so the linear theory of the reference holds to ~1e-7): the span sags as a simply supported beam
  // on the wire's spring.
  const int elements = 16;
  const double g = 0.01, stiffness = 2.0e8;
  HeldPinnedBoom held = held_pinned_boom(elements, Eigen::Vector2d(0.0, 1.0), stiffness, g, 0.0);  // (the weight makes it taut)
  const multibody::StaticEquilibrium statics =
      multibody::solve_static_equilibrium(*held.equations, held.equations->initial_guess(), 1e-13);
  const double beta = statics.z(held.equations->heel_offset());
  const double length = held.reference.length;
  // The tip's displacement in the boom's frame at rest: A(β)(L + u, v) − (L, 0).
  const Eigen::Vector2d tip_local = Eigen::Vector2d(length, 0.0) + statics.outputs.tip_deflection;
  const Eigen::Vector2d tip = Eigen::Rotation2Dd(beta).toRotationMatrix() * tip_local - Eigen::Vector2d(length, 0.0);
  const double q = held.reference.mass_per_length * g;  // transverse load per length, towards −y
  const double exact_tip = test::static_deflection_analytic(held.reference, -q, length);
  const Eigen::Vector2d local_gravity(0.0, -g);
  const test::PinnedBoomStatic fe = test::static_deflection_fe(held.reference, elements, local_gravity, Eigen::Vector2d::Zero());
  EXPECT_NEAR(tip.y(), exact_tip, 1e-6 * std::abs(exact_tip));
  EXPECT_NEAR(tip.y(), fe.tip_displacement.y(), 1e-6 * std::abs(fe.tip_displacement.y()));
  EXPECT_NEAR(beta, fe.heel_rotation, 1e-6 * std::abs(fe.heel_rotation));
  EXPECT_NEAR(statics.outputs.luffing_tension, q * length / 2.0, 1e-6 * q * length / 2.0);  // moment about the heel
  std::printf("static sag: tip %.3e (exact %.3e), heel rotation %.3e (reference %.3e); relative errors %.1e, %.1e\n",
              tip.y(), exact_tip, beta, fe.heel_rotation, std::abs(tip.y() / exact_tip - 1.0),
              std::abs(beta / fe.heel_rotation - 1.0));
}

// The chord frame's pinned-pinned mode set (the tip on the frame's axis, the frame turning about the
// pin): with most of its modes the modal boom spans what the nodal one does, so the crane's lowest
// frequencies match the independent frame model; the clamped-free and free-free sets (the heel's
// tangent frame) likewise. All three describe the same physics.
TEST(PinnedBoom, EveryModeSetReachesTheIndependentFrequencies) {
  const int elements = 16;
  const Eigen::Vector2d direction(-std::sin(30.0 * M_PI / 180.0), std::cos(30.0 * M_PI / 180.0));
  HeldPinnedBoom nodal = held_pinned_boom(elements, direction, 2.0e8, 0.0, taut);
  const Eigen::VectorXd reference = test::natural_frequencies_fe(nodal.reference, elements, 4);
  for (const fem::Boundary set : {fem::Boundary::clamped_free, fem::Boundary::free_free, fem::Boundary::pinned_pinned}) {
    scene::BoomChoice choice{scene::BoomKind::modal, elements, 40, true};
    choice.mode_set = set;
    HeldPinnedBoom modal = held_pinned_boom(elements, direction, 2.0e8, 0.0, taut, &choice);
    const Eigen::VectorXd crane = crane_frequencies(*modal.equations);
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(crane(i), reference(i), 1e-6 * reference(i)) << fem::to_string(set) << ", mode " << i + 1;
    }
  }
}

TEST(PinnedBoom, ThePinnedPinnedModeSetNeedsAPinnedHeel) {
  const scene::Scene clamped = scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  scene::BoomChoice choice{scene::BoomKind::modal, 16, 2, true};
  choice.mode_set = fem::Boundary::pinned_pinned;
  try {
    (void)scene::build_crane_model(clamped, choice);
    ADD_FAILURE() << "a clamped boom must refuse the chord frame's mode set";
  } catch (const scene::SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("boom.heel"), std::string::npos) << error.what();
  }
}

// A tackle of p parts of line, each of stiffness k/p, is the single wire of stiffness k: the same
// rest (the derived unstretched length included), the same frequencies, the same pull on the boom;
// each part carries 1/p of it, and the two wires share the pull equally.
TEST(PinnedBoom, AReevedTackleIsItsPartsOfLineInParallel) {
  const scene::Scene single = scene::load_scene(FFRF_SOURCE_DIR "/cases/pinned_luffing_crane.toml");
  ASSERT_EQ(single.luffing->parts, 1);
  scene::Scene reeved = single;
  reeved.luffing->parts = 4;
  reeved.luffing->stiffness = single.luffing->stiffness / 4.0;
  auto single_equations = scene::build_crane_equations(single, {scene::BoomKind::nodal, 4});
  auto reeved_equations = scene::build_crane_equations(reeved, {scene::BoomKind::nodal, 4});
  const multibody::StaticEquilibrium a = multibody::solve_static_equilibrium(*single_equations, single_equations->initial_guess());
  const multibody::StaticEquilibrium b = multibody::solve_static_equilibrium(*reeved_equations, reeved_equations->initial_guess());
  ASSERT_EQ(a.z.size(), b.z.size());
  EXPECT_LT((a.z - b.z).norm(), 1e-9 * (1.0 + a.z.norm()));
  EXPECT_NEAR(b.outputs.luffing_tension, a.outputs.luffing_tension, 1e-9 * a.outputs.luffing_tension);
  const int wires = single.luffing->wires;
  EXPECT_NEAR(a.outputs.luffing_line_pull, a.outputs.luffing_tension / wires, 1e-9 * a.outputs.luffing_tension);
  EXPECT_NEAR(b.outputs.luffing_line_pull, a.outputs.luffing_tension / (4.0 * wires), 1e-9 * a.outputs.luffing_tension);
  // About the rest: the stiffness and mass of the two cranes' linearisations (multibody/linearisation.hpp).
  const multibody::LinearisedCrane la = multibody::linearise_crane(*single_equations, a.z);
  const multibody::LinearisedCrane lb = multibody::linearise_crane(*reeved_equations, b.z);
  EXPECT_LT((la.stiffness - lb.stiffness).norm(), 1e-7 * la.stiffness.norm());
  EXPECT_LT((la.mass - lb.mass).norm(), 1e-9 * la.mass.norm());
  EXPECT_LT((la.damping - lb.damping).norm(), 1e-7 * la.damping.norm());
  std::printf("luffing pull %.6g N on %d wires; line pull %.6g N single, %.6g N in 4 parts\n", a.outputs.luffing_tension, wires,
              a.outputs.luffing_line_pull, b.outputs.luffing_line_pull);
}

TEST(PinnedBoom, ADroppedLoadSlackensTheLuffingWiresAndTheRunNamesThem) {
  // The shipped pinned crane in calm water with its cargo lifted 3 m and released: the boom, loaded
  // at rest by the cargo, is suddenly unloaded and whips up off its luffing wires (their tension
  // drops below zero on the way), then the falling cargo snatches it down again.
  scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/pinned_luffing_crane.toml");
  scene.wave.reset();
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 4});
  const multibody::StaticEquilibrium statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
  ASSERT_GT(statics.outputs.luffing_tension, 0.0);  // taut at rest
  Eigen::VectorXd z0 = statics.z;
  z0(equations->cargo_offset() + 1) += 3.0;  // the cargo raised 3 m and released at rest
  multibody::RunSettings settings;
  settings.kind = solve::Integrator::cvode;
  settings.relative_tolerance = 1e-8;
  settings.absolute_tolerance = 1e-8;
  settings.duration = 8.0;
  settings.output_interval = 0.01;
  settings.monitor.boom_length = scene.boom.mesh.length;
  settings.monitor.wire_unstretched_length = scene.wire->unstretched_length;
  settings.monitor.static_tension = statics.outputs.wire_tension;
  const multibody::RunResult run = multibody::simulate(*equations, z0, settings);
  EXPECT_FALSE(run.luffing_events.empty());
  ASSERT_EQ(run.wire_names.size(), 3u);  // the hoist wire, then the two luffing wires
  EXPECT_EQ(test::named_detections(run, solve::FailureKind::luffing_slack, {"luffing wire"}), 2) << "each luffing wire named";
  // Slack means no tension: the sampled tension is zero somewhere after the release.
  double least = std::numeric_limits<double>::infinity();
  for (const multibody::CraneOutputs& sample : run.samples) least = std::min(least, sample.luffing_tension);
  EXPECT_EQ(least, 0.0);
}

}  // namespace
}  // namespace ffrf
