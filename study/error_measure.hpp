// How every study measures a model against its reference (one physics across
// commands): the same error window, the same judged outputs, the same "worst" error.
//  * Window: after the wave ramp (ramp_periods × period), where the wave is fully in; a run that
//    ends within the ramp, or a scene in calm water, is measured over its whole length.
//  * Judged outputs: what an engineer designs the lift for — a crane's motions and loads (cargo
//    heave and pitch, crane heave and pitch, wire tension, and the boom's load: the bending moment at
//    a clamped root, the peak fibre stress of a pinned boom); a hub scene (no hull, so the hull
//    channels are zero) its boom's tip deflection. The output-channel table says which
//    (multibody/output_channels.hpp: judged_for_*). The tip
//    deflection of a crane is left out: it is the boom model's own coordinate (a rigid boom has
//    none, so its error would be 100 % by construction), and what it does to the lift shows in
//    the cargo motion, the wire tension and the root moment. Every channel's error is still reported.
//  * Worst error: the largest normalized RMS error (multibody/error_metrics.hpp) over the judged outputs.
#pragma once

#include <string>
#include <vector>

#include "multibody/error_metrics.hpp"
#include "scene/scene.hpp"

namespace ffrf::study {

// End of the wave ramp [s] (0 in calm water).
double ramp_end(const scene::Scene& scene);
// Start of the error window for runs of `duration` seconds [s].
double error_window(const scene::Scene& scene, double duration);

// The judged outputs of a scene (see above), in report order.
std::vector<multibody::OutputChannel> judged_outputs(const scene::Scene& scene);

// The judged channels of their names ("cargo_heave"), in the order given; throws SettingError
// (Setting::outputs) naming an unknown one (or none given) and the valid names.
std::vector<multibody::OutputChannel> channels_named(const std::vector<std::string>& names);

// The change between two reference levels: the worst normalized RMS error over the scene's judged
// outputs and the boom's tip deflection.
double convergence_change(const scene::Scene& scene, const multibody::RunErrors& errors);
// "cargo_heave,wire_tension"
std::string output_list(const std::vector<multibody::OutputChannel>& outputs);

struct WorstError {
  double error = 0.0;  // largest normalized RMS error; NaN or inf when a judged channel is
  multibody::OutputChannel channel = multibody::OutputChannel::cargo_heave;
};
// The worst judged channel; a non-finite error wins (it is a failure, not a small number).
WorstError worst_error(const multibody::RunErrors& errors, const std::vector<multibody::OutputChannel>& outputs);

}  // namespace ffrf::study
