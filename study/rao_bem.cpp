// The [bem] hull in the frequency domain (study/rao_bem.hpp).
#include "study/rao_bem.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "sea/bem_excitation.hpp"
#include "hydro/radiation_memory.hpp"
#include "scene/bem_files.hpp"
#include "scene/bem_hull_model.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf::study {
namespace {

using Complex = std::complex<double>;

void require_bem(const scene::Scene& scene) {
  if (!scene.hull || !scene.bem) throw std::invalid_argument("bem_hull_impedance: the scene has no [hull] with [bem]");
}

// K̂(s) of the model's kernel (see the header).
Eigen::Matrix3cd kernel_transform(const hydro::RadiationMemoryModel& model, Complex s) {
  Eigen::Matrix3cd transform = Eigen::Matrix3cd::Zero();
  if (model.kind == hydro::RadiationKind::convolution) {
    const auto& samples = model.kernel.kernel;
    const double dt = model.kernel.time_step;
    const Complex step = std::exp(-s * dt);
    Complex factor = 1.0;
    for (std::size_t j = 0; j < samples.size(); ++j) {
      const double weight = (j == 0 || j + 1 == samples.size()) ? 0.5 : 1.0;
      transform += (weight * dt * factor) * samples[j].cast<Complex>();
      factor *= step;
    }
  } else if (model.kind == hydro::RadiationKind::state_space) {
    for (int i = 0; i < model.order; ++i) {
      transform += (model.output.col(i) * model.input.row(i)) / (s - model.poles(i));
    }
  }
  return transform;
}

}  // namespace

std::string_view to_string(BemRadiationSource source) {
  return source == BemRadiationSource::file ? "file" : "model";
}

HullImpedance bem_hull_impedance(const scene::Scene& scene, BemRadiationSource source) {
  require_bem(scene);
  const std::shared_ptr<const hydro::RadiationMemoryModel> model = scene::bem_radiation_model(scene);
  // What the linearisation at t = 0 already holds: A_model in the mass, ∂μ/∂ẋ(0) in the damping.
  const hydro::RadiationMemory at_rest(model);
  const Eigen::Matrix3d initial_damping = at_rest.velocity_derivative(0.0);
  const Eigen::Matrix3d model_added_mass = model->added_mass;
  if (source == BemRadiationSource::model) {
    return [model, initial_damping](Complex s) -> Eigen::Matrix3cd {
      if (model->kind == hydro::RadiationKind::constant) return Eigen::Matrix3cd::Zero();
      return s * (kernel_transform(*model, s) - initial_damping.cast<Complex>());
    };
  }
  const Eigen::Matrix3d transfer = sea::rigid_transfer(scene::bem_origin_offset(scene));
  const hydro::PlanarRadiation radiation = scene.bem->radiation;
  const std::string file = scene.bem->radiation_file;
  return [radiation, transfer, model_added_mass, initial_damping, file](Complex s) -> Eigen::Matrix3cd {
    const double omega = s.imag();
    if (std::abs(s.real()) > 1e-12 * std::abs(s) || !(omega > 0.0)) {
      throw std::invalid_argument(fmt::format("the added mass and damping of {} are known on the real frequency axis only "
                                              "(asked at s = {} + {}i rad/s)", file, s.real(), s.imag()));
    }
    const hydro::ConstantRadiation at = hydro::radiation_at(radiation, omega);
    const Eigen::Matrix3d added_mass = transfer.transpose() * at.added_mass * transfer - model_added_mass;
    const Eigen::Matrix3d damping = transfer.transpose() * at.damping * transfer - initial_damping;
    return (-omega * omega) * added_mass.cast<Complex>() + Complex(0.0, omega) * damping.cast<Complex>();
  };
}

void require_bem_band(const scene::Scene& scene, const std::vector<double>& angular_frequencies) {
  if (!scene.bem) return;
  const scene::BemHull& bem = *scene.bem;
  const auto check = [&](const std::vector<double>& band, const std::string& key, const std::string& file) {
    if (band.empty()) return;
    const double low = band.front(), high = band.back();
    for (const double omega : angular_frequencies) {
      if (omega < low * (1.0 - 1e-9) || omega > high * (1.0 + 1e-9)) {
        const double period = 2.0 * std::numbers::pi / omega;
        throw scene::SceneError({{scene.file, 0, 0, key, "\"" + file + "\"",
                                  fmt::format("ω = {:.6g} rad/s (period {:.6g} s) lies outside the file's frequencies; valid "
                                              "range {:.6g} … {:.6g} rad/s (periods {:.6g} … {:.6g} s): the frequency domain "
                                              "does not extrapolate BEM data — narrow the periods or give the BEM run them",
                                              omega, period, low, high, 2.0 * std::numbers::pi / high,
                                              2.0 * std::numbers::pi / low)}});
      }
    }
  };
  check(bem.radiation.frequency, scene::bem_radiation_key(bem), bem.radiation_file);
  if (bem.excitation == scene::ExcitationModel::bem && bem.excitation_table) {
    check(bem.excitation_table->frequency, scene::bem_excitation_key(bem), bem.excitation_file);
  }
}

}  // namespace ffrf::study
