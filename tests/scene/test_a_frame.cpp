// The A-frame pinned to the deck and held by its backstays (cases/a_frame_crane.toml) against an
// independent model (tests/multibody/a_frame_reference.hpp: its own exact two-coordinate energy of a
// rigid boom and A-frame, and its own frame finite elements of the elastic boom, nothing of fem/ or
// multibody/): the crane with its hull held level (its frame the reference's deck frame), without
// the cargo, solved for its static equilibrium and linearised about it (multibody/linearisation.hpp).
// Then the crane's own consistency: minimal and full coordinates (the A-frame's pin eliminated, or a
// constraint with its multipliers) give one motion, the energy is conserved without damping, and a
// backstay that goes slack is named.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "../multibody/a_frame_reference.hpp"
#include "held_boom.hpp"
#include "slack_detections.hpp"
#include "multibody/crane_model.hpp"
#include "multibody/crane_run.hpp"
#include "multibody/crane_statics.hpp"
#include "nodal/nodal_coordinates.hpp"
#include "scene/a_frame.hpp"
#include "scene/crane_builder.hpp"
#include "scene/luffing_wires.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf {
namespace {

scene::Scene a_frame_scene() { return scene::load_scene(FFRF_SOURCE_DIR "/cases/a_frame_crane.toml"); }

// The reference's crane for a scene whose hull is held at G1 = (0, 0), level: the heel, the A-frame's
// pin, top and centre, the deck point are the scene's points in the hull frame.
test::AFrameCrane reference_of(const scene::Scene& scene) {
  const scene::AFrameGeometry a_frame = scene::a_frame_geometry(scene);
  test::AFrameCrane p;
  p.heel = Eigen::Vector2d(scene.boom.mount->root_x, scene.boom.mount->root_y);
  p.boom_length = scene.boom.mesh.length;
  p.boom_angle = scene.boom.mount->angle;
  const fem::BeamSection& section = scene.boom.mesh.section;
  p.EI = section.youngs_modulus * section.second_moment;
  p.EA = section.youngs_modulus * section.area;
  p.mass_per_length = section.mass_per_length;
  p.luffing_count = scene.luffing->wires;
  p.luffing_stiffness = scene.luffing->parts * scene.luffing->stiffness;
  p.pivot = a_frame.pin;
  p.top = a_frame.top;
  p.a_frame_cg = a_frame.centre;
  p.a_frame_mass = scene.a_frame->mass;
  p.a_frame_inertia = a_frame.rotary_inertia;
  p.deck_point = a_frame.deck;
  p.backstay_count = scene.backstay->wires;
  p.backstay_stiffness = scene.backstay->stiffness;
  p.gravity = scene.environment.gravity;
  return p;
}

// The scene's crane on its held, level hull without the cargo, undamped.
template <class Coords>
std::unique_ptr<multibody::CraneEquations> held_crane(const scene::Scene& scene, Coords coords,
                                                      scene::Stiffening stiffening = scene::Stiffening::none) {
  return test::held_boom(scene::build_crane_parameters(scene, std::move(coords), stiffening), Eigen::Vector3d::Zero());
}

scene::Scene undamped(scene::Scene scene) {
  scene.boom.damping_ratio = 0.0;
  scene.luffing->damping_ratio = 0.0;
  scene.backstay->damping_ratio = 0.0;
  return scene;
}

modal::ModalCoordinates rigid_boom(const scene::Scene& scene) {
  return scene::modal_coordinates(scene, scene::BoomChoice{scene::BoomKind::rigid, 1});
}

Eigen::VectorXd frequencies_about_rest(multibody::CraneEquations& equations, multibody::StaticEquilibrium& statics) {
  statics = multibody::solve_static_equilibrium(equations, equations.initial_guess(), 1e-13);
  return test::natural_frequencies(equations, statics.z);
}

TEST(AFrame, ARigidBoomRestsAndSwingsAsTheExactTwoCoordinateModel) {
  // The shipped lengths, derived with the cargo at the tip, hold the boom and the A-frame off their
  // built pose once the cargo is gone: both models find that equilibrium from their own equations.
  const scene::Scene scene = undamped(a_frame_scene());
  auto equations = held_crane(scene, rigid_boom(scene));
  ASSERT_EQ(equations->minimal_size(), 2);  // the A-frame's γ, the heel's β
  test::AFrameCrane reference = reference_of(scene);
  reference.luffing_unstretched = scene::luffing_geometry(scene).unstretched_length;
  reference.backstay_unstretched = scene::a_frame_geometry(scene).backstay_unstretched_length;
  multibody::StaticEquilibrium statics;
  const Eigen::VectorXd crane = frequencies_about_rest(*equations, statics);
  const Eigen::Vector2d rest = test::rigid_static_equilibrium(reference);  // (β, ψ)
  const Eigen::Vector2d exact = test::rigid_frequencies(reference);
  const multibody::CraneLayout& layout = equations->layout();
  const double gamma = statics.z(layout.bodies.at(0).minimal), beta = statics.z(layout.heel);
  EXPECT_GT(std::abs(beta), 1e-4);  // (a real excursion from the built pose)
  EXPECT_NEAR(beta, rest(0), 1e-6 * std::abs(rest(0)));
  EXPECT_NEAR(gamma, rest(1), 1e-6 * std::abs(rest(1)));
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(crane(i), exact(i), 1e-6 * exact(i)) << "mode " << i + 1;
  std::printf("rigid boom: beta %.6e (exact %.6e), gamma %.6e (exact %.6e); f = %.6f, %.6f Hz (exact %.6f, %.6f)\n", beta,
              rest(0), gamma, rest(1), crane(0) / (2 * M_PI), crane(1) / (2 * M_PI), exact(0) / (2 * M_PI), exact(1) / (2 * M_PI));
}

TEST(AFrame, TheTensionsAtRestAreTheMomentBalanceOfBothPins) {
  // With the cargo (a load hanging at the tip: for the statics the reference's tip mass) the derived
  // lengths hold the rigid boom at boom.angle and the A-frame at its built pose.
  const scene::Scene scene = a_frame_scene();
  auto parameters = scene::build_crane_parameters(scene, rigid_boom(scene));
  parameters.hull.fixed = true;
  parameters.hull.hydrostatics = false;
  parameters.hull.support_pose.setZero();
  auto equations = multibody::make_crane_equations(std::move(parameters));
  const multibody::StaticEquilibrium statics =
      multibody::solve_static_equilibrium(*equations, equations->initial_guess(), 1e-13);
  test::AFrameCrane reference = reference_of(scene);
  reference.tip_mass = scene.cargo->mass;
  const test::AFrameRest rest = test::rest_tensions(reference);
  EXPECT_NEAR(statics.z(equations->layout().heel), 0.0, 1e-9);
  EXPECT_NEAR(statics.z(equations->layout().bodies.at(1).minimal), 0.0, 1e-9);
  EXPECT_NEAR(statics.outputs.a_frame_rotation, 0.0, 1e-9);
  EXPECT_NEAR(statics.outputs.luffing_tension, rest.luffing_tension, 1e-8 * rest.luffing_tension);
  EXPECT_NEAR(statics.outputs.backstay_tension, rest.backstay_tension, 1e-8 * rest.backstay_tension);
  std::printf("at rest: luffing %.6g N (reference %.6g), backstays %.6g N (reference %.6g)\n", statics.outputs.luffing_tension,
              rest.luffing_tension, statics.outputs.backstay_tension, rest.backstay_tension);
}

// The elastic boom's lengths: those that make the straight boom at boom.angle and the A-frame at
// rest an equilibrium without the cargo (the reference's linearisation is about that state).
scene::Scene at_reference_rest(scene::Scene scene) {
  const test::AFrameRest rest = test::rest_tensions(reference_of(scene));
  scene.luffing->unstretched_length = rest.luffing_unstretched;
  scene.backstay->unstretched_length = rest.backstay_unstretched;
  return scene;
}

TEST(AFrame, AStiffBoomSwingsAndRocksAsTheFrameModelUnderFullGravity) {
  // A boom 10⁴ times stiffer sags 10⁴ times less: the crane's equilibrium is the reference's rest, so
  // the two linearisations are of one state, with the full weight's wire tensions, the A-frame's load
  // stiffness and the boom's swing on its luffing wires coupled to the A-frame's rocking on its
  // backstays. (The boom's bending modes then lie above 250 Hz, where the prestress the reference
  // keeps, ∫N w'δw', is not negligible against this crane's unstiffened boom: not compared.)
  scene::Scene scene = at_reference_rest(undamped(a_frame_scene()));
  scene.boom.mesh.section.youngs_modulus *= 1e4;
  const int elements = 16;
  auto equations = held_crane(scene, nodal::NodalCoordinates(scene::boom_beam(scene, elements)));
  multibody::StaticEquilibrium statics;
  const Eigen::VectorXd crane = frequencies_about_rest(*equations, statics);
  const Eigen::VectorXd reference = test::elastic_frequencies(reference_of(scene), elements, 2);
  // The A-frame's rocking within 1e-6; the swing within 1e-5: the boom's small elastic share of it
  // feels the reference's prestress, N L²/EI ~ 1e-5 with this stiffness.
  EXPECT_NEAR(crane(0), reference(0), 1e-5 * reference(0)) << "swing";
  EXPECT_NEAR(crane(1), reference(1), 1e-6 * reference(1)) << "A-frame";
  std::printf("stiff boom, N = %d: f = %.7f %.7f Hz (reference %.7f %.7f)\n", elements, crane(0) / (2 * M_PI), crane(1) / (2 * M_PI),
              reference(0) / (2 * M_PI), reference(1) / (2 * M_PI));
}

// The scene at gravity g with the rest lengths of that g (no cargo): the wires' pretension, the sag
// and the boom's axial prestress all scale with g.
scene::Scene at_gravity(double g) {
  scene::Scene scene = undamped(a_frame_scene());
  scene.environment.gravity = g;
  return at_reference_rest(scene);
}

TEST(AFrame, TheElasticBoomsFrequenciesMatchTheIndependentFrameModel) {
  // g = 10⁻⁴ m/s²: the wires pretensioned by the weight (taut), the sag and the prestress ~10⁻⁵ of
  // the shipped crane's, so the crane's linearisation and the reference's are of one state and one
  // physics: the boom's bending and axial motion, its swing and the A-frame's rocking, coupled by
  // the wires' springs.
  const scene::Scene scene = at_gravity(1e-4);
  const int elements = 16;
  auto equations = held_crane(scene, nodal::NodalCoordinates(scene::boom_beam(scene, elements)));
  multibody::StaticEquilibrium statics;
  const Eigen::VectorXd crane = frequencies_about_rest(*equations, statics);
  ASSERT_EQ(crane.size(), 3 * elements + 2);  // the A-frame's γ, the heel's β, the clamped-free frame's 3N
  const Eigen::VectorXd reference = test::elastic_frequencies(reference_of(scene), elements, 6);
  double worst = 0.0;
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(crane(i), reference(i), 1e-6 * reference(i)) << "mode " << i + 1;
    worst = std::max(worst, std::abs(crane(i) / reference(i) - 1.0));
  }
  std::printf("elastic boom, N = %d: f = %.6f %.6f %.6f %.6f Hz; worst relative difference of 6 frequencies %.1e\n", elements,
              crane(0) / (2 * M_PI), crane(1) / (2 * M_PI), crane(2) / (2 * M_PI), crane(3) / (2 * M_PI), worst);
}

