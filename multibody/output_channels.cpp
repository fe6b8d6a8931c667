// The crane's output-channel table (see output_channels.hpp).
#include "multibody/output_channels.hpp"

#include "multibody/output_channel_table.hpp"

#include <array>
#include <string>

namespace ffrf::multibody {
namespace {

using channel_table::channels;

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
