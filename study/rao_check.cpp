// Regular-wave time-domain runs against the RAOs (study/rao_check.hpp).
#include "study/rao_check.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "linalg/dense_solvers.hpp"
#include "study/rao.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {
namespace {

using multibody::LinearOutput;

// Samples per wave period of the check's runs: resolves the second harmonic in the fit.
constexpr double samples_per_period = 40.0;
// A free mode enters the fit basis while e^{σ t} at the window's start is above e^{−30}, and when
// its frequency is below half the sampling's Nyquist frequency (faster modes are gone by then).
constexpr double dead_mode_exponent = -30.0;

// The output's SI value in a time-domain sample (its row of the output-channel table).
double sample_value(LinearOutput output, const multibody::CraneOutputs& sample) {
  return multibody::linear_channel(output).extract(sample);
}

double wrapped(double angle) {
  const double turn = 2.0 * std::numbers::pi;
  angle = std::fmod(angle + std::numbers::pi, turn);
  if (angle < 0.0) angle += turn;
  return angle - std::numbers::pi;
}

struct FreeMode {
  double decay;      // σ [1/s] (< 0)
  double frequency;  // damped ω_d [rad/s] (0: a real root)
};

// The basis of the fit (see the header) at the window's samples.
Eigen::MatrixXd fit_basis(const std::vector<double>& time, std::size_t first, double omega, double start,
                          const std::vector<FreeMode>& modes) {
  const auto rows = static_cast<Eigen::Index>(time.size() - first);
  Eigen::Index columns = 5;
  for (const FreeMode& mode : modes) columns += mode.frequency > 0.0 ? 2 : 1;
  Eigen::MatrixXd basis(rows, columns);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const double t = time[first + static_cast<std::size_t>(r)];
    basis(r, 0) = 1.0;
    basis(r, 1) = std::cos(omega * t);
    basis(r, 2) = std::sin(omega * t);
    basis(r, 3) = std::cos(2.0 * omega * t);
    basis(r, 4) = std::sin(2.0 * omega * t);
    Eigen::Index c = 5;
    for (const FreeMode& mode : modes) {
      const double envelope = std::exp(mode.decay * (t - start));
      basis(r, c++) = envelope * std::cos(mode.frequency * t);
      if (mode.frequency > 0.0) basis(r, c++) = envelope * std::sin(mode.frequency * t);
    }
  }
  return basis;
}

}  // namespace

std::vector<LinearOutput> checked_outputs() {
  return {LinearOutput::hull_heave, LinearOutput::hull_pitch, LinearOutput::cargo_heave};
}

double PeriodCheck::worst_deviation() const {
  double worst = 0.0;
  for (const ChannelCheck& channel : channels) worst = std::max(worst, std::abs(channel.deviation()));
  return worst;
}

bool PeriodCheck::amplitude_dependent() const {
  return probe && probe->worst_deviation <= amplitude_dependent_ratio * worst_deviation();
}

double TimeDomainCheck::worst_deviation() const {
  double worst = 0.0;
  for (const PeriodCheck& period : periods) worst = std::max(worst, period.worst_deviation());
  return worst;
}

std::optional<double> TimeDomainCheck::suggested_wave_height() const {
  std::optional<double> height;
  for (const PeriodCheck& period : periods) {
    if (period.worst_deviation() <= request.tolerance || !period.amplitude_dependent()) continue;
    const double exponent = std::clamp(period.probe->exponent, 1.0, 3.0);
    const double scaled = request.wave_height * std::pow(0.5 * request.tolerance / period.worst_deviation(), 1.0 / exponent);
    height = std::min(height.value_or(scaled), scaled);
  }
  if (!height) return height;
  const double unit = std::pow(10.0, std::floor(std::log10(*height)) - 1.0);  // two significant digits, rounded down
  return std::floor(*height / unit) * unit;
}