TEST(AFrame, TheSagUnderItsWeightMatchesTheIndependentFrameModel) {
  // g = 10⁻³ m/s²: the boom sags by ~1 µm from the straight rest, where the reference's linear statics
  // hold, and its prestress (which this crane's unstiffened boom has not) changes the sag by ~3e-6.
  const scene::Scene scene = at_gravity(1e-3);
  const int elements = 16;
  auto equations = held_crane(scene, nodal::NodalCoordinates(scene::boom_beam(scene, elements)));
  const multibody::StaticEquilibrium statics =
      multibody::solve_static_equilibrium(*equations, equations->initial_guess(), 1e-13);
  const test::AFrameCrane reference = reference_of(scene);
  const test::AFrameStatic sag = test::elastic_static_deflection(reference, elements);
  // The tip's displacement in the boom's rest frame: A(β)(L + u, v) − (L, 0).
  const double beta = statics.z(equations->layout().heel), length = scene.boom.mesh.length;
  const Eigen::Vector2d tip = Eigen::Rotation2Dd(beta).toRotationMatrix() * (Eigen::Vector2d(length, 0.0) + statics.outputs.tip_deflection) -
                              Eigen::Vector2d(length, 0.0);
  EXPECT_NEAR(tip.x(), sag.tip_displacement.x(), 1e-5 * sag.tip_displacement.norm());
  EXPECT_NEAR(tip.y(), sag.tip_displacement.y(), 1e-5 * sag.tip_displacement.norm());
  const double luffing = test::rest_tensions(reference).luffing_tension + sag.luffing_tension_change;
  EXPECT_NEAR(statics.outputs.luffing_tension, luffing, 1e-8 * luffing);
  std::printf("sag at g = 0.001: tip (%.6e, %.6e) m (reference (%.6e, %.6e)), A-frame %.3e rad (%.3e), luffing %.9g N (%.9g)\n",
              tip.x(), tip.y(), sag.tip_displacement.x(), sag.tip_displacement.y(), statics.outputs.a_frame_rotation,
              sag.a_frame_rotation, statics.outputs.luffing_tension, luffing);
}

