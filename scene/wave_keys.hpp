// The [wave] section of a scene file (docs/scenes.md, docs/hydrodynamics.md §7): which keys each
// wave.spectrum needs (regular: height, period; jonswap, pierson-moskowitz: significant_height,
// peak_period; components: the three arrays of equal length) and which it refuses (another
// spectrum's keys), and the Scene::wave (regular) or Scene::sea (irregular) it makes. The loader
// gives access to the keys as written through WrittenKeys.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace ffrf::scene {

// What the loader knows of the scene's keys (dotted names of the schema).
class WrittenKeys {
 public:
  virtual ~WrittenKeys() = default;
  virtual bool written(std::string_view key) const = 0;   // present in the file
  virtual bool has(std::string_view key) const = 0;       // a valid value (written or default)
  virtual int line(std::string_view key) const = 0;       // of a written key
  virtual std::string shown(std::string_view key) const = 0;  // a written key's value as written
  virtual double number(std::string_view key) const = 0;
  virtual const std::string& text(std::string_view key) const = 0;
  virtual const std::vector<double>& list(std::string_view key) const = 0;
  virtual void report(int line, std::string key, std::string value, std::string message) = 0;

 protected:
  WrittenKeys() = default;
  WrittenKeys(const WrittenKeys&) = default;
  WrittenKeys& operator=(const WrittenKeys&) = default;
};

// Reports every missing and foreign [wave] key; `wave_line` is the section's line.
void check_wave_keys(WrittenKeys& keys, int wave_line);
// Sets scene.wave (spectrum = regular) or scene.sea from valid keys.
void build_wave(const WrittenKeys& keys, Scene& scene);

}  // namespace ffrf::scene
