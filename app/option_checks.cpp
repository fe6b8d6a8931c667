// Command-line value checks (see option_checks.hpp).
#include "app/option_checks.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "scene/scene_schema.hpp"

namespace ffrf::app {
namespace {

std::string bound(double value) { return fmt::format("{:g}", value); }

std::string range_text(double lower, double upper, std::string_view unit, bool lower_open) {
  const std::string range = fmt::format("{}{}, {}]", lower_open ? '(' : '[', bound(lower), bound(upper));
  return unit.empty() ? range : range + " " + std::string(unit);
}

}  // namespace

CLI::Validator whole_number(long long lower, long long upper) {
  const std::string range = fmt::format("[{}, {}]", lower, upper);
  return CLI::Validator(
      [lower, upper, range](std::string& text) -> std::string {
        long long value = 0;
        const char* begin = text.data();
        const char* end = text.data() + text.size();
        const char* digits = begin != end && *begin == '+' ? begin + 1 : begin;
        const auto [stop, error] = std::from_chars(digits, end, value);
        if (text.empty() || stop != end || (error != std::errc{} && error != std::errc::result_out_of_range)) {
          return fmt::format("{}: not a whole number (valid range {})", text, range);
        }
        if (error == std::errc::result_out_of_range || value < lower || value > upper) {
          return fmt::format("{}: out of range (valid range {})", text, range);
        }
        text = fmt::format("{}", value);  // decimal as read: CLI11 would take "010" as octal
        return {};
      },
      "INT in " + range);
}

CLI::Validator finite_number(double lower, double upper, std::string_view unit, bool lower_open) {
  const std::string range = range_text(lower, upper, unit, lower_open);
  return CLI::Validator(
      [lower, upper, lower_open, range](std::string& text) -> std::string {
        errno = 0;
        char* stop = nullptr;
        const double value = std::strtod(text.c_str(), &stop);
        const bool hexadecimal = text.find_first_of("xX") != std::string::npos;
        if (text.empty() || stop != text.c_str() + text.size() || hexadecimal) {
          return fmt::format("{}: not a number (valid range {})", text, range);
        }
        if (!std::isfinite(value) || (errno == ERANGE && std::abs(value) > 1.0)) {
          return fmt::format("{}: not a finite number (valid range {})", text, range);
        }
        const bool above = lower_open ? value > lower : value >= lower;
        if (!above || value > upper) return fmt::format("{}: out of range (valid range {})", text, range);
        text = fmt::format("{}", value);  // the value as read (shortest exact form)
        return {};
      },
      "NUMBER in " + range);
}

CLI::Validator scene_key_range(std::string_view dotted_key) {
  const scene::KeySpec& key = scene::key_spec(dotted_key);
  return finite_number(key.range.lower.value, key.range.upper.value, scene::si_unit(key.dimension), !key.range.lower.closed);
}

CLI::Validator scene_key_count(std::string_view dotted_key) {
  const scene::KeySpec& key = scene::key_spec(dotted_key);
  return whole_number(static_cast<long long>(key.range.lower.value), static_cast<long long>(key.range.upper.value));
}

}  // namespace ffrf::app