// A run of `duration` s sampled every 0.01 s with `kind` at rtol = atol = `tolerance`.
multibody::RunSettings run_settings(const scene::Scene& scene, solve::Integrator kind, double duration, double tolerance) {
  multibody::RunSettings settings;
  settings.kind = kind;
  settings.relative_tolerance = tolerance;
  settings.absolute_tolerance = tolerance;
  settings.duration = duration;
  settings.output_interval = 0.01;
  settings.monitor.boom_length = scene.boom.mesh.length;
  return settings;
}

// Runs the scene's crane (nodal N = 4) from its static equilibrium with the cargo raised by `lift` and
// released, with `kind` (CVODE: minimal coordinates; IDA: full ones).
multibody::RunResult released_cargo(const scene::Scene& scene, double lift, solve::Integrator kind, double duration) {
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 4});
  const multibody::StaticEquilibrium statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
  Eigen::VectorXd z0 = statics.z;
  z0(equations->cargo_offset() + 1) += lift;
  multibody::RunSettings settings = run_settings(scene, kind, duration, 1e-9);
  settings.monitor.wire_unstretched_length = scene.wire->unstretched_length;
  settings.monitor.static_tension = statics.outputs.wire_tension;
  return multibody::simulate(*equations, z0, settings);
}

scene::Scene calm(scene::Scene scene) {
  scene.wave.reset();
  return scene;
}

