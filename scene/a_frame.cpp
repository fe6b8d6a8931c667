// The A-frame's geometry and its backstays' rest tension (scene/a_frame.hpp).
// Moment balance of the A-frame about its pin P on the level hull, the boom rigid at boom.angle: the
// luffing wires' tension T_L pulls its top T towards their boom point along d_L, its weight m g acts at
// its centre G = (P + T)/2, and the backstays' tension T_B pulls T towards the deck point D along d_B:
//   (T − P) × (T_L d_L) + (G − P) × (0, −m g) + T_B (T − P) × d_B = 0,
// so T_B = −[(T − P) × (T_L d_L) − m g (G − P)_x] / ((T − P) × d_B), each backstay stretched by
// T_B / (n k), L0 = |D − T| − T_B / (n k). Damping: the fraction ζ of critical for the A-frame's inertia
// about its pin, I_P = m (ρ² + h²/4), on the backstays' rotational stiffness n k lever², shared by n wires
// at the lever: c = 2 ζ √(n k lever² I_P) / (n lever²).
#include "scene/a_frame.hpp"

#include <fmt/format.h>

#include <cmath>

#include "scene/luffing_wires.hpp"
#include "solve/second_order_system.hpp"
#include "scene/scene_key.hpp"

namespace ffrf::scene {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

AFrameGeometry a_frame_geometry(const Scene& scene) {
  const AFrame& a_frame = *scene.a_frame;
  const Backstay& backstay = *scene.backstay;
  const LuffingGeometry luffing = luffing_geometry(scene);
  AFrameGeometry g;
  g.pin = Eigen::Vector2d(a_frame.pin_x, a_frame.pin_y);
  g.top = luffing.a_frame;
  g.centre = 0.5 * (g.pin + g.top);
  const Eigen::Vector2d span = g.top - g.pin;
  g.height = span.norm();
  g.angle = std::atan2(span.y(), span.x());
  const double radius = a_frame.radius_of_gyration.value_or(g.height / std::sqrt(12.0));
  g.rotary_inertia = a_frame.mass * radius * radius;
  g.inertia_about_pin = g.rotary_inertia + a_frame.mass * 0.25 * g.height * g.height;
  g.deck = Eigen::Vector2d(backstay.deck_x, backstay.deck_y);
  const Eigen::Vector2d stay = g.deck - g.top;
  g.backstay_length = stay.norm();
  const Eigen::Vector2d stay_direction = stay / g.backstay_length;
  g.backstay_lever = cross(span, stay_direction);
  const Eigen::Vector2d luffing_direction = (luffing.boom_point - g.top) / luffing.length;  // on the top, towards the boom
  const double luffing_moment = cross(span, luffing.total_tension * luffing_direction);
  const double weight_moment = cross(g.centre - g.pin, Eigen::Vector2d(0.0, -a_frame.mass * scene.environment.gravity));
  g.backstay_tension = g.backstay_lever != 0.0 ? -(luffing_moment + weight_moment) / g.backstay_lever : 0.0;
  g.backstay_unstretched_length =
      backstay.unstretched_length.value_or(g.backstay_length - g.backstay_tension / (backstay.wires * backstay.stiffness));
  const double lever_squared = g.backstay_lever * g.backstay_lever;
  if (lever_squared > 0.0) {
    const double rotational_stiffness = backstay.wires * backstay.stiffness * lever_squared;
    g.backstay_damping =
        backstay.damping_ratio * 2.0 * std::sqrt(rotational_stiffness * g.inertia_about_pin) / (backstay.wires * lever_squared);
  }
  return g;
}

std::vector<SceneFinding> a_frame_findings(const Scene& scene) {
  std::vector<SceneFinding> found;
  const auto error = [&found](std::vector<std::string> keys, std::string message) {
    found.push_back({true, std::move(keys), std::move(message)});
  };
  const AFrameGeometry g = a_frame_geometry(scene);
  if (!(g.height > 0.1)) {
    error({scene_key("a_frame.pin_x"), scene_key("a_frame.pin_y"), scene_key("luffing.a_frame_x"), scene_key("luffing.a_frame_y")},
          fmt::format("the A-frame's pin lies at its top ({:.3g} m apart; valid: more than 0.1 m): give the foot pin on the deck "
                      "below the top",
                      g.height));
    return found;
  }
  if (!(g.backstay_length > 0.1)) {
    error({scene_key("backstay.deck_x"), scene_key("backstay.deck_y")},
          fmt::format("the backstays' deck point lies at the A-frame top ({:.3g} m apart; valid: more than 0.1 m)", g.backstay_length));
    return found;
  }
  if (!(g.backstay_tension > 0.0) || !(std::abs(g.backstay_lever) > 1e-3 * g.height)) {
    error({scene_key("backstay.deck_x"), scene_key("backstay.deck_y"), scene_key("a_frame.pin_x")},
          fmt::format("the backstays cannot hold the A-frame against the luffing wires: at rest they would have to push "
                      "({:.4g} N; valid: a positive tension); their lever about the pin is {:.3g} m: put the deck point on "
                      "the side of the A-frame away from the boom",
                      g.backstay_tension, g.backstay_lever));
    return found;
  }
  const Backstay& backstay = *scene.backstay;
  // Every wire is an event function of the solvers (solve::max_events of them): the hoist wire, the
  // luffing wires and the backstays together.
  const int wires = (scene.cargo ? 1 : 0) + scene.luffing->wires + backstay.wires;
  if (wires > solve::max_events) {
    error({scene_key("backstay.wires"), scene_key("luffing.wires")},
          fmt::format("the crane would have {} wires (the hoist wire, {} luffing wires and {} backstays); at most {} are tracked "
                      "(valid: luffing.wires + backstay.wires ≤ {}): fewer, stiffer wires",
                      wires, scene.luffing->wires, backstay.wires, solve::max_events, solve::max_events - (scene.cargo ? 1 : 0)));
    return found;
  }
  if (backstay.unstretched_length && *backstay.unstretched_length >= g.backstay_length) {
    found.push_back({false, {scene_key("backstay.unstretched_length")},
                     fmt::format("the backstays are slack at the A-frame's built pose (unstretched {:.4g} m, {:.4g} m from its top to "
                                 "the deck point): the A-frame leans forward on its pin until they hold it",
                                 *backstay.unstretched_length, g.backstay_length)});
  }
  if (!backstay.unstretched_length && !(g.backstay_unstretched_length > 0.5 * g.backstay_length)) {
    error({scene_key("backstay.stiffness"), scene_key("backstay.wires")},
          fmt::format("the backstays are too soft to hold the A-frame: {:.4g} N of tension would stretch them by {:.3g} m of "
                      "their {:.3g} m (valid: less than half); stiffen them or add wires",
                      g.backstay_tension, g.backstay_length - g.backstay_unstretched_length, g.backstay_length));
  }
  return found;
}

}  // namespace ffrf::scene
