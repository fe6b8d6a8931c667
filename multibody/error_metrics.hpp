// Error metrics of a crane run against a reference run sampled at the same times:
// per output channel, over the window after the wave ramp, the normalized RMS error
// RMS(x − x_ref) / RMS(x_ref − mean(x_ref)), the max absolute error and the max error normalized by
// the reference's amplitude max|x_ref − mean|; and the error of the wire tension's dynamic
// amplification factor DAF = max tension / static tension (static = the t = 0 sample, which is the
// static equilibrium).
#pragma once

#include <array>
#include <string_view>

#include "multibody/output_channels.hpp"
#include "multibody/crane_run.hpp"

namespace ffrf::multibody {

// The judged outputs: the output-channel table's rows marked judged (multibody/output_channels.hpp),
// named here for the code that indexes the verdicts' errors by them. Each enumerator is its row's
// name, and every judged row has one: multibody/error_metrics.cpp checks both at compile time, so a
// judged row added to the table without its enumerator (or the reverse) does not compile.
enum class OutputChannel {
  cargo_heave, cargo_pitch, crane_heave, crane_pitch, wire_tension, tip_deflection, joint_moment, boom_peak_stress
};
inline constexpr std::array<OutputChannel, 8> all_channels{
    OutputChannel::cargo_heave,    OutputChannel::cargo_pitch,  OutputChannel::crane_heave,
    OutputChannel::crane_pitch,    OutputChannel::wire_tension, OutputChannel::tip_deflection,
    OutputChannel::joint_moment,   OutputChannel::boom_peak_stress};
inline constexpr std::array<std::string_view, all_channels.size()> judged_names{
    "cargo_heave", "cargo_pitch", "crane_heave", "crane_pitch", "wire_tension", "tip_deflection", "joint_moment", "boom_peak_stress"};

// Its unit and value come from its row.
std::string_view channel_name(OutputChannel channel);  // "cargo_heave", ...
const OutputChannelSpec& output_channel(OutputChannel channel);
std::string_view channel_unit(OutputChannel channel);  // the SI unit: "m", "rad", "N", "N m"
double channel_value(const CraneOutputs& sample, OutputChannel channel);  // SI

struct ChannelError {
  double normalized_rms = 0.0;
  double max_abs = 0.0;
  double normalized_max = 0.0;
};

struct RunErrors {
  std::array<ChannelError, all_channels.size()> channels{};
  double daf = 0.0, reference_daf = 0.0, daf_error = 0.0;  // |DAF − DAF_ref| / DAF_ref
  const ChannelError& operator[](OutputChannel c) const { return channels[static_cast<std::size_t>(c)]; }
  double worst_normalized_rms() const;
};

double dynamic_amplification(const RunResult& run, double window_start);
// Throws std::invalid_argument when the runs are not sampled at the same times.
RunErrors compare_runs(const RunResult& run, const RunResult& reference, double window_start);

}  // namespace ffrf::multibody
