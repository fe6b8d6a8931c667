// The crane's output-channel table (see output_channels.hpp).
#include "multibody/output_channels.hpp"

#include <array>
#include <string>
#include <numbers>

namespace ffrf::multibody {
namespace {

constexpr double degrees = 180.0 / std::numbers::pi;

// name, column, title, display unit, SI unit, display scale, about static, judged, linear (RAO) name,
// SI value.
constexpr std::array channels{
    OutputChannelSpec{"crane_surge", "crane_surge_m", "crane surge", "m", "m", 1.0, true, false, "hull_surge",
                      [](const CraneOutputs& o) { return o.hull.x(); }},
    OutputChannelSpec{"crane_heave", "crane_heave_m", "crane heave", "m", "m", 1.0, true, true, "hull_heave",
                      [](const CraneOutputs& o) { return o.hull.y(); }},
    OutputChannelSpec{"crane_pitch", "crane_pitch_deg", "crane pitch", "deg", "rad", degrees, true, true, "hull_pitch",
                      [](const CraneOutputs& o) { return o.hull.z(); }},
    OutputChannelSpec{"cargo_surge", "cargo_surge_m", "cargo surge", "m", "m", 1.0, true, false, "cargo_surge",
                      [](const CraneOutputs& o) { return o.cargo.x(); }},
    OutputChannelSpec{"cargo_heave", "cargo_heave_m", "cargo heave", "m", "m", 1.0, true, true, "cargo_heave",
                      [](const CraneOutputs& o) { return o.cargo.y(); }},
    OutputChannelSpec{"cargo_pitch", "cargo_pitch_deg", "cargo pitch", "deg", "rad", degrees, true, true, "cargo_pitch",
                      [](const CraneOutputs& o) { return o.cargo.z(); }},
    OutputChannelSpec{"tip_axial", "tip_axial_m", "boom tip axial deflection", "m", "m", 1.0, false, false, "tip_axial",
                      [](const CraneOutputs& o) { return o.tip_deflection.x(); }},
    OutputChannelSpec{"tip_deflection", "tip_transverse_m", "boom tip transverse deflection", "m", "m", 1.0, false, true, "tip_transverse",
                      [](const CraneOutputs& o) { return o.tip_deflection.y(); }},
    OutputChannelSpec{"wire_tension", "wire_tension_N", "wire tension", "N", "N", 1.0, false, true, "wire_tension",
                      [](const CraneOutputs& o) { return o.wire_tension; }},
    OutputChannelSpec{"luffing_tension", "luffing_tension_N", "luffing wires' tension", "N", "N", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.luffing_tension; }},
    OutputChannelSpec{"joint_force_x", "joint_force_x_N", "joint force x at B", "N", "N", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.joint_reaction.x(); }},
    OutputChannelSpec{"joint_force_y", "joint_force_y_N", "joint force y at B", "N", "N", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.joint_reaction.y(); }},
    OutputChannelSpec{"joint_moment", "joint_moment_Nm", "joint bending moment at B", "N m", "N m", 1.0, false, true, "",
                      [](const CraneOutputs& o) { return o.joint_reaction.z(); }},
    OutputChannelSpec{"constraint_residual", "constraint_residual_m", "constraint residual", "m", "m", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.constraint_residual; }},
    OutputChannelSpec{"kinetic_energy", "kinetic_energy_J", "kinetic energy", "J", "J", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.kinetic_energy; }},
    OutputChannelSpec{"gravity_energy", "gravity_energy_J", "gravity energy", "J", "J", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.gravity_energy; }},
    OutputChannelSpec{"strain_energy", "strain_energy_J", "strain energy", "J", "J", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.strain_energy; }},
    OutputChannelSpec{"wire_energy", "wire_energy_J", "wire energy", "J", "J", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.wire_energy; }},
    OutputChannelSpec{"spring_energy", "spring_energy_J", "spring energy", "J", "J", 1.0, false, false, "",
                      [](const CraneOutputs& o) { return o.spring_energy; }},
};

constexpr int count_linear_rows() {
  int count = 0;
  for (const OutputChannelSpec& row : channels) count += row.linear_name.empty() ? 0 : 1;
  return count;
}
static_assert(count_linear_rows() == linear_output_count, "one LinearOutput per row with a linear name");

// The rows with a linear name, in table order (the order of LinearOutput).
std::array<const OutputChannelSpec*, linear_output_count> find_linear_rows() {
  std::array<const OutputChannelSpec*, linear_output_count> rows{};
  std::size_t next = 0;
  for (const OutputChannelSpec& row : channels) {
    if (!row.linear_name.empty()) rows[next++] = &row;
  }
  return rows;
}

}  // namespace

std::span<const OutputChannelSpec> output_channels() { return channels; }

const OutputChannelSpec& linear_channel(LinearOutput output) {
  static const std::array<const OutputChannelSpec*, linear_output_count> rows = find_linear_rows();
  return *rows[static_cast<std::size_t>(output)];
}

std::string_view to_string(LinearOutput output) { return linear_channel(output).linear_name; }

std::string_view unit_per_amplitude(LinearOutput output) {
  // The SI unit per metre of wave amplitude ("m/m", "rad/m", "N/m"), made once per output.
  static const std::array<std::string, linear_output_count> units = [] {
    std::array<std::string, linear_output_count> made;
    for (int i = 0; i < linear_output_count; ++i) made[i] = std::string(linear_channel(static_cast<LinearOutput>(i)).si_unit) + "/m";
    return made;
  }();
  return units[static_cast<std::size_t>(output)];
}

}  // namespace ffrf::multibody
