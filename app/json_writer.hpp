// A minimal streaming JSON writer (objects, arrays, strings, numbers, booleans, null) with
// two-space indentation. Numbers are written in the shortest form that reads back exactly;
// NaN and infinity, which JSON cannot represent, are written as null.
#pragma once

#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ffrf::app {

class JsonWriter {
 public:
  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }

  JsonWriter& key(std::string_view name) {
    separate();
    out_ += quoted(name) + ": ";
    after_key_ = true;
    return *this;
  }
  JsonWriter& value(std::string_view text) { return raw(quoted(text)); }
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(bool flag) { return raw(flag ? "true" : "false"); }
  JsonWriter& value(int number) { return raw(fmt::format("{}", number)); }
  JsonWriter& value(double number) { return std::isfinite(number) ? raw(fmt::format("{}", number)) : null(); }
  JsonWriter& value(const std::optional<double>& number) { return number ? value(*number) : null(); }
  JsonWriter& null() { return raw("null"); }

  template <class T>
  JsonWriter& field(std::string_view name, const T& v) {
    return key(name).value(v);
  }

  std::string str() const { return out_ + "\n"; }

 private:
  JsonWriter& open(char bracket) {
    separate();
    out_ += bracket;
    first_.push_back(true);
    return *this;
  }
  JsonWriter& close(char bracket) {
    const bool empty = first_.back();
    first_.pop_back();
    if (!empty) newline();
    out_ += bracket;
    return *this;
  }
  JsonWriter& raw(std::string_view text) {
    separate();
    out_ += text;
    return *this;
  }
  // Comma and newline before a new element; nothing right after a key.
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (first_.empty()) return;
    if (!first_.back()) out_ += ',';
    first_.back() = false;
    newline();
  }
  void newline() { out_ += '\n' + std::string(2 * first_.size(), ' '); }
  static std::string quoted(std::string_view text) {
    std::string q = "\"";
    for (char c : text) {
      switch (c) {
        case '"': q += "\\\""; break;
        case '\\': q += "\\\\"; break;
        case '\n': q += "\\n"; break;
        case '\t': q += "\\t"; break;
        case '\r': q += "\\r"; break;
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            q += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
          } else {
            q += c;
          }
      }
    }
    return q + "\"";
  }

  std::string out_;
  std::vector<bool> first_;
  bool after_key_ = false;
};

}  // namespace ffrf::app
