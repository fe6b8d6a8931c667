// The crane's output-channel table itself (see multibody/output_channels.hpp): a constexpr array so
// that the code that names channels (the linear outputs, the judged outputs of
// multibody/error_metrics.hpp) is checked against it at compile time. Included by
// multibody/output_channels.cpp and multibody/error_metrics.cpp only.
#pragma once

#include <array>
#include <numbers>
#include <string_view>

#include "multibody/output_channels.hpp"

namespace ffrf::multibody::channel_table {

constexpr double degrees = 180.0 / std::numbers::pi;

// name, column, title, display unit, SI unit, display scale, about static, judged for (bits; 0: not
// judged), linear (RAO) name, SI value.
constexpr std::array channels{
    OutputChannelSpec{"crane_surge", "crane_surge_m", "crane surge", "m", "m", 1.0, true, 0, "hull_surge",
                      [](const CraneOutputs& o) { return o.hull.x(); }},
    OutputChannelSpec{"crane_heave", "crane_heave_m", "crane heave", "m", "m", 1.0, true, judged_for_crane, "hull_heave",
                      [](const CraneOutputs& o) { return o.hull.y(); }},
    OutputChannelSpec{"crane_pitch", "crane_pitch_deg", "crane pitch", "deg", "rad", degrees, true, judged_for_crane, "hull_pitch",
                      [](const CraneOutputs& o) { return o.hull.z(); }},
    OutputChannelSpec{"cargo_surge", "cargo_surge_m", "cargo surge", "m", "m", 1.0, true, 0, "cargo_surge",
                      [](const CraneOutputs& o) { return o.cargo.x(); }},
    OutputChannelSpec{"cargo_heave", "cargo_heave_m", "cargo heave", "m", "m", 1.0, true, judged_for_crane, "cargo_heave",
                      [](const CraneOutputs& o) { return o.cargo.y(); }},
    OutputChannelSpec{"cargo_pitch", "cargo_pitch_deg", "cargo pitch", "deg", "rad", degrees, true, judged_for_crane, "cargo_pitch",
                      [](const CraneOutputs& o) { return o.cargo.z(); }},
    OutputChannelSpec{"tip_axial", "tip_axial_m", "boom tip axial deflection", "m", "m", 1.0, false, 0, "tip_axial",
                      [](const CraneOutputs& o) { return o.tip_deflection.x(); }},
    OutputChannelSpec{"tip_deflection", "tip_transverse_m", "boom tip transverse deflection", "m", "m", 1.0, false, judged_for_hub, "tip_transverse",
                      [](const CraneOutputs& o) { return o.tip_deflection.y(); }},
    OutputChannelSpec{"wire_tension", "wire_tension_N", "wire tension", "N", "N", 1.0, false, judged_for_crane, "wire_tension",
                      [](const CraneOutputs& o) { return o.wire_tension; }},
    OutputChannelSpec{"luffing_tension", "luffing_tension_N", "luffing wires' tension", "N", "N", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.luffing_tension; }},
    OutputChannelSpec{"luffing_line_pull", "luffing_line_pull_N", "luffing rope line pull", "N", "N", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.luffing_line_pull; }},
    OutputChannelSpec{"backstay_tension", "backstay_tension_N", "backstays' tension", "N", "N", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.backstay_tension; }},
    OutputChannelSpec{"a_frame_rotation", "a_frame_rotation_deg", "A-frame rotation on its pin", "deg", "rad", degrees, true, 0, "",
                      [](const CraneOutputs& o) { return o.a_frame_rotation; }},
    OutputChannelSpec{"joint_force_x", "joint_force_x_N", "joint force x at B", "N", "N", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.joint_reaction.x(); }},
    OutputChannelSpec{"joint_force_y", "joint_force_y_N", "joint force y at B", "N", "N", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.joint_reaction.y(); }},
    OutputChannelSpec{"joint_moment", "joint_moment_Nm", "joint bending moment at B", "N m", "N m", 1.0, false, judged_for_clamped_crane, "",
                      [](const CraneOutputs& o) { return o.joint_reaction.z(); }},
    OutputChannelSpec{"boom_peak_stress", "boom_peak_stress_MPa", "peak fibre stress along the boom", "MPa", "Pa", 1e-6, false,
                      judged_for_pinned_crane, "", [](const CraneOutputs& o) { return o.boom_peak_stress; }},
    OutputChannelSpec{"boom_peak_stress_position", "boom_peak_stress_x_m", "position of the peak fibre stress", "m", "m", 1.0,
                      false, 0, "", [](const CraneOutputs& o) { return o.boom_peak_stress_position; }},
    OutputChannelSpec{"boom_stress_utilisation", "boom_stress_utilisation", "boom stress utilisation", "-", "-", 1.0, false, 0,
                      "", [](const CraneOutputs& o) { return o.boom_stress_utilisation; }},
    OutputChannelSpec{"constraint_residual", "constraint_residual_m", "constraint residual", "m", "m", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.constraint_residual; }},
    OutputChannelSpec{"kinetic_energy", "kinetic_energy_J", "kinetic energy", "J", "J", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.kinetic_energy; }},
    OutputChannelSpec{"gravity_energy", "gravity_energy_J", "gravity energy", "J", "J", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.gravity_energy; }},
    OutputChannelSpec{"strain_energy", "strain_energy_J", "strain energy", "J", "J", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.strain_energy; }},
    OutputChannelSpec{"wire_energy", "wire_energy_J", "wire energy", "J", "J", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.wire_energy; }},
    OutputChannelSpec{"spring_energy", "spring_energy_J", "spring energy", "J", "J", 1.0, false, 0, "",
                      [](const CraneOutputs& o) { return o.spring_energy; }},
};

// The row named `name` (channels.size() when none).
constexpr std::size_t row_of(std::string_view name) {
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (channels[i].name == name) return i;
  }
  return channels.size();
}

// True when every name in `names` is a judged row of `table` and every judged row is named: the
// judged outputs' enumerators (multibody/error_metrics.hpp: judged_names) against the table.
template <std::size_t Rows, std::size_t Names>
constexpr bool judged_rows_named(const std::array<OutputChannelSpec, Rows>& table, const std::array<std::string_view, Names>& names) {
  std::size_t judged = 0;
  for (const OutputChannelSpec& row : table) judged += row.judged != 0 ? 1 : 0;
  if (judged != Names) return false;
  for (const std::string_view name : names) {
    bool found = false;
    for (const OutputChannelSpec& row : table) found = found || (row.judged != 0 && row.name == name);
    if (!found) return false;
  }
  return true;
}

}  // namespace ffrf::multibody::channel_table
