// Reading a scene's WAMIT files (see the header).
#include "scene/bem_files.hpp"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>

#include "hydro/wamit_reader.hpp"
#include "scene/capytaine_files.hpp"
#include "scene/scene_key.hpp"

namespace ffrf::scene {

std::string resolve_scene_path(const std::string& scene_file, const std::string& written) {
  const std::filesystem::path path(written);
  if (path.is_absolute() || scene_file.empty()) return written;
  // Not normalized: "cases/../data" must go through a symlinked cases/ as the OS resolves it.
  return (std::filesystem::path(scene_file).parent_path() / path).string();
}

namespace {

// The file's problem, or "" when it exists and is a regular file. A missing file is named by its
// absolute path, with the rule that made it from what the scene says.
std::string missing_file(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    return fmt::format("file not found: {} (looked for at {}; a relative path in a scene is relative to the scene "
                       "file's folder, not to the working directory)",
                       path, error ? path : absolute.lexically_normal().string());
  }
  if (!std::filesystem::is_regular_file(path, error)) return fmt::format("not a regular file: {}", path);
  return {};
}

}  // namespace

std::vector<BemProblem> load_bem_files(Scene& scene) {
  std::vector<BemProblem> problems;
  BemHull& bem = *scene.bem;
  if (!scene.hull) {
    problems.push_back({"bem", "belongs to a floating hull: give [hull] (a hub scene has no water)"});
    return problems;
  }
  if (bem.radiation_file.empty()) {
    problems.push_back({scene_key("bem.radiation_file"), "missing: [bem] needs the WAMIT .1 file (added mass and damping)"});
    return problems;
  }
  if (bem.excitation == ExcitationModel::bem && bem.excitation_file.empty()) {
    problems.push_back({scene_key("bem.excitation"), "\"bem\" needs bem.excitation_file (the WAMIT .3 file); or choose \"froude-krylov\""});
  }
  const hydro::WamitScaling scaling{bem.length_scale, scene.environment.water_density, scene.environment.gravity};
  const auto read = [&](const std::string& key, const std::string& path, auto&& reader) {
    if (path.empty()) return;
    if (const std::string missing = missing_file(path); !missing.empty()) {
      problems.push_back({key, missing});
      return;
    }
    try {
      reader(path);
    } catch (const hydro::WamitFileError& error) {
      problems.push_back({key, error.what()});
    } catch (const std::invalid_argument& error) {
      problems.push_back({key, fmt::format("{}: {}", path, error.what())});
    }
  };
  if (bem.format == BemFormat::capytaine) {  // one NetCDF dataset (scene/capytaine_files.hpp)
    read(scene_key("bem.capytaine_file"), bem.radiation_file, [&](const std::string&) {
      for (BemProblem& problem : load_capytaine_dataset(scene)) problems.push_back(std::move(problem));
    });
    return problems;
  }
  read(scene_key("bem.radiation_file"), bem.radiation_file,
       [&](const std::string& path) { bem.radiation = hydro::read_wamit_radiation(path, scaling); });
  read(scene_key("bem.excitation_file"), bem.excitation_file,
       [&](const std::string& path) { bem.excitation_table = hydro::read_wamit_excitation(path, scaling); });
  read(scene_key("bem.hydrostatics_file"), bem.hydrostatics_file,
       [&](const std::string& path) { bem.hydrostatics = hydro::read_wamit_hydrostatics(path, scaling); });
  if (bem.hydrostatics) {
    // The pressure integration owns the hydrostatics; the .hst must describe the same waterplane.
    if (std::string mismatch = waterplane_mismatch(scene, *bem.hydrostatics, bem.hydrostatics_file); !mismatch.empty())
      problems.push_back({scene_key("bem.hydrostatics_file"), std::move(mismatch)});
  }
  return problems;
}

std::string waterplane_mismatch(const Scene& scene, const hydro::PlanarMatrix& hydrostatics, const std::string& file) {
  const Hull& hull = *scene.hull;
  const double box = scene.environment.water_density * scene.environment.gravity * hull.length * hull.width;
  const double c33 = hydrostatics(1, 1);
  if (std::abs(c33 - box) <= 0.02 * box) return {};
  return fmt::format("{}: C33 = {:.6g} N/m differs from the box hull's ρ·g·L·B = {:.6g} N/m by {:.1f} % (valid: within 2 %): "
                     "the BEM files describe another hull than [hull]", file, c33, box, 100.0 * (c33 - box) / box);
}

std::string bem_radiation_key(const BemHull& bem) {
  return bem.format == BemFormat::capytaine ? scene_key("bem.capytaine_file") : scene_key("bem.radiation_file");
}

std::string bem_excitation_key(const BemHull& bem) {
  return bem.format == BemFormat::capytaine ? scene_key("bem.capytaine_file") : scene_key("bem.excitation_file");
}

}  // namespace ffrf::scene
