// How a modal boom's stresses are recovered from its elastic coordinates (multibody/boom_stress.hpp):
// mode displacement (the modes' own deflection Φη) or mode acceleration (that plus the nodal model's
// static response to every load the modes leave unbalanced). docs/theory.md §13.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace ffrf::multibody {

enum class StressRecovery { mode_displacement, mode_acceleration };
inline constexpr std::array<StressRecovery, 2> all_stress_recoveries{StressRecovery::mode_displacement,
                                                                     StressRecovery::mode_acceleration};
std::string_view to_string(StressRecovery method);  // "displacement", "acceleration"
std::optional<StressRecovery> parse_stress_recovery(std::string_view text);
std::string stress_recovery_choices();  // "displacement|acceleration"

}  // namespace ffrf::multibody
