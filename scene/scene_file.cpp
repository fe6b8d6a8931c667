// Reading a scene file and the key written on a line (see scene_file.hpp).
#include "scene/scene_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "scene/scene_loader.hpp"

namespace ffrf::scene {

std::optional<WrittenKey> key_on_line(std::string_view text, int line_number) {
  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  if (line_number < 1 || static_cast<std::size_t>(line_number) > lines.size()) return std::nullopt;
  const auto trim = [](std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return std::string_view{};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
  };
  const std::string_view line = trim(lines[static_cast<std::size_t>(line_number) - 1]);
  const auto equals = line.find('=');
  if (equals == std::string_view::npos || line.empty() || line.front() == '[' || line.front() == '#') return std::nullopt;
  const std::string_view leaf = trim(line.substr(0, equals));
  std::string_view value = trim(line.substr(equals + 1));
  if (const auto comment = value.find(" #"); comment != std::string_view::npos) value = trim(value.substr(0, comment));
  std::string section;
  for (std::size_t i = static_cast<std::size_t>(line_number) - 1; i-- > 0;) {
    const std::string_view header = trim(lines[i]);
    if (header.size() > 2 && header.front() == '[' && header.back() == ']') {
      section = std::string(trim(header.substr(1, header.size() - 2)));
      break;
    }
  }
  if (leaf.empty() || section.empty()) return std::nullopt;
  return WrittenKey{section + "." + std::string(leaf), std::string(value)};
}

Scene load_scene(const std::string& path) { return load_scene(path, SceneOverrides{}); }

Scene load_scene(const std::string& path, const SceneOverrides& overrides) {
  return load_scene_text(read_scene_file(path), path, overrides);
}

std::string read_scene_file(const std::string& path) {
  if (path.empty()) throw SceneError({{path, 0, 0, "", "", "an empty file name: give the scene file (TOML)"}});
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw SceneError({{path, 0, 0, "", "", "is a directory, not a scene file (TOML)"}});
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw SceneError({{path, 0, 0, "", "", fmt::format("cannot open the scene file for reading: {}", std::strerror(errno))}});
  }
  // Read at most one byte more than the limit: a device or a huge file is refused, not swallowed.
  std::string text(max_scene_bytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > max_scene_bytes) {
    throw SceneError({{path, 0, 0, "", "",
                       fmt::format("larger than {} bytes: not a scene file (a scene is a few kilobytes of TOML)",
                                   max_scene_bytes)}});
  }
  if (in.bad()) throw SceneError({{path, 0, 0, "", "", fmt::format("cannot read the scene file: {}", std::strerror(errno))}});
  return text;
}

}  // namespace ffrf::scene
