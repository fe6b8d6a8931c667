// The one error window, judged outputs and worst error of the studies (see error_measure.hpp).
#include "study/error_measure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "scene/irregular_sea.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {

double ramp_end(const scene::Scene& scene) { return scene::wave_ramp_duration(scene); }

double error_window(const scene::Scene& scene, double duration) {
  const double ramp = ramp_end(scene);
  return duration > ramp + 1e-9 ? ramp : 0.0;
}

namespace {

// The judged_for_* bit of the scene's kind of model (multibody/output_channels.hpp).
unsigned model_kind(const scene::Scene& scene) {
  if (!scene.is_crane()) return multibody::judged_for_hub;
  return scene.boom.mount && scene.boom.mount->pinned ? multibody::judged_for_pinned_crane : multibody::judged_for_clamped_crane;
}

}  // namespace

std::vector<multibody::OutputChannel> judged_outputs(const scene::Scene& scene) {
  // In the order of the report: the cargo's motions, the crane's, the hoist wire, the boom's load.
  const unsigned kind = model_kind(scene);
  std::vector<multibody::OutputChannel> judged;
  for (const multibody::OutputChannel channel : multibody::all_channels) {
    if ((multibody::output_channel(channel).judged & kind) != 0) judged.push_back(channel);
  }
  return judged;
}

std::vector<multibody::OutputChannel> channels_named(const std::vector<std::string>& names) {
  std::string choices;
  for (const auto channel : multibody::all_channels) {  // piece by piece, as output_list
    if (!choices.empty()) choices += ',';
    choices += multibody::channel_name(channel);
  }
  if (names.empty()) throw SettingError(Setting::outputs, "", "no output given; choose from " + choices);
  std::vector<multibody::OutputChannel> channels;
  for (const std::string& name : names) {
    const auto found = std::find_if(multibody::all_channels.begin(), multibody::all_channels.end(),
                                    [&](multibody::OutputChannel c) { return multibody::channel_name(c) == name; });
    if (found == multibody::all_channels.end()) {
      throw SettingError(Setting::outputs, name, fmt::format("unknown output '{}'; choose from {}", name, choices));
    }
    channels.push_back(*found);
  }
  return channels;
}

double convergence_change(const scene::Scene& scene, const multibody::RunErrors& errors) {
  const unsigned kind = model_kind(scene);
  double worst = 0.0;
  for (const multibody::OutputChannel channel : multibody::all_channels) {
    const bool own = channel == multibody::OutputChannel::tip_deflection;  // the boom's own deflection, always
    if (own || (multibody::output_channel(channel).judged & kind) != 0) worst = std::max(worst, errors[channel].normalized_rms);
  }
  return worst;
}

std::string output_list(const std::vector<multibody::OutputChannel>& outputs) {
  std::string s;
  for (const auto channel : outputs) {  // (piece by piece: GCC 12 warns falsely on a concatenation here)
    if (!s.empty()) s += ',';
    s += multibody::channel_name(channel);
  }
  return s;
}

WorstError worst_error(const multibody::RunErrors& errors, const std::vector<multibody::OutputChannel>& outputs) {
  WorstError worst;
  for (const multibody::OutputChannel channel : outputs) {
    const double e = errors[channel].normalized_rms;
    if (e >= worst.error || !std::isfinite(e)) {
      worst = {e, channel};
      if (!std::isfinite(e)) break;
    }
  }
  return worst;
}

}  // namespace ffrf::study
