// Quantities a user may try to set in a scene that ffrf computes instead: the hull's draft, trim and
// displacement follow from its box and the masses it floats (the static equilibrium), the wire's
// static tension from the cargo's weight, its stretch from that tension and its stiffness. The loader
// answers such a key with what it is computed from and which keys change it, instead of a bare
// "unknown key".
#pragma once

#include <optional>
#include <string_view>

namespace ffrf::scene {

// Why `dotted_name` ("hull.draft") is not a scene key and how to change the quantity; nullopt when
// it names nothing ffrf computes.
std::optional<std::string_view> computed_quantity_note(std::string_view dotted_name);

}  // namespace ffrf::scene
