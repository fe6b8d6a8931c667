// Response amplitude operators and natural modes of the linearised crane (study/rao.hpp).
#include "study/rao.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "coupling/crane_equations.hpp"
#include "scene/scene_loader.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {
namespace {

using coupling::LinearisedCrane;

// The name of minimal coordinate j (the elastic ones are "boom").
std::string coordinate_name(const LinearisedCrane& linear, int j) {
  static const char* const axes[] = {"surge", "heave", "pitch"};
  if (linear.hull_at >= 0 && j >= linear.hull_at && j < linear.hull_at + 3) return std::string("hull ") + axes[j - linear.hull_at];
  if (linear.cargo_at >= 0 && j >= linear.cargo_at && j < linear.cargo_at + 3) {
    return std::string("cargo ") + axes[j - linear.cargo_at];
  }
  return "boom";
}

// The coordinate (or the boom as a whole) holding the largest share of a mode's kinetic energy.
std::string dominant_coordinate(const LinearisedCrane& linear, const Eigen::VectorXcd& shape) {
  const Eigen::VectorXcd momentum = linear.mass * shape;
  std::string best;
  double best_share = -1.0, boom_share = 0.0;
  for (int j = 0; j < linear.size(); ++j) {
    const double share = std::abs(std::real(std::conj(shape(j)) * momentum(j)));
    if (j >= linear.elastic_at) {
      boom_share += share;
    } else if (share > best_share) {
      best_share = share;
      best = coordinate_name(linear, j);
    }
  }
  return boom_share > best_share ? "boom" : best;
}

}  // namespace

double NaturalMode::period() const { return 2.0 * std::numbers::pi / angular_frequency; }

std::vector<NaturalMode> natural_modes(const LinearisedCrane& linear) {
  const int n = linear.size();
  // First-order form y = (x, ẋ): ẏ = [0 I; −M⁻¹K −M⁻¹C] y.
  const Eigen::PartialPivLU<Eigen::MatrixXd> mass(linear.mass);
  Eigen::MatrixXd state = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  state.topRightCorner(n, n).setIdentity();
  state.bottomLeftCorner(n, n) = -mass.solve(linear.stiffness);
  state.bottomRightCorner(n, n) = -mass.solve(linear.damping);
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(state, true);
  if (solver.info() != Eigen::Success) throw std::runtime_error("natural_modes: the eigenvalue solver did not converge");
  std::vector<NaturalMode> modes;
  for (int i = 0; i < 2 * n; ++i) {
    const std::complex<double> lambda = solver.eigenvalues()(i);
    const double magnitude = std::abs(lambda);
    if (lambda.imag() < 0.0 || magnitude == 0.0) continue;  // one of each complex pair
    // A real (overdamped) root: its partner is another real root; both are listed.
    modes.push_back({magnitude, -lambda.real() / magnitude,
                     dominant_coordinate(linear, solver.eigenvectors().col(i).head(n))});
  }
  std::sort(modes.begin(), modes.end(),
            [](const NaturalMode& a, const NaturalMode& b) { return a.angular_frequency < b.angular_frequency; });
  return modes;
}

Eigen::VectorXcd frequency_response(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& damping,
                                    const Eigen::MatrixXd& stiffness, const Eigen::VectorXcd& force,
                                    double angular_frequency) {
  const std::complex<double> i_omega(0.0, angular_frequency);
  const Eigen::MatrixXcd dynamic_stiffness = (-angular_frequency * angular_frequency) * mass.cast<std::complex<double>>() +
                                             i_omega * damping.cast<std::complex<double>>() +
                                             stiffness.cast<std::complex<double>>();
  const Eigen::FullPivLU<Eigen::MatrixXcd> lu(dynamic_stiffness);
  if (!lu.isInvertible()) {
    throw std::runtime_error("the linearised system is singular at ω = " + std::to_string(angular_frequency) +
                             " rad/s (an undamped resonance)");
  }
  return lu.solve(force);
}

std::vector<scene::BoomChoice> rao_models() {
  using scene::BoomKind;
  return {{BoomKind::rigid, 1}, {BoomKind::nodal, 16}, {BoomKind::modal, 16, 2, true}};
}

scene::Scene with_regular_wave(const scene::Scene& scene, double height, double period, double ramp_periods) {
  scene::Scene waved = scene;
  scene::WaveDirection direction = scene.wave ? scene.wave->direction : scene::WaveDirection::following;
  if (scene.sea && scene.sea->heading == hydro::WaveHeading::head) direction = scene::WaveDirection::head;
  waved.sea.reset();  // a regular wave replaces the scene's irregular sea (the frequency domain is per component)
  waved.wave = scene::Wave{height, period, direction, ramp_periods};
  return waved;
}

