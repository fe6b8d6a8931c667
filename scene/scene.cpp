// Names of the scene's enumerations (scene/scene.hpp).
#include "scene/scene.hpp"

namespace ffrf::scene {

std::string_view to_string(Stiffening stiffening) {
  switch (stiffening) {
    case Stiffening::none: return "none";
    case Stiffening::static_load: return "static";
    case Stiffening::centrifugal: return "centrifugal";
    case Stiffening::both: return "both";
  }
  return "?";
}

std::optional<Stiffening> parse_stiffening(std::string_view text) {
  for (Stiffening s : {Stiffening::none, Stiffening::static_load, Stiffening::centrifugal, Stiffening::both}) {
    if (text == to_string(s)) return s;
  }
  return std::nullopt;
}

}  // namespace ffrf::scene
