// What a wire does in the crane — which output channels sum it and which detector names it when it
// goes slack: the hoist wire carries the cargo, the luffing wires hold a pinned boom, the backstays
// hold an A-frame pinned to the deck.
#pragma once

namespace ffrf::multibody {

enum class WireRole { hoist, luffing, backstay };

}  // namespace ffrf::multibody
