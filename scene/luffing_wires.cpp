// The luffing wires' geometry and rest tension (scene/luffing_wires.hpp).
// Moment balance of the rigid boom about its heel B at boom.angle α on the level hull, the hoist
// wire hanging vertically from the tip: the wires' tension T (all of them) on the lever
// (P − B) × d, d the unit vector from the boom point P to the A-frame top, holds the boom's weight
// at L/2 and the cargo's at L:
//   T (P − B) × d = g (m_boom L/2 + m_cargo L) cos α,   each wire's stretch T / (n k), L0 = |F − P| − T / (n k),
// n wires, each a tackle of p parts of line of stiffness k₁ each: k = p k₁ (the blocks' separation
// stretches all p parts; each carries 1/p of the pull).
#include "scene/luffing_wires.hpp"

#include <fmt/format.h>

#include <cmath>

#include "scene/scene_key.hpp"

namespace ffrf::scene {

double tackle_stiffness(const Luffing& luffing) { return luffing.parts * luffing.stiffness; }

LuffingGeometry luffing_geometry(const Scene& scene) {
  const Luffing& luffing = *scene.luffing;
  const BoomMount& mount = *scene.boom.mount;
  LuffingGeometry g;
  g.a_frame = Eigen::Vector2d(luffing.a_frame_x, luffing.a_frame_y);
  g.heel = Eigen::Vector2d(mount.root_x, mount.root_y);
  const double length = scene.boom.mesh.length;
  g.attachment = luffing.attachment.value_or(length);
  const Eigen::Vector2d axis(std::cos(mount.angle), std::sin(mount.angle));
  g.boom_point = g.heel + g.attachment * axis;
  const Eigen::Vector2d span = g.a_frame - g.boom_point;
  g.length = span.norm();
  const Eigen::Vector2d direction = span / g.length;
  const Eigen::Vector2d arm = g.boom_point - g.heel;
  g.lever = arm.x() * direction.y() - arm.y() * direction.x();
  const double cargo_mass = scene.cargo ? scene.cargo->mass : 0.0;
  const double moment = scene.environment.gravity * (scene.boom.mesh.total_mass() * 0.5 * length + cargo_mass * length) *
                        std::cos(mount.angle);
  g.total_tension = g.lever > 0.0 ? moment / g.lever : 0.0;
  g.unstretched_length = luffing.unstretched_length.value_or(g.length - g.total_tension / (luffing.wires * tackle_stiffness(luffing)));
  return g;
}

std::vector<SceneFinding> luffing_findings(const Scene& scene) {
  std::vector<SceneFinding> found;
  const auto error = [&found](std::vector<std::string> keys, std::string message) {
    found.push_back({true, std::move(keys), std::move(message)});
  };
  const Luffing& luffing = *scene.luffing;
  const double length = scene.boom.mesh.length;
  if (luffing.attachment && *luffing.attachment > length) {
    error({scene_key("luffing.attachment"), scene_key("boom.length")},
          fmt::format("the wires' boom point lies beyond the tip (valid range [0, {:g}] m: boom.length)", length));
    return found;
  }
  const LuffingGeometry g = luffing_geometry(scene);
  if (!(g.lever > 1e-3 * length)) {
    error({scene_key("luffing.a_frame_y"), scene_key("luffing.a_frame_x"), scene_key("boom.angle")},
          fmt::format("the luffing wires cannot hold the boom up: from the boom point they must pull towards the hull side "
                      "above the boom's line (their lever about the heel is {:.3g} m); raise the A-frame top",
                      g.lever));
    return found;
  }
  if (!luffing.unstretched_length && !(g.unstretched_length > 0.5 * g.length)) {
    error({scene_key("luffing.stiffness"), scene_key("luffing.wires"), scene_key("luffing.parts")},
          fmt::format("the luffing wires are too soft to hold the boom at boom.angle: {:.4g} N of tension would stretch "
                      "them by {:.3g} m of their {:.3g} m (valid: less than half); stiffen them, add wires or reeve more parts",
                      g.total_tension, g.length - g.unstretched_length, g.length));
  }
  return found;
}

}  // namespace ffrf::scene