// How far two runs' histories of one output lie apart, against how far the first moves from its start.
struct Agreement {
  double difference = 0.0, range = 0.0;
};
template <class Extract>
Agreement agreement(const multibody::RunResult& a, const multibody::RunResult& b, Extract extract) {
  Agreement out;
  for (std::size_t i = 0; i < a.samples.size() && i < b.samples.size(); ++i) {
    out.difference = std::max(out.difference, std::abs(extract(a.samples[i]) - extract(b.samples[i])));
    out.range = std::max(out.range, std::abs(extract(a.samples[i]) - extract(a.samples[0])));
  }
  return out;
}
double rocking_of(const multibody::CraneOutputs& o) { return o.a_frame_rotation; }

TEST(AFrame, MinimalAndFullCoordinatesGiveOneMotion) {
  // The A-frame's pin eliminated (its angle a coordinate) or kept as two constraint rows with their
  // multipliers (IDA, index 2 reduced): the same A-frame rocking and cargo bounce.
  const scene::Scene scene = calm(a_frame_scene());
  const multibody::RunResult minimal = released_cargo(scene, 0.5, solve::Integrator::cvode, 6.0);
  const multibody::RunResult full = released_cargo(scene, 0.5, solve::Integrator::ida, 6.0);
  ASSERT_EQ(minimal.samples.size(), full.samples.size());
  const Agreement rocking = agreement(minimal, full, rocking_of);
  const Agreement heave = agreement(minimal, full, [](const multibody::CraneOutputs& o) { return o.cargo.y(); });
  double residual = 0.0;
  for (const multibody::CraneOutputs& o : full.samples) residual = std::max(residual, o.constraint_residual);
  EXPECT_GT(rocking.range, 1e-6);  // (the A-frame moves)
  EXPECT_LT(rocking.difference, 1e-4 * rocking.range);
  EXPECT_LT(heave.difference, 1e-4 * heave.range);
  EXPECT_LT(residual, 1e-6);
  std::printf("A-frame rocking range %.3e rad, minimal vs full %.2e; cargo heave range %.3f m, %.2e; |C| ≤ %.1e m\n", rocking.range,
              rocking.difference, heave.range, heave.difference, residual);
}