TimeDomainCheck check_time_domain(const scene::Scene& scene, const scene::BoomChoice& choice,
                                  const TimeDomainCheckRequest& request, const std::function<void(double, double)>& progress,
                                  modal::ModeCache* modes) {
  if (request.periods.empty()) throw std::invalid_argument("no wave period to check the time domain at");
  for (const double period : request.periods) {
    if (!(period > 0.0) || !std::isfinite(period)) {
      throw std::invalid_argument("wave period " + std::to_string(period) + " s is not positive and finite");
    }
  }
  if (!(request.wave_height > 0.0)) throw std::invalid_argument("the check's wave height must be positive");
  if (!(request.tolerance > 0.0 && request.tolerance < 1.0)) {
    throw std::invalid_argument("the check's tolerance " + std::to_string(request.tolerance) + " is not in (0, 1)");
  }
  modal::ModeCache own;
  modal::ModeCache& cache = modes != nullptr ? *modes : own;
  TimeDomainCheck check;
  check.choice = choice;
  check.request = request;
  RaoRequest linear_request;
  linear_request.models = {choice};
  linear_request.memory_natural_modes = request.memory_free_modes;
  for (const double period : request.periods) linear_request.angular_frequencies.push_back(2.0 * std::numbers::pi / period);
  const RaoResult linear = response_amplitude_operators(scene, linear_request, {}, &cache);
  const ModelRao& rao = linear.models.front();
  std::optional<RaoResult> model_linear;
  if (scene.bem) {
    linear_request.bem_radiation = BemRadiationSource::model;
    model_linear = response_amplitude_operators(scene, linear_request, {}, &cache);
  }
  // One regular-wave run at a period and height, its channels fitted against the RAOs.
  const auto run_period = [&](std::size_t p, double height) {
    const double period = request.periods[p], omega = linear.angular_frequencies[p], amplitude = 0.5 * height;
    if (progress) progress(period, height);
    scene::Scene waved = with_regular_wave(scene, height, period, request.ramp_periods);
    waved.simulation.output_interval = period / samples_per_period;
    if (scene.bem) {  // the memory's recording step: no coarser than the kernel's
      waved.simulation.output_interval = period / std::ceil(period / std::min(period / samples_per_period, scene.bem->kernel_time_step));
    }
    waved.simulation.cargo_lift = 0.0;
    waved.simulation.initial_state = scene::InitialState::static_equilibrium;
    DynamicsRequest dynamics;
    dynamics.relative_tolerance = request.relative_tolerance;
    dynamics.absolute_tolerance = request.relative_tolerance;
    dynamics.duration = (request.ramp_periods + request.window_periods) * period;
    const ModelRun run = run_model(waved, choice, integrator_settings(waved, dynamics), &cache);
    PeriodCheck result;
    result.period = period;
    result.duration = *dynamics.duration;
    result.stats = run.result.stats;
    result.window_start = request.ramp_periods * period;
    const std::vector<double>& time = run.result.time;
    std::size_t first = 0;
    while (first < time.size() && time[first] < result.window_start - 1e-9) ++first;
    const double nyquist = std::numbers::pi / waved.simulation.output_interval;
    std::vector<FreeMode> free_modes;
    for (const NaturalMode& mode : rao.modes) {
      const double decay = -mode.damping_ratio * mode.angular_frequency;
      const double damped = mode.angular_frequency * std::sqrt(std::max(0.0, 1.0 - mode.damping_ratio * mode.damping_ratio));
      if (decay * result.window_start > dead_mode_exponent && damped < 0.5 * nyquist) free_modes.push_back({decay, damped});
    }
    result.fitted_modes = static_cast<int>(free_modes.size());
    const Eigen::MatrixXd basis = fit_basis(time, first, omega, result.window_start, free_modes);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> least_squares(basis);
    for (const LinearOutput output : checked_outputs()) {
      Eigen::VectorXd values(basis.rows());
      for (Eigen::Index r = 0; r < values.size(); ++r) {
        values(r) = sample_value(output, run.result.samples[first + static_cast<std::size_t>(r)]);
      }
      const Eigen::VectorXd coefficients = least_squares.solve(values);
      const std::complex<double> fitted(coefficients(1), -coefficients(2));  // Re(Y e^{iωt}) = A cos − B sin…
      const double residual = std::sqrt((basis * coefficients - values).squaredNorm() / static_cast<double>(values.size()));
      const std::complex<double> expected = rao.response[static_cast<std::size_t>(output)][p];
      ChannelCheck channel;
      channel.output = output;
      channel.frequency_domain = std::abs(expected);
      if (model_linear) channel.model_frequency_domain = std::abs(model_linear->models.front().response[static_cast<std::size_t>(output)][p]);
      channel.time_domain = std::abs(fitted) / amplitude;
      channel.phase_difference = wrapped(std::arg(fitted) - std::arg(expected));
      channel.fit_residual = residual / std::abs(fitted);
      result.channels.push_back(channel);
    }
    return result;
  };
  for (std::size_t p = 0; p < request.periods.size(); ++p) {
    PeriodCheck result = run_period(p, request.wave_height);
    const double omega = linear.angular_frequencies[p];
    for (const NaturalMode& mode : rao.modes) {
      if (!mode.resonant()) continue;
      const auto distance = [omega](const NaturalMode& m) { return std::abs(std::log(m.angular_frequency / omega)); };
      if (!result.nearest_mode || distance(mode) < distance(*result.nearest_mode)) result.nearest_mode = mode;
    }
    result.in_half_power_band = result.nearest_mode && result.nearest_mode->in_half_power_band(omega);
    if (request.probe_nonlinearity && result.worst_deviation() > request.tolerance) {
      const PeriodCheck half = run_period(p, 0.5 * request.wave_height);
      NonlinearityProbe probe{0.5 * request.wave_height, half.worst_deviation(), 0.0};
      if (probe.worst_deviation > 0.0 && probe.worst_deviation < result.worst_deviation()) {
        probe.exponent = std::log2(result.worst_deviation() / probe.worst_deviation);
      }
      result.probe = probe;
    }
    check.periods.push_back(std::move(result));
  }
  return check;
}

}  // namespace ffrf::study
