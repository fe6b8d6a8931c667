// `ffrf modes` of a pinned boom as the crane supports it (study/supported_boom.hpp) against an
// independent model (tests/multibody/pinned_boom_reference.hpp: its own frame finite elements of a
// pinned beam on an elastic support, nothing of fem/ or multibody/), on the shipped pinned crane
// with its luffing wires leaving the tip towards the A-frame.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "../multibody/pinned_boom_reference.hpp"
#include "scene/luffing_wires.hpp"
#include "scene/scene_loader.hpp"
#include "study/modes.hpp"
#include "study/supported_boom.hpp"

namespace ffrf {
namespace {

scene::Scene pinned_scene() { return scene::load_scene(FFRF_SOURCE_DIR "/cases/pinned_luffing_crane.toml"); }

// The reference boom of the scene: its section, the wires' total stiffness along the line from the
// tip to the A-frame in the boom's frame, and the static tension the supported boom reports.
test::PinnedBoom reference_boom(const scene::Scene& scene, double tension) {
  const double angle = scene.boom.mount->angle, length = scene.boom.mesh.length;
  const Eigen::Vector2d heel(scene.boom.mount->root_x, scene.boom.mount->root_y);
  const Eigen::Matrix2d frame = Eigen::Rotation2Dd(angle).toRotationMatrix();
  const Eigen::Vector2d tip = heel + frame * Eigen::Vector2d(length, 0.0);
  const Eigen::Vector2d to_a_frame = Eigen::Vector2d(scene.luffing->a_frame_x, scene.luffing->a_frame_y) - tip;
  test::PinnedBoom boom;
  boom.length = length;
  boom.EI = scene.boom.mesh.section.bending_rigidity();
  boom.EA = scene.boom.mesh.section.axial_rigidity();
  boom.mass_per_length = scene.boom.mesh.section.mass_per_length;
  boom.wire_stiffness = scene::tackle_stiffness(*scene.luffing) * scene.luffing->wires;
  boom.wire_direction_local = frame.transpose() * to_a_frame.normalized();
  boom.wire_length = to_a_frame.norm();
  boom.wire_tension = tension;
  return boom;
}

TEST(SupportedBoom, FrequenciesMatchAPinnedBeamOnTheWiresSpring) {
  // Under a small gravity (1e-4 m/s²) the boom barely moves from its drawn posture and its weight
  // barely loads it: the linearisation about that equilibrium is the reference's straight beam with
  // the wires' pretension (their tension T over their length ℓ as a transverse spring).
  scene::Scene scene = pinned_scene();
  scene.environment.gravity = 1e-4;
  scene.boom.stiffening = scene::Stiffening::none;
  const int elements = 16, count = 6;
  const auto supported = study::supported_boom_modes(scene, elements, count);
  ASSERT_TRUE(supported.has_value());
  ASSERT_EQ(supported->modes.size(), static_cast<std::size_t>(count));
  EXPECT_GT(supported->luffing_tension, 0.0);
  const test::PinnedBoom boom = reference_boom(scene, supported->luffing_tension);
  const test::PinnedBoomModes reference = test::natural_modes_fe(boom, elements);
  for (int j = 0; j < count; ++j) {
    const double hz = reference.omega(j) / (2.0 * std::numbers::pi);
    EXPECT_NEAR(supported->modes[static_cast<std::size_t>(j)].hz, hz, 1e-6 * hz) << "mode " << j + 1;
    // The axial modes are the reference's too (its share of kinetic energy in the u DOFs).
    EXPECT_EQ(supported->modes[static_cast<std::size_t>(j)].kind == study::SupportedBoomMode::Kind::axial,
              reference.axial_fraction(j) > 0.5)
        << "mode " << j + 1;
  }
}

TEST(SupportedBoom, StiffWiresMakeTheSpanSimplySupported) {
  // Wires and a boom section 10⁴ times stiffer along their lines hold the tip (the wires leave it
  // 23° off the boom's axis, so the tip's transverse motion is held by the wires and the boom's axial
  // stiffness together): the bending modes approach the pinned–pinned span's (nπ)² √(EI/ρA L⁴)
  // (within k_bending / k_support ~ 3e-4 for the second), and the boom's swing about its heel is no
  // longer its lowest mode. Under a tenth of the weight (g = 1 m/s²: the weight that tensions the
  // wires also turns and loads the boom, which shifts its modes by ~1 % at 9.81 m/s²).
  scene::Scene scene = pinned_scene();
  scene.environment.gravity = 1.0;
  scene.boom.stiffening = scene::Stiffening::none;
  scene.luffing->stiffness *= 1e4;
  scene.boom.mesh.section.area *= 1e4;
  const auto supported = study::supported_boom_modes(scene, 32, 6);
  ASSERT_TRUE(supported.has_value());
  int bending = 0;
  for (const study::SupportedBoomMode& mode : supported->modes) {
    if (mode.kind != study::SupportedBoomMode::Kind::bending) continue;
    ++bending;
    if (mode.bending_order <= 3) {
      EXPECT_NEAR(mode.hz / mode.pinned_pinned_hz, 1.0, 2e-3) << "bending mode " << mode.bending_order;
    }
    std::printf("bending mode %d: %.6f Hz, pinned-pinned %.6f Hz\n", mode.bending_order, mode.hz, mode.pinned_pinned_hz);
  }
  EXPECT_GE(bending, 3);
  EXPECT_EQ(supported->modes.front().kind, study::SupportedBoomMode::Kind::bending);
}

TEST(SupportedBoom, OnlyAPinnedBoomHasThem) {
  const scene::Scene clamped = scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  EXPECT_FALSE(study::supported_boom_modes(clamped, 16, 6).has_value());
  // The scene as shipped (g = 9.81 m/s²): the modes command's result carries them.
  const scene::Scene scene = pinned_scene();
  study::ModesResult result = study::solve_modes(scene.boom.mesh, fem::Boundary::clamped_free, modal::EigenSolverKind::arpack, 6);
  study::add_supported_boom(scene, 6, result);
  ASSERT_TRUE(result.supported.has_value());
  EXPECT_TRUE(result.warnings.empty());
  // Its lowest mode is the boom swinging on its wires, below the clamped-free boom's first bending mode.
  EXPECT_EQ(result.supported->modes.front().kind, study::SupportedBoomMode::Kind::swing);
}

}  // namespace
}  // namespace ffrf
