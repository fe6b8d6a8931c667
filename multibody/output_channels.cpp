// The crane's output-channel table (see output_channels.hpp).
#include "multibody/output_channels.hpp"

#include <array>
#include <numbers>

namespace ffrf::multibody {
namespace {

constexpr double degrees = 180.0 / std::numbers::pi;

// name, column, title, display unit, SI unit, display scale, about static, judged, SI value.
constexpr std::array channels{
    OutputChannelSpec{"crane_surge", "crane_surge_m", "crane surge", "m", "m", 1.0, true, false,
                      [](const CraneOutputs& o) { return o.hull.x(); }},
    OutputChannelSpec{"crane_heave", "crane_heave_m", "crane heave", "m", "m", 1.0, true, true,
                      [](const CraneOutputs& o) { return o.hull.y(); }},
    OutputChannelSpec{"crane_pitch", "crane_pitch_deg", "crane pitch", "deg", "rad", degrees, true, true,
                      [](const CraneOutputs& o) { return o.hull.z(); }},
    OutputChannelSpec{"cargo_surge", "cargo_surge_m", "cargo surge", "m", "m", 1.0, true, false,
                      [](const CraneOutputs& o) { return o.cargo.x(); }},
    OutputChannelSpec{"cargo_heave", "cargo_heave_m", "cargo heave", "m", "m", 1.0, true, true,
                      [](const CraneOutputs& o) { return o.cargo.y(); }},
    OutputChannelSpec{"cargo_pitch", "cargo_pitch_deg", "cargo pitch", "deg", "rad", degrees, true, true,
                      [](const CraneOutputs& o) { return o.cargo.z(); }},
    OutputChannelSpec{"tip_axial", "tip_axial_m", "boom tip axial deflection", "m", "m", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.tip_deflection.x(); }},
    OutputChannelSpec{"tip_deflection", "tip_transverse_m", "boom tip transverse deflection", "m", "m", 1.0, false, true,
                      [](const CraneOutputs& o) { return o.tip_deflection.y(); }},
    OutputChannelSpec{"wire_tension", "wire_tension_N", "wire tension", "N", "N", 1.0, false, true,
                      [](const CraneOutputs& o) { return o.wire_tension; }},
    OutputChannelSpec{"joint_force_x", "joint_force_x_N", "joint force x at B", "N", "N", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.joint_reaction.x(); }},
    OutputChannelSpec{"joint_force_y", "joint_force_y_N", "joint force y at B", "N", "N", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.joint_reaction.y(); }},
    OutputChannelSpec{"joint_moment", "joint_moment_Nm", "joint bending moment at B", "N m", "N m", 1.0, false, true,
                      [](const CraneOutputs& o) { return o.joint_reaction.z(); }},
    OutputChannelSpec{"constraint_residual", "constraint_residual_m", "constraint residual", "m", "m", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.constraint_residual; }},
    OutputChannelSpec{"kinetic_energy", "kinetic_energy_J", "kinetic energy", "J", "J", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.kinetic_energy; }},
    OutputChannelSpec{"gravity_energy", "gravity_energy_J", "gravity energy", "J", "J", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.gravity_energy; }},
    OutputChannelSpec{"strain_energy", "strain_energy_J", "strain energy", "J", "J", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.strain_energy; }},
    OutputChannelSpec{"wire_energy", "wire_energy_J", "wire energy", "J", "J", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.wire_energy; }},
    OutputChannelSpec{"spring_energy", "spring_energy_J", "spring energy", "J", "J", 1.0, false, false,
                      [](const CraneOutputs& o) { return o.spring_energy; }},
};

}  // namespace

std::span<const OutputChannelSpec> output_channels() { return channels; }

}  // namespace ffrf::multibody
