// Test helpers for the CLI tests: run `ffrf` through the shell capturing exit code, stdout and
// stderr; a per-test temporary directory; scene files written into it; a minimal JSON parser
// (test-only) to read `--json` output back.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ffrf::test {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code;
  std::string out;
  std::string err;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A fresh directory per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "ffrf-cli-" + std::to_string(::getpid()) + "-" + info->test_suite_name() + "-" + info->name();
    for (char& c : name) c = c == '/' ? '_' : c;  // parameterized test names contain '/'
    path_ = fs::temp_directory_path() / name;
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

// Runs `ffrf ARGS` (ARGS already shell-quoted where needed); `environment` is put before the
// command ("PATH='/x':$PATH": variables for this run only).
inline RunResult run_ffrf(const std::string& args, const fs::path& scratch, const std::string& environment = "") {
  const fs::path out = scratch / "stdout.txt";
  const fs::path err = scratch / "stderr.txt";
  const std::string command = environment + (environment.empty() ? "" : " ") + std::string(FFRF_BINARY_DIR "/app/ffrf ") +
                              args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return {code, read_text(out), read_text(err)};
}

// Every entry of a directory (names, sorted): what a command left behind.
inline std::vector<std::string> directory_entries(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

inline std::string source_file(const std::string& relative) { return std::string(FFRF_SOURCE_DIR "/") + relative; }

// --- minimal JSON (test-only): enough to validate ffrf's output and read numbers back ---
struct Json {
  enum class Type { null, boolean, number, string, array, object } type = Type::null;
  bool flag = false;
  double number = 0.0;
  std::string text;
  std::vector<Json> items;
  std::vector<std::pair<std::string, Json>> members;

  const Json& operator[](const std::string& key) const {
    for (const auto& [name, value] : members) {
      if (name == key) return value;
    }
    throw std::out_of_range("no JSON member " + key);
  }
  const Json& operator[](std::size_t i) const { return items.at(i); }
};

class JsonParser {
 public:
  explicit JsonParser(std::string text) : s_(std::move(text)) {}
  // Throws std::runtime_error on anything that is not one valid JSON document.
  Json parse() {
    Json value = parse_value();
    skip_space();
    if (pos_ != s_.size()) fail("trailing characters");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("invalid JSON at offset " + std::to_string(pos_) + ": " + what);
  }
  void skip_space() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\n' || s_[pos_] == '\t' || s_[pos_] == '\r')) ++pos_;
  }
  bool consume(const std::string& token) {
    if (s_.compare(pos_, token.size(), token) != 0) return false;
    pos_ += token.size();
    return true;
  }
  void expect(char c) {
    skip_space();
    if (pos_ >= s_.size() || s_[pos_] != c) fail(std::string("expected '") + c + "'");
    ++pos_;
  }
  Json parse_value() {
    skip_space();
    if (pos_ >= s_.size()) fail("unexpected end");
    Json v;
    const char c = s_[pos_];
    if (c == '{') {
      v.type = Json::Type::object;
      ++pos_;
      skip_space();
      if (consume("}")) return v;
      do {
        skip_space();
        std::string key = parse_string();
        expect(':');
        v.members.emplace_back(std::move(key), parse_value());
        skip_space();
      } while (consume(","));
      expect('}');
    } else if (c == '[') {
      v.type = Json::Type::array;
      ++pos_;
      skip_space();
      if (consume("]")) return v;
      do {
        v.items.push_back(parse_value());
        skip_space();
      } while (consume(","));
      expect(']');
    } else if (c == '"') {
      v.type = Json::Type::string;
      v.text = parse_string();
    } else if (consume("true")) {
      v.type = Json::Type::boolean;
      v.flag = true;
    } else if (consume("false")) {
      v.type = Json::Type::boolean;
    } else if (consume("null")) {
      v.type = Json::Type::null;
    } else {
      v.type = Json::Type::number;
      const std::size_t start = pos_;
      if (s_[pos_] == '-') ++pos_;
      if (pos_ >= s_.size() || !std::isdigit(static_cast<unsigned char>(s_[pos_]))) fail("expected a value");
      while (pos_ < s_.size() && std::string_view("0123456789.eE+-").find(s_[pos_]) != std::string_view::npos) ++pos_;
      std::size_t used = 0;
      v.number = std::stod(s_.substr(start, pos_ - start), &used);
      if (used != pos_ - start) fail("malformed number");
    }
    return v;
  }
  std::string parse_string() {
    if (pos_ >= s_.size() || s_[pos_] != '"') fail("expected a string");
    ++pos_;
    std::string out;
    while (pos_ < s_.size() && s_[pos_] != '"') {
      if (static_cast<unsigned char>(s_[pos_]) < 0x20) fail("control character in string");
      if (s_[pos_] == '\\') {
        ++pos_;
        if (pos_ >= s_.size() || std::string_view("\"\\/bfnrtu").find(s_[pos_]) == std::string_view::npos) fail("bad escape");
        if (s_[pos_] == 'u') pos_ += 4;
      }
      out += s_[pos_++];
    }
    if (pos_ >= s_.size()) fail("unterminated string");
    ++pos_;
    return out;
  }

  std::string s_;
  std::size_t pos_ = 0;
};

}  // namespace ffrf::test
