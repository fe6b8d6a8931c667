// The free-free mode set on the paper's clamped crane: taken in the heel's tangent frame, its shapes
// satisfy the clamp, so with most of its modes the modal boom spans the nodal boom's space and the
// crane's lowest frequencies match the nodal crane's (a second method: nodal coordinates) and the
// exact cantilever's first bending frequency, β₁L = 1.8751 (Euler–Bernoulli). The crane is the
// shipped scene's with its hull held, no gravity, no cargo and no hoist wire: a bare cantilever.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "fem/analytic_beam.hpp"
#include "held_boom.hpp"
#include "modal/modal_coordinates.hpp"
#include "multibody/crane_model.hpp"
#include "multibody/linearisation.hpp"
#include "nodal/nodal_coordinates.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf {
namespace {

template <class Parameters>
std::unique_ptr<multibody::CraneEquations> bare_cantilever(Parameters model) {
  model.gravity = 0.0;
  return test::held_boom(std::move(model), Eigen::Vector3d::Zero());
}

Eigen::VectorXd lowest_frequencies(multibody::CraneEquations& equations, int count) {
  return test::natural_frequencies(equations, Eigen::VectorXd::Zero(equations.minimal_size())).head(count);
}

TEST(ModeSets, TheFreeFreeSetOnAClampedBoomReachesTheNodalAndExactFrequencies) {
  scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  scene.boom.damping_ratio = 0.0;
  const int elements = 16;
  auto nodal = bare_cantilever(scene::build_crane_parameters(scene, nodal::NodalCoordinates(scene::boom_beam(scene, elements))));
  scene::BoomChoice choice{scene::BoomKind::modal, elements, 40, true};
  choice.mode_set = fem::Boundary::free_free;
  auto modal = bare_cantilever(scene::build_crane_parameters(scene, scene::modal_coordinates(scene, choice)));
  const Eigen::VectorXd reference = lowest_frequencies(*nodal, 4);
  const Eigen::VectorXd free_free = lowest_frequencies(*modal, 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(free_free(i), reference(i), 1e-6 * reference(i)) << "mode " << i + 1;
  const double exact = fem::analytic_bending_modes(scene.boom.mesh, fem::Boundary::clamped_free, 1)[0].angular_frequency;
  EXPECT_NEAR(free_free(0), exact, 1e-6 * exact);
  std::printf("first bending: free-free set %.9f rad/s, nodal %.9f, exact %.9f\n", free_free(0), reference(0), exact);

  // Few modes: still a cantilever's shapes, so the first frequency is bounded from below by the exact one.
  choice.modes = 2;
  choice.static_modes = false;
  auto few = bare_cantilever(scene::build_crane_parameters(scene, scene::modal_coordinates(scene, choice)));
  const double first = lowest_frequencies(*few, 1)(0);
  EXPECT_GT(first, exact * (1.0 - 1e-9));
  std::printf("k = 2 free-free: first bending %.6f rad/s (+%.2e over the exact)\n", first, first / exact - 1.0);
}

}  // namespace
}  // namespace ffrf
