// Error metrics against a reference run (see header).
#include "multibody/error_metrics.hpp"

#include "multibody/output_channel_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ffrf::multibody {

static_assert(channel_table::judged_rows_named(channel_table::channels, judged_names),
              "each judged row of the output-channel table needs its OutputChannel enumerator (judged_names), and each "
              "enumerator must name a judged row");
static_assert(all_channels.size() == judged_names.size());

std::string_view channel_name(OutputChannel channel) { return judged_names[static_cast<std::size_t>(channel)]; }

const OutputChannelSpec& output_channel(OutputChannel channel) {
  return channel_table::channels[channel_table::row_of(channel_name(channel))];
}

std::string_view channel_unit(OutputChannel channel) { return output_channel(channel).si_unit; }

double channel_value(const CraneOutputs& s, OutputChannel channel) { return output_channel(channel).extract(s); }

double RunErrors::worst_normalized_rms() const {
  double worst = 0.0;
  for (const ChannelError& e : channels) worst = std::max(worst, e.normalized_rms);
  return worst;
}

double dynamic_amplification(const RunResult& run, double window_start) {
  double peak = 0.0;
  for (std::size_t i = 0; i < run.time.size(); ++i) {
    if (run.time[i] >= window_start) peak = std::max(peak, run.samples[i].wire_tension);
  }
  const double static_tension = run.samples.front().wire_tension;
  return static_tension > 0.0 ? peak / static_tension : 0.0;
}

RunErrors compare_runs(const RunResult& run, const RunResult& reference, double window_start) {
  if (run.time.size() != reference.time.size() ||
      (!run.time.empty() && std::abs(run.time.back() - reference.time.back()) > 1e-9)) {
    throw std::invalid_argument("runs are not sampled at the same times (" + std::to_string(run.time.size()) + " vs " +
                                std::to_string(reference.time.size()) + " samples): use the same duration and output interval");
  }
  RunErrors errors;
  for (OutputChannel channel : all_channels) {
    double mean = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < run.time.size(); ++i) {
      if (reference.time[i] < window_start) continue;
      mean += channel_value(reference.samples[i], channel);
      ++count;
    }
    if (count == 0) throw std::invalid_argument("the comparison window after t = " + std::to_string(window_start) + " s is empty");
    mean /= count;
    double sq_error = 0.0, sq_signal = 0.0, max_abs = 0.0, amplitude = 0.0;
    for (std::size_t i = 0; i < run.time.size(); ++i) {
      if (reference.time[i] < window_start) continue;
      const double r = channel_value(reference.samples[i], channel);
      const double d = channel_value(run.samples[i], channel) - r;
      sq_error += d * d;
      sq_signal += (r - mean) * (r - mean);
      max_abs = std::max(max_abs, std::abs(d));
      amplitude = std::max(amplitude, std::abs(r - mean));
    }
    ChannelError& e = errors.channels[static_cast<std::size_t>(channel)];
    e.normalized_rms = sq_signal > 0.0 ? std::sqrt(sq_error / sq_signal) : std::sqrt(sq_error / count);
    e.max_abs = max_abs;
    e.normalized_max = amplitude > 0.0 ? max_abs / amplitude : max_abs;
  }
  errors.daf = dynamic_amplification(run, window_start);
  errors.reference_daf = dynamic_amplification(reference, window_start);
  errors.daf_error = errors.reference_daf > 0.0 ? std::abs(errors.daf - errors.reference_daf) / errors.reference_daf : 0.0;
  return errors;
}

}  // namespace ffrf::multibody
