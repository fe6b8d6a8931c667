// The time-series outputs of a crane run: the model's output-channel table
// (multibody/output_channels.hpp: CSV column name with its unit, chart title, how a value is taken
// from multibody::CraneOutputs and whether the column is the displacement from static equilibrium).
// The CSV, the JSON statistics, the charts and the reports all iterate it, so an output added to
// the table appears everywhere.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"
#include "multibody/crane_equations.hpp"
#include "multibody/output_channels.hpp"

namespace ffrf::study {

using SeriesSpec = multibody::OutputChannelSpec;  // value(sample): in the display unit (the CSV's)

// Every column after time_s, in CSV order.
std::span<const SeriesSpec> crane_series();
// Index of a column in crane_series(); throws std::out_of_range for an unknown name.
std::size_t series_index(std::string_view column);

// The CSV value of one output at one sample.
double series_value(const SeriesSpec& spec, const multibody::CraneOutputs& sample, const multibody::CraneOutputs& statics);
// The value the statistics measure RMS about: 0 for displacements from static, else the static value.
double series_reference(const SeriesSpec& spec, const multibody::CraneOutputs& statics);

// The samples the statistics use: t > ramp end when the scene has a wave (all samples when the
// run ends before the ramp does, or in calm water).
struct StatsWindow {
  std::size_t first = 0;     // first sample index in the window
  double start_s = 0.0;      // its time
  bool after_ramp = false;   // true when the window starts after a wave ramp
  double ramp_end_s = 0.0;   // the wave ramp's end (0: calm water); a run ending before it has no window after it
};
StatsWindow stats_window(const scene::Scene& scene, const std::vector<double>& time);

struct SeriesStats {
  double static_value = 0.0;  // the reference (0 for displacements from static)
  double min = 0.0, max = 0.0;
  double rms = 0.0;           // about static_value
  double mean = 0.0;          // over the window
  double standard_deviation = 0.0;  // about the mean (population: divided by the count)
};
// Statistics of every series over the window.
std::vector<SeriesStats> series_stats(const std::vector<multibody::CraneOutputs>& samples,
                                      const multibody::CraneOutputs& statics, const StatsWindow& window);

}  // namespace ffrf::study