TEST(AFrame, OnADrivenDeckMinimalAndFullCoordinatesGiveOneMotion) {
  // The deck held out of the water and turned by a prescribed spin-up (0.05 rad/s reached in 4 s): the
  // A-frame's and the boom's pins move with it, so the driven base's acceleration enters both the
  // pinned bodies' known acceleration (minimal coordinates) and the pins' C_t, C_tt (full ones).
  const scene::Scene scene = calm(a_frame_scene());
  auto parameters = scene::build_crane_parameters(scene, nodal::NodalCoordinates(scene::boom_beam(scene, 4)));
  parameters.hull.fixed = true;
  parameters.hull.hydrostatics = false;
  parameters.hull.support_pose.setZero();
  multibody::PrescribedMotion spin;
  spin.profile = multibody::RotationProfile::spin_up;
  spin.spin_rate = 0.05;
  spin.spin_up_time = 4.0;
  parameters.hull.prescribed = spin;
  const auto model = multibody::make_crane_model(std::move(parameters));
  std::vector<multibody::RunResult> runs;
  for (const solve::Integrator kind : {solve::Integrator::cvode, solve::Integrator::ida}) {
    auto equations = model->equations();
    const multibody::StaticEquilibrium statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
    runs.push_back(multibody::simulate(*equations, statics.z, run_settings(scene, kind, 5.0, 1e-9)));
  }
  const multibody::RunResult &minimal = runs[0], &full = runs[1];
  ASSERT_EQ(minimal.samples.size(), full.samples.size());
  const Agreement rocking = agreement(minimal, full, rocking_of);
  const Agreement tip = agreement(minimal, full, [](const multibody::CraneOutputs& o) { return o.tip_deflection.y(); });
  EXPECT_GT(rocking.range, 1e-6);
  EXPECT_LT(rocking.difference, 1e-4 * rocking.range);
  EXPECT_LT(tip.difference, 1e-4 * tip.range);
  EXPECT_NEAR(minimal.samples.back().hull.z(), spin.pose(5.0).z(), 1e-12);
  std::printf("driven deck: A-frame rocking range %.3e rad, minimal vs full %.2e; tip range %.3e m, %.2e\n", rocking.range, rocking.difference,
              tip.range, tip.difference);
}

TEST(AFrame, TheEnergyIsConservedWithoutDamping) {
  // On the held hull, undamped, the A-frame, the boom and the cargo exchange a released lift's energy:
  // kinetic + gravity + strain + wires stays constant (a conservation law of the equations, not of
  // the integrator's accuracy alone: a wrong mass or force term of the A-frame would drift it).
  scene::Scene scene = undamped(calm(a_frame_scene()));
  scene.wire->damping_ratio = 0.0;
  auto parameters = scene::build_crane_parameters(scene, nodal::NodalCoordinates(scene::boom_beam(scene, 4)));
  parameters.hull.fixed = true;
  parameters.hull.hydrostatics = false;
  parameters.hull.support_pose.setZero();
  auto equations = multibody::make_crane_equations(std::move(parameters));
  const multibody::StaticEquilibrium statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
  Eigen::VectorXd z0 = statics.z;
  z0(equations->cargo_offset() + 1) += 0.2;  // (the wires stay taut)
  z0(equations->layout().bodies.at(1).minimal) += 1e-3;  // and the A-frame turned by a milliradian
  const multibody::RunResult run = multibody::simulate(*equations, z0, run_settings(scene, solve::Integrator::cvode, 5.0, 1e-11));
  const auto total = [](const multibody::CraneOutputs& o) {
    return o.kinetic_energy + o.gravity_energy + o.strain_energy + o.wire_energy + o.spring_energy;
  };
  const double start = total(run.samples.front());
  double drift = 0.0, exchanged = 0.0;
  for (const multibody::CraneOutputs& o : run.samples) {
    drift = std::max(drift, std::abs(total(o) - start));
    exchanged = std::max(exchanged, o.kinetic_energy);
  }
  EXPECT_GT(exchanged, 1e4);
  EXPECT_LT(drift, 1e-6 * exchanged);
  std::printf("undamped A-frame crane: kinetic energy up to %.4g J, total energy drift %.2e J (%.1e of it)\n", exchanged, drift,
              drift / exchanged);
}

TEST(AFrame, ADroppedLoadSlackensTheBackstaysAndTheRunNamesThem) {
  // The cargo raised 3 m and released: the boom whips up off its luffing wires, the A-frame loses the
  // pull that its backstays held it against and they go slack too, each named.
  const multibody::RunResult run = released_cargo(calm(a_frame_scene()), 3.0, solve::Integrator::cvode, 8.0);
  ASSERT_EQ(run.wire_names.size(), 5u);  // the hoist wire, the two backstays, the two luffing wires
  EXPECT_FALSE(run.backstay_events.empty());
  EXPECT_EQ(test::named_detections(run, solve::FailureKind::backstay_slack, {"backstay", "A-frame"}), 2) << "each backstay named";
  double least = std::numeric_limits<double>::infinity();
  for (const multibody::CraneOutputs& sample : run.samples) least = std::min(least, sample.backstay_tension);
  EXPECT_EQ(least, 0.0);
}

}  // namespace
}  // namespace ffrf
