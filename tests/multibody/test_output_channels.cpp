// The output-channel table (multibody/output_channels.hpp): names and columns unique, every column
// ending in its display unit, angles shown in degrees of the radians they hold, and every judged
// output (multibody/error_metrics.hpp) a row of the table that reads the CraneOutputs field it names.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>

#include "multibody/error_metrics.hpp"
#include "multibody/output_channels.hpp"

namespace output_channels_test {

using namespace ffrf::multibody;

// A sample whose every field holds a different value.
CraneOutputs distinct_sample() {
  CraneOutputs o;
  o.hull = {1.0, 2.0, 0.03};
  o.cargo = {4.0, 5.0, 0.06};
  o.tip_deflection = {7.0, 8.0};
  o.wire_tension = 9.0;
  o.wire_length = 10.0;
  o.joint_reaction = {11.0, 12.0, 13.0};
  o.root_axial_force = 14.0;
  o.constraint_residual = 15.0;
  o.kinetic_energy = 16.0;
  o.gravity_energy = 17.0;
  o.strain_energy = 18.0;
  o.wire_energy = 19.0;
  o.spring_energy = 20.0;
  o.boom_peak_stress = 21.0e6;
  o.boom_peak_stress_position = 22.0;
  o.boom_stress_utilisation = 0.23;
  return o;
}

TEST(OutputChannels, NamesAndColumnsAreUniqueAndColumnsCarryTheirUnit) {
  std::set<std::string> names, columns;
  const std::string unit_suffix[][2] = {{"m", "_m"},   {"deg", "_deg"}, {"N", "_N"},
                                         {"N m", "_Nm"}, {"J", "_J"},     {"MPa", "_MPa"}};
  for (const OutputChannelSpec& spec : output_channels()) {
    EXPECT_TRUE(names.insert(std::string(spec.name)).second) << spec.name;
    EXPECT_TRUE(columns.insert(std::string(spec.column)).second) << spec.column;
    // A dimensionless ratio ("-") has no unit to carry: its column must not end as if it had one.
    bool suffixed = spec.unit == "-";
    for (const auto& [unit, suffix] : unit_suffix) {
      if (spec.unit == unit) suffixed = spec.column.ends_with(suffix);
      if (spec.unit == "-") suffixed = suffixed && !spec.column.ends_with(suffix);
    }
    EXPECT_TRUE(suffixed) << spec.column << " in " << spec.unit;
    const bool angle = spec.si_unit == "rad", megapascal = spec.unit == "MPa";
    EXPECT_EQ(spec.unit == "deg", angle) << spec.name;
    EXPECT_EQ(megapascal, spec.si_unit == "Pa") << spec.name;
    EXPECT_DOUBLE_EQ(spec.display_scale, angle ? 180.0 / std::numbers::pi : megapascal ? 1e-6 : 1.0) << spec.name;
  }
  EXPECT_EQ(output_channels().size(), 25u);
}

TEST(OutputChannels, EveryJudgedOutputIsARowReadingItsField) {
  const CraneOutputs o = distinct_sample();
  EXPECT_EQ(channel_value(o, OutputChannel::cargo_heave), 5.0);
  EXPECT_EQ(channel_value(o, OutputChannel::cargo_pitch), 0.06);
  EXPECT_EQ(channel_value(o, OutputChannel::crane_heave), 2.0);
  EXPECT_EQ(channel_value(o, OutputChannel::crane_pitch), 0.03);
  EXPECT_EQ(channel_value(o, OutputChannel::wire_tension), 9.0);
  EXPECT_EQ(channel_value(o, OutputChannel::tip_deflection), 8.0);
  EXPECT_EQ(channel_value(o, OutputChannel::joint_moment), 13.0);
  EXPECT_EQ(channel_value(o, OutputChannel::boom_peak_stress), 21.0e6);
  EXPECT_DOUBLE_EQ(output_channel(OutputChannel::boom_peak_stress).value(o), 21.0);  // in MPa
  for (const OutputChannel c : all_channels) {
    const OutputChannelSpec& spec = output_channel(c);
    EXPECT_EQ(spec.name, channel_name(c));
    EXPECT_EQ(spec.si_unit, channel_unit(c));
    EXPECT_DOUBLE_EQ(spec.value(o), spec.display_scale * channel_value(o, c)) << spec.column;
  }
  EXPECT_NEAR(output_channel(OutputChannel::crane_pitch).value(o), 0.03 * 180.0 / std::numbers::pi, 1e-12);
  // The judged rows are exactly the judged outputs.
  std::set<std::string> judged_rows, judged_outputs;
  for (const OutputChannelSpec& spec : output_channels())
    if (spec.judged) judged_rows.insert(std::string(spec.name));
  for (const OutputChannel c : all_channels) judged_outputs.insert(std::string(channel_name(c)));
  EXPECT_EQ(judged_rows, judged_outputs);
}

}  // namespace output_channels_test
