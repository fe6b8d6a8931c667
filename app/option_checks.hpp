// Checks of command-line values before CLI11 converts them, so that no value overflows or is half-read: every number is read whole
// (no trailing text, no octal or hexadecimal), finite, and inside a plausible range — the same range
// as the scene key it overrides where there is one — so that `--elements 3000000000` is named with
// its valid range instead of wrapping around. A failed check's message is "VALUE: what is wrong
// (valid range ...)"; main.cpp prints it as "--option VALUE: ...".
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

#include "scene/scene_key.hpp"

namespace ffrf::app {

// A whole number in [lower, upper].
CLI::Validator whole_number(long long lower, long long upper);
// A finite number in [lower, upper] ((lower, upper] when lower_open); `unit` follows the range.
CLI::Validator finite_number(double lower, double upper, std::string_view unit = {}, bool lower_open = false);
// The SI range of a number scene key (scene::scene_key("simulation.duration"), scene::scene_key("hub.spin_rate")).
CLI::Validator scene_key_range(std::string_view dotted_key);
// The whole-number range of an integer scene key (scene::scene_key("boom.elements")).
CLI::Validator scene_key_count(std::string_view dotted_key);

}  // namespace ffrf::app
