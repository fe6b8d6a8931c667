// The hull's BEM hydrodynamics for the crane (see the header).
#include "scene/bem_hull_model.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sea/excitation_record.hpp"
#include "hydro/retardation.hpp"
#include "hydro/state_space_fit.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf::scene {

Eigen::Vector2d bem_origin_offset(const Scene& scene) {
  const Hull& hull = *scene.hull;
  const BemHull& bem = *scene.bem;
  return {hull.g1_aft_of_mid_length + bem.origin_forward_of_mid_length, bem.origin_above_keel - hull.g1_above_keel};
}

Scene with_radiation(const Scene& scene, hydro::RadiationKind kind) {
  if (!scene.bem) {
    throw SceneError({SceneProblem{scene.file, 0, 0, "bem", "", "a radiation model needs BEM coefficients: the scene has no [bem] section"}});
  }
  Scene copy = scene;
  copy.bem->radiation_model = kind;
  return copy;
}

double constant_radiation_frequency(const Scene& scene) {
  const BemHull& bem = *scene.bem;
  if (bem.constant_period) return 2.0 * std::numbers::pi / *bem.constant_period;
  if (scene.wave) return 2.0 * std::numbers::pi / scene.wave->period;
  const Hull& hull = *scene.hull;
  const double rho = scene.environment.water_density;
  const double displaced = hull.mass + scene.boom.mesh.total_mass() + (scene.cargo ? scene.cargo->mass : 0.0);
  const double heave_stiffness = rho * scene.environment.gravity * hull.length * hull.width;
  double omega = std::sqrt(heave_stiffness / displaced);
  for (int i = 0; i < 50; ++i) omega = std::sqrt(heave_stiffness / (displaced + hydro::radiation_at(bem.radiation, omega).added_mass(1, 1)));
  return omega;
}

namespace {

std::shared_ptr<const hydro::RadiationMemoryModel> build_model(const Scene& scene) {
  const BemHull& bem = *scene.bem;
  const Eigen::Matrix3d transfer = sea::rigid_transfer(bem_origin_offset(scene));
  if (bem.radiation_model == hydro::RadiationKind::constant) {
    return std::make_shared<const hydro::RadiationMemoryModel>(hydro::transferred(
        hydro::constant_memory(hydro::radiation_at(bem.radiation, constant_radiation_frequency(scene))), transfer));
  }
  hydro::RetardationOptions options;
  options.time_step = bem.kernel_time_step;
  options.truncation_time = bem.truncation_time;
  const hydro::RetardationFunction kernel = hydro::retardation_function(bem.radiation, options);
  if (bem.radiation_model == hydro::RadiationKind::convolution) {
    return std::make_shared<const hydro::RadiationMemoryModel>(hydro::transferred(hydro::convolution_memory(kernel), transfer));
  }
  hydro::StateSpaceOptions fit_options;
  fit_options.tolerance = bem.state_space_tolerance;
  const hydro::RadiationStateSpace fit = hydro::fit_state_space(kernel, fit_options);
  return std::make_shared<const hydro::RadiationMemoryModel>(
      hydro::transferred(hydro::state_space_memory(fit, kernel.infinite_frequency_added_mass), transfer));
}

}  // namespace

std::shared_ptr<const hydro::RadiationMemoryModel> bem_radiation_model(const Scene& scene) {
  const BemHull& bem = *scene.bem;
  const Eigen::Vector2d origin = bem_origin_offset(scene);
  // A∞ of a Capytaine dataset without one depends on the estimate's method.
  const std::string key = fmt::format("{}|{}|{}|{}|{}|{}|{}|{}|{}|{}|{}|{}", bem.radiation_file, hydro::to_string(bem.radiation_model),
                                      hydro::to_string(bem.infinite_frequency_method),
                                      bem.length_scale, scene.environment.water_density, scene.environment.gravity,
                                      bem.kernel_time_step, bem.truncation_time, bem.state_space_tolerance, origin.x(),
                                      origin.y(),
                                      // ω_c depends on the wave: only the constant model needs it (a memory
                                      // model's kernel is the same for every wave, computed once)
                                      bem.radiation_model == hydro::RadiationKind::constant ? constant_radiation_frequency(scene) : 0.0);
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const hydro::RadiationMemoryModel>> cache;
  {
    const std::lock_guard lock(mutex);
    if (const auto found = cache.find(key); found != cache.end()) return found->second;
  }
  auto model = build_model(scene);
  const std::lock_guard lock(mutex);
  return cache.emplace(key, std::move(model)).first->second;
}

void apply_bem_hydrodynamics(const Scene& scene, multibody::HullModel& hull, const std::optional<sea::WaveField>& wave) {
  if (!scene.bem) return;
  hull.added_mass.setZero();
  hull.radiation_damping.setZero();
  hull.radiation_memory = bem_radiation_model(scene);
  if (scene.bem->excitation == ExcitationModel::bem && wave && scene.bem->excitation_table) {
    const Eigen::Vector2d origin = bem_origin_offset(scene);
    const double origin_x = hull.support_pose.x() + origin.x();
    hull.bem_excitation = std::make_shared<const sea::BemExcitation>(
        sea::bem_excitation(*scene.bem->excitation_table, *wave, origin_x, origin));
    // An irregular sea on the component grid: the excitation history recorded once (exact sums
    // outside the record, or wherever the grid does not allow one).
    if (scene.sea && scene.sea->kinematics == WaveKinematics::precomputed) {
      sea::ExcitationRecordOptions options;
      options.duration = scene.simulation.duration;
      options.tolerance = sea::excitation_tolerance(*hull.bem_excitation);
      sea::ExcitationRecordOutcome outcome = sea::ExcitationRecord::build(*hull.bem_excitation, *wave, options);
      if (outcome.record) hull.bem_excitation_record = std::make_shared<const sea::ExcitationRecord>(std::move(*outcome.record));
    }
  }
}

}  // namespace ffrf::scene
