// Response amplitude operators and natural modes of the linearised crane (study/rao.hpp).
#include "study/rao.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "multibody/crane_equations.hpp"
#include "scene/crane_model_cache.hpp"
#include "scene/irregular_sea.hpp"
#include "scene/scene_loader.hpp"
#include "study/run_pipeline.hpp"
#include "study/wall_clock.hpp"
#include "linalg/dense_solvers.hpp"

namespace ffrf::study {
namespace {

using multibody::LinearisedCrane;

// The name of minimal coordinate j (the elastic ones and the heel's angle are "boom"; a body pinned
// to the hull is its name, "A-frame").
std::string coordinate_name(const LinearisedCrane& linear, int j) {
  static const char* const axes[] = {"surge", "heave", "pitch"};
  if (linear.hull_at >= 0 && j >= linear.hull_at && j < linear.hull_at + 3) return std::string("hull ") + axes[j - linear.hull_at];
  if (linear.cargo_at >= 0 && j >= linear.cargo_at && j < linear.cargo_at + 3) {
    return std::string("cargo ") + axes[j - linear.cargo_at];
  }
  for (std::size_t i = 0; i < linear.pinned_at.size(); ++i) {
    if (j == linear.pinned_at[i]) return linear.pinned_names[i];
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

struct RootAndShape {
  std::complex<double> root;
  Eigen::VectorXcd shape;
  std::string unrefined;  // a root Newton was asked to refine and could not: why
};

// The constant system's eigenvalues (Im λ ≥ 0) and shapes, from its first-order form
// y = (x, ẋ): ẏ = [0 I; −M⁻¹K −M⁻¹C] y.
std::vector<RootAndShape> constant_roots(const LinearisedCrane& linear) {
  const int n = linear.size();
  const Eigen::PartialPivLU<Eigen::MatrixXd> mass(linear.mass);
  Eigen::MatrixXd state = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  state.topRightCorner(n, n).setIdentity();
  state.bottomLeftCorner(n, n) = -mass.solve(linear.stiffness);
  state.bottomRightCorner(n, n) = -mass.solve(linear.damping);
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(state, true);
  if (solver.info() != Eigen::Success) throw std::runtime_error("natural_modes: the eigenvalue solver did not converge");
  std::vector<RootAndShape> roots;
  for (int i = 0; i < 2 * n; ++i) {
    const std::complex<double> lambda = solver.eigenvalues()(i);
    if (lambda.imag() < 0.0 || std::abs(lambda) == 0.0) continue;  // one of each complex pair
    // A real (overdamped) root: its partner is another real root; both are listed.
    roots.push_back({lambda, solver.eigenvectors().col(i).head(n), {}});
  }
  return roots;
}

std::vector<NaturalMode> to_modes(const LinearisedCrane& linear, const std::vector<RootAndShape>& roots) {
  std::vector<NaturalMode> modes;
  for (const RootAndShape& r : roots) {
    const double magnitude = std::abs(r.root);
    modes.push_back({magnitude, -r.root.real() / magnitude, dominant_coordinate(linear, r.shape), r.unrefined});
  }
  std::sort(modes.begin(), modes.end(),
            [](const NaturalMode& a, const NaturalMode& b) { return a.angular_frequency < b.angular_frequency; });
  return modes;
}

// D(s) = s²M + sC + K + Z(s) (Z in the hull's rows and columns).
Eigen::MatrixXcd dynamic_matrix(const LinearisedCrane& linear, const HullImpedance& impedance, std::complex<double> s) {
  Eigen::MatrixXcd d = (s * s) * linear.mass.cast<std::complex<double>>() + s * linear.damping.cast<std::complex<double>>() +
                       linear.stiffness.cast<std::complex<double>>();
  d.block<3, 3>(linear.hull_at, linear.hull_at) += impedance(s);
  return d;
}

// Newton on log det D(s) from `root`, deflated by the roots already found (and their conjugates) so
// that two starts do not converge to one root: s ← s − 1/(tr(D⁻¹D′) − Σ_j 1/(s − r_j)). Empty when it
// converged (root and shape replaced); else why it did not (a non-finite or zero log-derivative, a
// non-finite step, or no convergence within `max_steps`), root and shape unchanged.
std::string refine_root(const LinearisedCrane& linear, const HullImpedance& impedance, const std::vector<std::complex<double>>& found,
                        int max_steps, std::complex<double>& root, Eigen::VectorXcd& shape) {
  const auto at = [](std::complex<double> s) { return fmt::format("s = {:.6g}{:+.6g}i rad/s", s.real(), s.imag()); };
  std::complex<double> s = root;
  for (int iteration = 0; iteration < max_steps; ++iteration) {
    const double h = 1e-6 * std::abs(s);
    const Eigen::MatrixXcd d = dynamic_matrix(linear, impedance, s);
    const Eigen::MatrixXcd slope = (dynamic_matrix(linear, impedance, s + h) - dynamic_matrix(linear, impedance, s - h)) / (2.0 * h);
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(d);
    std::complex<double> log_slope = lu.solve(slope).trace();
    for (const std::complex<double> r : found) log_slope -= 1.0 / (s - r) + 1.0 / (s - std::conj(r));
    if (!std::isfinite(log_slope.real()) || !std::isfinite(log_slope.imag()) || std::abs(log_slope) == 0.0) {
      return fmt::format("Newton on log det D(s) stopped at step {}: the log-derivative tr(D⁻¹D′) is {} at {}", iteration + 1,
                         std::abs(log_slope) == 0.0 ? "zero" : "not finite", at(s));
    }
    const std::complex<double> step = 1.0 / log_slope;
    if (!std::isfinite((s - step).real()) || !std::isfinite((s - step).imag())) {
      return fmt::format("Newton on log det D(s) stopped at step {}: a non-finite step from {}", iteration + 1, at(s));
    }
    s -= step;
    if (std::abs(step) < 1e-11 * std::abs(s)) {
      const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(dynamic_matrix(linear, impedance, s), Eigen::ComputeFullV);
      shape = svd.matrixV().col(svd.matrixV().cols() - 1);
      root = s.imag() < 0.0 ? std::conj(s) : s;
      return {};
    }
  }
  return fmt::format("Newton on log det D(s) did not converge in {} steps (from {}, last {})", max_steps, at(root), at(s));
}

}  // namespace

std::vector<NaturalMode> natural_modes(const LinearisedCrane& linear) { return to_modes(linear, constant_roots(linear)); }

std::vector<NaturalMode> natural_modes(const LinearisedCrane& linear, const HullImpedance& impedance, double refine_below,
                                       int max_newton_steps) {
  std::vector<RootAndShape> roots = constant_roots(linear);
  if (impedance && linear.hull_at >= 0) {
    std::vector<std::complex<double>> found;
    for (RootAndShape& r : roots) {
      if (std::abs(r.root) > refine_below) continue;
      r.unrefined = refine_root(linear, impedance, found, max_newton_steps, r.root, r.shape);
      if (r.unrefined.empty()) found.push_back(r.root);
    }
  }
  return to_modes(linear, roots);
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

std::vector<scene::BoomChoice> rao_models(const scene::Scene& scene) {
  using scene::BoomKind;
  const int elements = scene.boom.mesh.element_count;
  return {{BoomKind::rigid, 1}, {BoomKind::nodal, elements}, {BoomKind::modal, elements, 2, true}};
}

scene::Scene with_regular_wave(const scene::Scene& scene, double height, double period, double ramp_periods) {
  scene::Scene waved = scene;
  hydro::WaveHeading direction = scene.wave ? scene.wave->direction : hydro::WaveHeading::following;
  if (scene.sea && scene.sea->heading == hydro::WaveHeading::head) direction = hydro::WaveHeading::head;
  waved.sea.reset();  // a regular wave replaces the scene's irregular sea (the frequency domain is per component)
  waved.wave = scene::Wave{height, period, direction, ramp_periods};
  return waved;
}

namespace {

// The outputs whose resonance peaks are refined: all but the rigid boom's tip deflection (zero).
std::vector<bool> searched_outputs(const scene::BoomChoice& choice) {
  std::vector<bool> searched(multibody::linear_output_count, true);
  if (choice.kind == scene::BoomKind::rigid) {
    searched[static_cast<std::size_t>(multibody::LinearOutput::tip_axial)] = false;
    searched[static_cast<std::size_t>(multibody::LinearOutput::tip_transverse)] = false;
  }
  return searched;
}

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
  return natural_modes(multibody::linearise_crane(*prepared.equations, prepared.statics.z));
}

std::vector<double> period_grid(double shortest, double longest, int count) {
  std::vector<double> omegas;
  for (int i = count - 1; i >= 0; --i) {
    omegas.push_back(2.0 * std::numbers::pi / (shortest + (longest - shortest) * i / std::max(count - 1, 1)));
  }
  return omegas;
}

std::optional<hydro::WaveSpectrum> default_sea_spectrum(const scene::Scene& scene) {
  if (!scene.sea || scene.sea->spectrum == scene::SeaSpectrum::components) return std::nullopt;
  return scene::sea_spectrum(*scene.sea);
}

std::vector<double> default_rao_frequencies() {
  return period_grid(default_rao_shortest_period, default_rao_longest_period, default_rao_period_count);
}

std::vector<double> frequencies_of_periods(const std::vector<double>& periods) {
  if (periods.empty()) throw SettingError(Setting::wave_periods, "[]", "no wave period given");
  std::vector<double> omegas;
  for (double period : periods) {
    if (!(period > 0.0 && period <= max_rao_period)) {
      throw SettingError(Setting::wave_periods, fmt::format("{}", period),
                         fmt::format("out of range (valid range (0, {:g}] s)", max_rao_period));
    }
    omegas.push_back(2.0 * std::numbers::pi / period);
  }
  return omegas;
}

void validate_frequencies(const std::vector<double>& angular_frequencies) {
  if (angular_frequencies.empty()) throw SettingError(Setting::wave_frequencies, "[]", "no wave frequency given");
  for (double omega : angular_frequencies) {
    if (!(omega > 0.0 && omega <= max_rao_frequency)) {
      throw SettingError(Setting::wave_frequencies, fmt::format("{}", omega),
                         fmt::format("out of range (valid range (0, {:g}] rad/s)", max_rao_frequency));
    }
  }
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
  // A [bem] hull: its impedance beyond the linearisation's constant part (study/rao_bem.hpp), from the
  // files or from the radiation model; the natural modes always from the model's own kernel (the
  // files' A, B are known on the real axis only) — the modes of the time domain.
  HullImpedance impedance, model_impedance;
  double refine_below = 0.0;
  if (scene.bem && !request.hydrodynamics) {
    require_bem_band(scene, request.angular_frequencies);
    impedance = bem_hull_impedance(scene, request.bem_radiation);
    model_impedance = bem_hull_impedance(scene, BemRadiationSource::model);
    refine_below = 2.0 * scene.bem->radiation.frequency.back();
  }
  scene::Scene calm = scene;
  calm.wave.reset();
  calm.sea.reset();
  RaoResult result;
  result.angular_frequencies = request.angular_frequencies;
  result.excitation_amplitude = request.excitation_amplitude;
  if (request.refine_peaks) result.peak_search = request.peak_search;
  result.frequency_dependent_hydrodynamics = static_cast<bool>(request.hydrodynamics) || static_cast<bool>(impedance);
  if (impedance) {
    result.bem_radiation = request.bem_radiation;
    result.bem_radiation_model = std::string(hydro::to_string(scene.bem->radiation_model));
    result.bem_radiation_file = scene.bem->radiation_file;
    if (scene.bem->excitation == scene::ExcitationModel::bem) result.bem_excitation_file = scene.bem->excitation_file;
  }
  const double a = request.excitation_amplitude;
  // Each boom model is built once in calm water and linearised once; the excitation at ω comes from
  // the same model in that regular wave (scene::with_waters: the hull and wave replaced, the boom not
  // rebuilt); A(ω), B(ω), X(ω) of the hull enter per frequency below.
  scene::CraneModelCache models(calm, &cache);
  for (const scene::BoomChoice& choice : request.models.empty() ? rao_models(scene) : request.models) {
    if (progress) progress(choice.label());
    const auto start = std::chrono::steady_clock::now();
    PreparedRun prepared = prepare_run(models, choice);
    const std::shared_ptr<const multibody::CraneModel> calm_model = models.model(choice);
    const LinearisedCrane linear = multibody::linearise_crane(*prepared.equations, prepared.statics.z);
    const multibody::OutputMap outputs = multibody::linear_outputs(*prepared.equations, linear);
    ModelRao model;
    model.choice = choice;
    model.coordinates = linear.size();
    model.modes = model_impedance && request.memory_natural_modes ? natural_modes(linear, model_impedance, refine_below) : natural_modes(linear);
    // The outputs Y = (G + iωH) X at ω.
    const OutputResponse response_at = [&](double omega) -> Eigen::VectorXcd {
      const auto waved = scene::with_waters(*calm_model, with_regular_wave(scene, 2.0 * a, 2.0 * std::numbers::pi / omega, 0.0))->equations();
      Eigen::VectorXcd force = multibody::wave_excitation(*waved, linear, omega, a);
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
      if (impedance && linear.hull_at >= 0) {  // Z(iω) = −ω²ΔA + iωΔB
        const Eigen::Matrix3cd z = impedance(std::complex<double>(0.0, omega));
        mass.block<3, 3>(linear.hull_at, linear.hull_at) -= z.real() / (omega * omega);
        damping.block<3, 3>(linear.hull_at, linear.hull_at) += z.imag() / omega;
      }
      const Eigen::VectorXcd motion = frequency_response(mass, damping, linear.stiffness, force, omega);
      return outputs.position.cast<std::complex<double>>() * motion +
             std::complex<double>(0.0, omega) * (outputs.velocity.cast<std::complex<double>>() * motion);
    };
    std::vector<Eigen::VectorXcd> responses;
    for (const double omega : request.angular_frequencies) responses.push_back(response_at(omega));
    model.angular_frequencies = request.angular_frequencies;
    if (request.refine_peaks) {
      RefinedResponse refined = refine_resonance_peaks(request.angular_frequencies, responses, model.modes, response_at,
                                                       searched_outputs(choice), request.peak_search);
      model.angular_frequencies = std::move(refined.angular_frequencies);
      responses = std::move(refined.responses);
      model.peaks = std::move(refined.peaks);
      model.added_frequencies = refined.added;
    }
    for (const Eigen::VectorXcd& response : responses) {
      for (int k = 0; k < multibody::linear_output_count; ++k) model.response[static_cast<std::size_t>(k)].push_back(response(k));
    }
    if (request.sea_spectrum) {
      for (int k = 0; k < multibody::linear_output_count; ++k) {
        model.significant_response[static_cast<std::size_t>(k)] =
            significant_response(model.angular_frequencies, model.response[static_cast<std::size_t>(k)], *request.sea_spectrum);
      }
    }
    model.wall_seconds = seconds_since(start);
    result.models.push_back(std::move(model));
  }
  if (request.sea_spectrum) {
    const auto [low, high] = std::minmax_element(request.angular_frequencies.begin(), request.angular_frequencies.end());
    result.sea = sea_weighting(*request.sea_spectrum, *low, *high);
  }
  return result;
}

}  // namespace ffrf::study
