// The static equilibrium over cargo masses 1 t … 10 000 t, wires of 1e6 … 1e9 N/m and two hulls
// (the reference crane, 12 600 t on 90 × 40 m, and the large crane, 30 000 t on 150 × 45 m),
// judged by physics that does not come from the solver:
//  * the wire carries the cargo's weight (no water forces act on the cargo): T = m g;
//  * Archimedes: the trimmed box displaces L·B·(keel depth at mid-length)/cos θ of water, whose
//    mass equals hull + boom + cargo;
// and, where a hand estimate (linear hydrostatics of the box with the cargo's weight at the boom
// tip, the wire's stretch m g / k) says the lift is impossible — the hull would sink, a deck edge
// would go under, or the cargo would hang in the water — the failure names that reason. Cases within
// ±25 % of a limit by the hand estimate are left out: the estimate is linear, the model is not.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "multibody/planar.hpp"
#include "multibody/crane_run.hpp"
#include "scene/crane_builder.hpp"
#include "study/statics.hpp"
#include "study_test_support.hpp"

namespace statics_test {

using namespace ffrf;

// What the hand estimate expects of a lift.
enum class Expect { equilibrium, sinks, deck_under, cargo_in_water, unclear };

Expect hand_estimate(const scene::Scene& scene) {
  const scene::Hull& hull = *scene.hull;
  const scene::BoomMount& mount = *scene.boom.mount;
  const double rho = scene.environment.water_density, g = scene.environment.gravity;
  const double boom_mass = scene.boom.mesh.total_mass(), cargo = scene.cargo->mass;
  const double total = hull.mass + boom_mass + cargo;
  if (total >= rho * hull.length * hull.width * hull.depth) return Expect::sinks;
  const double draft = total / (rho * hull.length * hull.width);
  const double length = scene.boom.mesh.length;
  const double root_height = hull.g1_above_keel + mount.root_y, tip_height = root_height + length * std::sin(mount.angle);
  const double keel_to_g = (hull.mass * hull.g1_above_keel + boom_mass * (root_height + 0.5 * length * std::sin(mount.angle)) +
                            cargo * tip_height) / total;
  const double gm = 0.5 * draft + hull.length * hull.length / (12.0 * draft) - keel_to_g;  // KB + BM_L − KG
  const double mid = hull.g1_aft_of_mid_length, tip_x = mount.root_x + length * std::cos(mount.angle);
  const double moment = -hull.mass * mid + boom_mass * (mount.root_x + 0.5 * length * std::cos(mount.angle) - mid) + cargo * (tip_x - mid);
  const double trim = moment / (total * gm);
  const double deck_margin = (hull.depth - draft) / (0.5 * hull.length * std::abs(std::tan(trim)));
  const double cargo_bottom = tip_height - draft - (tip_x - mid) * trim - scene.wire->unstretched_length -
                              cargo * g / scene.wire->stiffness - scene.cargo->hook_y - 0.5 * scene.cargo->height;
  if (deck_margin < 0.75) return Expect::deck_under;
  if (cargo_bottom < -0.25 * tip_height) return Expect::cargo_in_water;
  if (deck_margin < 1.25 || cargo_bottom < 0.25 * tip_height) return Expect::unclear;
  return Expect::equilibrium;
}

struct Tally {
  int solved = 0, refused = 0, skipped = 0;
};

void sweep_hull(const std::string& file, Tally& tally) {
  scene::Scene scene = test::scene_file(file);
  const double g = scene.environment.gravity, rho = scene.environment.water_density;
  const scene::Hull& hull = *scene.hull;
  for (const double stiffness : {1e6, 1e7, 1e8, 1e9}) {
    for (const double tonnes : {1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0, 10000.0}) {
      scene.cargo->mass = tonnes * 1e3;
      scene.wire->stiffness = stiffness;
      const std::string label = file + ", cargo " + std::to_string(tonnes) + " t, wire " + std::to_string(stiffness) + " N/m";
      const Expect expect = hand_estimate(scene);
      if (expect == Expect::unclear) {
        ++tally.skipped;
        continue;
      }
      const scene::BoomChoice choice{scene::BoomKind::nodal, scene.boom.mesh.element_count, 0, false};
      try {
        const study::StaticsResult result = study::solve_statics(scene, choice);
        const multibody::CraneOutputs& o = result.statics.outputs;
        EXPECT_EQ(expect, Expect::equilibrium) << label << ": solved where the hand estimate says it cannot be";
        const double weight = scene.cargo->mass * g;
        EXPECT_NEAR(o.wire_tension, weight, 1e-7 * weight) << label;
        EXPECT_NEAR(result.wire_stretch, weight / stiffness, 1e-7 * weight / stiffness + 1e-12) << label;
        const Eigen::Vector2d keel_mid =
            o.hull.head<2>() + multibody::rotation(o.hull.z()) * Eigen::Vector2d(hull.g1_aft_of_mid_length, -hull.g1_above_keel);
        const double displaced = rho * hull.length * hull.width * (-keel_mid.y()) / std::cos(o.hull.z());
        const double total = hull.mass + scene.boom.mesh.total_mass() + scene.cargo->mass;
        EXPECT_NEAR(displaced, total, 1e-9 * total) << label;
        EXPECT_LT(result.statics.scaled_residual, 1e-9) << label;
        ++tally.solved;
      } catch (const solve::SolverFailure& failure) {
        ++tally.refused;
        const std::string said = failure.cause();
        switch (expect) {
          case Expect::deck_under:
            EXPECT_TRUE(failure.kind() == solve::FailureKind::deck_submerged ||
                        (failure.kind() == solve::FailureKind::newton_divergence && said.find("the hull's") != std::string::npos))
                << label << ": " << failure.what();
            break;
          case Expect::cargo_in_water:
            EXPECT_EQ(failure.kind(), solve::FailureKind::cargo_in_water) << label << ": " << failure.what();
            break;
          default:
            ADD_FAILURE() << label << ": no equilibrium where the hand estimate finds one: " << failure.what();
        }
      } catch (const scene::SceneError& error) {
        ++tally.refused;
        EXPECT_EQ(expect, Expect::sinks) << label << ": " << error.what();
        EXPECT_NE(std::string(error.what()).find("sink"), std::string::npos) << error.what();
      }
    }
  }
}

TEST(Statics, CargoMassSweepOnTwoHullsMatchesTheWeightAndArchimedes) {
  Tally tally;
  sweep_hull("paper_floating_crane.toml", tally);
  sweep_hull("large_crane.toml", tally);
  // The sweep has to exercise both outcomes, not skip its way through.
  EXPECT_GE(tally.solved, 50);
  EXPECT_GE(tally.refused, 4);
  EXPECT_LE(tally.skipped, 12);
}

// The lift of the large crane with a 20 t and a 100 t cargo (a 300 t one worked before): light
// loads on the stiff wire solve by Newton from the rest pose, without the continuation.
TEST(Statics, LightCargoOnTheLargeCraneSolvesDirectly) {
  scene::Scene scene = test::scene_file("large_crane.toml");
  for (const double tonnes : {20.0, 100.0}) {
    scene.cargo->mass = tonnes * 1e3;
    const study::StaticsResult result = study::solve_statics(scene, {scene::BoomKind::nodal, 16, 0, false});
    EXPECT_FALSE(result.path.by_continuation()) << tonnes << " t";
    EXPECT_LE(result.statics.newton_iterations, 30) << tonnes << " t";
    EXPECT_NEAR(result.statics.outputs.wire_tension, scene.cargo->mass * scene.environment.gravity,
                1e-8 * scene.cargo->mass * scene.environment.gravity);
  }
}

// A hull that cannot float its load (its own mass raised past the box's buoyancy behind the scene
// checks' back): the failure names the hull's heave force, not slack or buckling.
TEST(Statics, AHullThatCannotFloatTheLoadIsNamed) {
  const scene::Scene scene = test::scene_file("large_crane.toml");
  auto model = scene::build_crane_parameters(scene, nodal::NodalCoordinates(scene::boom_beam(scene, 4)));
  const scene::Hull& hull = *scene.hull;
  model.hull.mass = 1.2 * scene.environment.water_density * hull.length * hull.width * hull.depth;
  auto equations = multibody::make_crane_equations(std::move(model));
  try {
    multibody::solve_static_equilibrium(*equations, equations->initial_guess());
    ADD_FAILURE() << "a hull heavier than its buoyancy found an equilibrium";
  } catch (const solve::SolverFailure& failure) {
    const std::string said = failure.what();
    EXPECT_NE(said.find("the hull's heave force"), std::string::npos) << said;
    EXPECT_NE(said.find("cannot float the load"), std::string::npos) << said;
    EXPECT_EQ(said.find("buckling"), std::string::npos) << said;
  }
}

// The continuation in the load, from a start Newton does not converge from within its 200 iterations
// (the hull pitched 0.05 rad and 3 m low, the cargo 20 m above its hanging place): it reaches the
// equilibrium Newton finds from the rest pose.
TEST(Statics, ContinuationFromAPoorStartReachesTheSameEquilibrium) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 16, 0, false});
  multibody::StaticSolvePath direct_path, poor_path;
  const multibody::StaticEquilibrium direct =
      multibody::solve_static_equilibrium(*equations, equations->initial_guess(), direct_path);
  Eigen::VectorXd poor = equations->initial_guess();
  poor(1) -= 3.0;
  poor(2) += 0.05;
  poor(equations->cargo_offset() + 1) += 20.0;
  const multibody::StaticEquilibrium reached = multibody::solve_static_equilibrium(*equations, poor, poor_path);
  EXPECT_FALSE(direct_path.by_continuation());
  EXPECT_TRUE(poor_path.by_continuation());
  EXPECT_NEAR(reached.outputs.cargo.y(), direct.outputs.cargo.y(), 1e-8);
  EXPECT_NEAR(reached.outputs.hull.z(), direct.outputs.hull.z(), 1e-10);
  EXPECT_NEAR(reached.outputs.wire_tension, scene.cargo->mass * scene.environment.gravity, 1e-7 * reached.outputs.wire_tension);
}

// The reference crane on a 120 m wire: its cargo would hang 16 m into the water, which the model
// gives no forces; the equilibrium is refused by that name.
TEST(Statics, CargoBelowTheWaterIsNamed) {
  scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  scene.wire->unstretched_length = 120.0;
  try {
    study::solve_statics(scene, {scene::BoomKind::nodal, 16, 0, false});
    ADD_FAILURE() << "a cargo in the water was accepted";
  } catch (const solve::SolverFailure& failure) {
    EXPECT_EQ(failure.kind(), solve::FailureKind::cargo_in_water) << failure.what();
  }
}

}  // namespace statics_test
