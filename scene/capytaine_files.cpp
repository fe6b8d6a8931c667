// A scene's Capytaine dataset (see capytaine_files.hpp).
#include "scene/capytaine_files.hpp"

#include <fmt/format.h>

#include <cmath>

#include "hydro/capytaine_reader.hpp"
#include "scene/scene_key.hpp"

namespace ffrf::scene {

namespace {

constexpr const char* kKey = scene_key("bem.capytaine_file");

// The environment of the run against the scene's: "" when they agree.
std::string environment_mismatch(const hydro::CapytaineDataset& data, const Environment& environment, const std::string& file) {
  if (std::abs(data.gravity - environment.gravity) > 1e-6 * environment.gravity)
    return fmt::format("{}: variable g = {} m/s^2 differs from environment.gravity = {} m/s^2; valid: the same g (the "
                       "wave numbers depend on it): set environment.gravity = {}", file, data.gravity, environment.gravity, data.gravity);
  const bool deep_file = std::isinf(data.water_depth), deep_scene = environment.deep_water();
  if (deep_file != deep_scene ||
      (!deep_file && std::abs(data.water_depth - environment.water_depth) > 0.01 * environment.water_depth))
    return fmt::format("{}: variable water_depth = {} m differs from environment.water_depth = {} m; valid: the same depth "
                       "(within 1 %, or both inf): set environment.water_depth = {}", file, data.water_depth,
                       environment.water_depth, data.water_depth);
  return {};
}

std::string matrix_text(const hydro::PlanarMatrix& m) {
  return fmt::format("surge {:.4g} kg, heave {:.4g} kg, pitch {:.4g} kg m²", m(0, 0), m(1, 1), m(2, 2));
}

std::string estimate_warning(const hydro::InfiniteFrequencyEstimate& e, const std::string& file, std::size_t frequencies) {
  const bool kk = e.method == hydro::InfiniteFrequencyMethod::kramers_kronig;
  const hydro::PlanarMatrix& other = kk ? e.high_frequency : e.kramers_kronig;
  std::string differences;
  for (int d = 0; d < hydro::kPlanarDofs; ++d)
    differences += fmt::format("{}{:+.1f} %", d == 0 ? "" : ", ", 100.0 * (other(d, d) - e.added_mass(d, d)) / e.added_mass(d, d));
  const std::string used = kk ? fmt::format("Kramers–Kronig from B(ω) (median over {} frequencies)", frequencies - 1)
                              : fmt::format("the high-frequency end of A(ω) (A∞ + c/ω² fitted to the last {} frequencies)",
                                            e.high_frequency_points);
  return fmt::format("{} holds no infinite-frequency added mass (no ω = inf): A∞ estimated by {}: {}; {} gives {} ({} "
                     "in surge, heave, pitch; bem.infinite_frequency_added_mass chooses)", file, used, matrix_text(e.added_mass),
                     kk ? "the high-frequency end" : "Kramers–Kronig", matrix_text(other), differences);
}

}  // namespace

std::vector<BemProblem> load_capytaine_dataset(Scene& scene) {
  BemHull& bem = *scene.bem;
  const std::string& file = bem.radiation_file;
  hydro::CapytaineDataset data;
  try {
    data = hydro::read_capytaine(file);
  } catch (const hydro::CapytaineFileError& error) {
    return {{kKey, error.what()}};
  }
  if (std::string mismatch = environment_mismatch(data, scene.environment, file); !mismatch.empty()) return {{kKey, mismatch}};
  data = hydro::at_density(std::move(data), scene.environment.water_density);
  std::vector<BemProblem> problems;
  if (bem.excitation == ExcitationModel::bem && !data.excitation)
    problems.push_back({scene_key("bem.excitation"), fmt::format("\"bem\" needs the excitation: {} holds neither Froude_Krylov_force and "
                                                      "diffraction_force nor excitation_force; or choose \"froude-krylov\"", file)});
  if (data.hydrostatics) {
    if (std::string mismatch = waterplane_mismatch(scene, *data.hydrostatics, file + " (hydrostatic_stiffness)"); !mismatch.empty())
      problems.push_back({kKey, std::move(mismatch)});
  }
  bem.radiation = std::move(data.radiation);
  bem.excitation_table = std::move(data.excitation);
  bem.hydrostatics = data.hydrostatics;
  if (!bem.radiation.has_infinite_frequency) {
    try {
      const auto estimate = hydro::estimate_infinite_frequency_added_mass(bem.radiation, bem.infinite_frequency_method);
      bem.radiation = hydro::with_infinite_frequency(std::move(bem.radiation), estimate);
      bem.infinite_frequency_estimate = estimate;
      problems.push_back({kKey, estimate_warning(estimate, file, bem.radiation.frequency.size()), true});
    } catch (const std::invalid_argument& error) {
      problems.push_back({kKey, fmt::format("{}: no ω = inf row and A∞ cannot be estimated: {}", file, error.what())});
    }
  }
  return problems;
}

}  // namespace ffrf::scene
