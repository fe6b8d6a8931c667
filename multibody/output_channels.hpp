// The crane's output channels, declared once: the model's table from which the time-series
// columns (study/output_series.hpp: CSV, JSON statistics, charts), the judged outputs of the
// verdicts (multibody/error_metrics.hpp) and the regression baselines' columns are derived. A row
// says the channel's name, its CSV column (display unit in the name), its title, its SI and display
// units, whether it is measured about the static value, and how its SI value is taken from a
// CraneOutputs sample (filled from the state; the joint reaction also from the accelerations).
#pragma once

#include <span>
#include <string_view>

#include "multibody/crane_equations.hpp"

namespace ffrf::multibody {

// Which models' verdicts judge a channel (a set of these bits; 0: none). A hub scene's beam is judged
// by its tip deflection; a crane by its motions and loads, and its boom by the load its heel makes it
// carry — the root moment of a clamped boom, the peak fibre stress of a pinned one (a pin carries no
// moment: its "root moment" samples are the integrator's round-off).
inline constexpr unsigned judged_for_hub = 1, judged_for_clamped_crane = 2, judged_for_pinned_crane = 4,
                          judged_for_crane = judged_for_clamped_crane | judged_for_pinned_crane;

struct OutputChannelSpec {
  std::string_view name;     // "cargo_heave": the channel (judged outputs, baselines, JSON)
  std::string_view column;   // "cargo_heave_m": the CSV column, display unit in the name
  std::string_view title;    // "cargo heave": for tables and charts
  std::string_view unit;     // display unit ("m", "deg", "N", "N m", "J")
  std::string_view si_unit;  // unit of the extracted value ("m", "rad", ...)
  double display_scale;      // display value = SI value × this (180/π for angles)
  bool about_static;         // time series and statistics hold value − static value (body motions)
  unsigned judged;           // judged_for_* bits: the verdicts' errors (of those models), irregular-sea statistics
  std::string_view linear_name;  // its name as a linear (frequency-domain) output ("hull_heave"); empty: none
  double (*extract)(const CraneOutputs&);  // the SI value from a sample
  // The value in the display unit (the CSV's).
  double value(const CraneOutputs& sample) const { return display_scale * extract(sample); }
};

// Every channel, in the time series' column order.
std::span<const OutputChannelSpec> output_channels();

// The linear outputs of the frequency domain (multibody/linearisation.hpp): the rows with a linear
// name, in table order; the enum names them for the studies that pick one.
enum class LinearOutput {
  hull_surge, hull_heave, hull_pitch, cargo_surge, cargo_heave, cargo_pitch, tip_axial, tip_transverse, wire_tension
};
inline constexpr int linear_output_count = 9;  // checked against the table (output_channels.cpp)
const OutputChannelSpec& linear_channel(LinearOutput output);
std::string_view to_string(LinearOutput output);           // the row's linear name: "hull_heave", ...
std::string_view unit_per_amplitude(LinearOutput output);  // the row's SI unit per metre of amplitude: "m/m", "rad/m", "N/m"

}  // namespace ffrf::multibody