namespace {

void require_crane(const scene::Scene& scene) {
  if (!scene.is_crane()) {
    throw scene::SceneError({{scene.file, 0, 0, "hull", "",
                              "the frequency domain needs a floating crane: this scene has no [hull] (a hub scene has no water)"}});
  }
}

}  // namespace

std::vector<NaturalMode> coupled_natural_modes(const scene::Scene& scene, const scene::BoomChoice& choice,
                                               modal::ModeCache* modes) {
  require_crane(scene);
  scene::Scene calm = scene;
  calm.wave.reset();
  calm.sea.reset();
  PreparedRun prepared = prepare_run(calm, choice, modes);
  return natural_modes(coupling::linearise_crane(*prepared.equations, prepared.statics.z));
}

RaoResult response_amplitude_operators(const scene::Scene& scene, const RaoRequest& request,
                                       const std::function<void(const std::string&)>& progress, modal::ModeCache* modes) {
  require_crane(scene);
  if (request.angular_frequencies.empty()) throw std::invalid_argument("no frequency to evaluate the response at");
  for (const double omega : request.angular_frequencies) {
    if (!(omega > 0.0) || !std::isfinite(omega)) {
      throw std::invalid_argument("angular frequency " + std::to_string(omega) + " rad/s is not positive and finite");
    }
  }
  if (!(request.excitation_amplitude > 0.0)) throw std::invalid_argument("the excitation amplitude must be positive");
  modal::ModeCache own;
  modal::ModeCache& cache = modes != nullptr ? *modes : own;
  if (scene.bem && !request.hydrodynamics) {
    // Linearised at t = 0, a [bem] hull would show only its radiation model's A and ∂μ/∂ẋ(0), not the
    // files' A(ω), B(ω) and excitation: refuse rather than give RAOs that are not those of the files.
    throw scene::SceneError({{scene.file, 0, 0, "bem", "",
                              "the frequency domain does not yet use BEM coefficients (its RAOs would not be those of the "
                              "files); run the time domain (ffrf run/compare) on this scene, or use [radiation] constants"}});
  }
  scene::Scene calm = scene;
  calm.wave.reset();
  calm.sea.reset();
  RaoResult result;
  result.angular_frequencies = request.angular_frequencies;
  result.excitation_amplitude = request.excitation_amplitude;
  result.frequency_dependent_hydrodynamics = static_cast<bool>(request.hydrodynamics);
  const double a = request.excitation_amplitude;
  for (const scene::BoomChoice& choice : request.models.empty() ? rao_models() : request.models) {
    if (progress) progress(choice.label());
    const auto start = std::chrono::steady_clock::now();
    PreparedRun prepared = prepare_run(calm, choice, &cache);
    const LinearisedCrane linear = coupling::linearise_crane(*prepared.equations, prepared.statics.z);
    const coupling::OutputMap outputs = coupling::linear_outputs(*prepared.equations, linear);
    ModelRao model;
    model.choice = choice;
    model.coordinates = linear.size();
    model.modes = natural_modes(linear);
    for (const double omega : request.angular_frequencies) {
      const auto waved = scene::build_crane(with_regular_wave(scene, 2.0 * a, 2.0 * std::numbers::pi / omega, 0.0), choice, &cache);
      Eigen::VectorXcd force = coupling::wave_excitation(*waved, linear, omega, a);
      Eigen::MatrixXd mass = linear.mass, damping = linear.damping;
      if (request.hydrodynamics && linear.hull_at >= 0) {
        const HullFrequencyTerms terms = request.hydrodynamics(omega);
        mass.block<3, 3>(linear.hull_at, linear.hull_at) += terms.added_mass;
        damping.block<3, 3>(linear.hull_at, linear.hull_at) += terms.damping;
        if (terms.excitation) {
          force.setZero();
          force.segment<3>(linear.hull_at) = *terms.excitation;
        }
      }
      const Eigen::VectorXcd motion = frequency_response(mass, damping, linear.stiffness, force, omega);
      const Eigen::VectorXcd response = outputs.position.cast<std::complex<double>>() * motion +
                                        std::complex<double>(0.0, omega) * (outputs.velocity.cast<std::complex<double>>() * motion);
      for (int k = 0; k < coupling::linear_output_count; ++k) model.response[static_cast<std::size_t>(k)].push_back(response(k));
    }
    model.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.models.push_back(std::move(model));
  }
  return result;
}

}  // namespace ffrf::study
