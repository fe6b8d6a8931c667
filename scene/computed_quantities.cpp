// The computed quantities' notes (see computed_quantities.hpp).
#include "scene/computed_quantities.hpp"

#include <array>
#include <utility>

namespace ffrf::scene {
namespace {

constexpr std::string_view kFloating =
    "computed, not set: the static equilibrium floats the hull's box (hull.length, hull.width) in water of "
    "environment.water_density under the weight of the hull, the boom and the cargo (hull.mass, "
    "boom.mass_per_length or boom.density, cargo.mass) and the boom's moment (boom.angle, "
    "hull.g1_aft_of_mid_length); change those to change it. `ffrf run` prints the draft and trim under \"static "
    "equilibrium\"";
constexpr std::string_view kTension =
    "computed, not set: the wire's static tension is the cargo's weight (cargo.mass times environment.gravity); "
    "change cargo.mass to change it. `ffrf run` prints it under \"static equilibrium\"";
constexpr std::string_view kStretch =
    "computed, not set: the wire's static stretch is its static tension (the cargo's weight) over wire.stiffness; "
    "change wire.unstretched_length, wire.stiffness or cargo.mass. `ffrf run` prints it under \"static equilibrium\"";

constexpr std::array<std::pair<std::string_view, std::string_view>, 10> kNotes{{
    {"hull.draft", kFloating},
    {"hull.trim", kFloating},
    {"hull.trim_deg", kFloating},
    {"hull.displacement", kFloating},
    {"hull.displaced_mass", kFloating},
    {"hull.displaced_volume", kFloating},
    {"hull.freeboard", kFloating},
    {"wire.tension", kTension},
    {"wire.static_tension", kTension},
    {"wire.stretch", kStretch},
}};

}  // namespace

std::optional<std::string_view> computed_quantity_note(std::string_view dotted_name) {
  for (const auto& [name, note] : kNotes) {
    if (name == dotted_name) return note;
  }
  return std::nullopt;
}

}  // namespace ffrf::scene
