// The BEM wave excitation recorded once by FFT and read back by Hermite interpolation (see the header).
#include "sea/excitation_record.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace ffrf::sea {

namespace {

constexpr const char* channel_names[3] = {"surge", "heave", "pitch"};

bool channel_is_zero(const BemExcitation& excitation, int channel) {
  for (const Eigen::Vector3cd& f : excitation.force)
    if (f(channel) != std::complex<double>(0.0)) return false;
  return true;
}

void check(const BemExcitation& excitation, const ExcitationRecordOptions& options) {
  if (excitation.frequency.size() != excitation.force.size() || excitation.phase.size() != excitation.force.size())
    throw std::invalid_argument(fmt::format("excitation record: {} forces, {} frequencies, {} phases; valid: equal counts",
                                            excitation.force.size(), excitation.frequency.size(), excitation.phase.size()));
  if (!(options.duration > 0.0) || !std::isfinite(options.duration))
    throw std::invalid_argument(fmt::format("excitation record: duration {} s; valid range > 0, finite", options.duration));
  for (int c = 0; c < 3; ++c) {
    const double tolerance = options.tolerance(c);
    if ((tolerance > 0.0 && std::isfinite(tolerance)) || (tolerance == 0.0 && channel_is_zero(excitation, c))) continue;
    throw std::invalid_argument(fmt::format("excitation record: {} tolerance {} {}; valid range > 0, finite (0 only for a "
                                            "channel without force)",
                                            channel_names[c], tolerance, c == 2 ? "N m" : "N"));
  }
}

// Why the excitation's components are not the harmonic grid's ω_i = (n0 + i) Δω, or empty when they are.
std::string grid_mismatch(const BemExcitation& excitation, const WaveField& wave) {
  const WaveField::HarmonicGrid& grid = wave.harmonic_grid();
  if (!grid.active)
    return "the wave's components are not on a harmonic grid omega_i = (n0 + i) d_omega in deep water "
           "(WaveField::harmonic_grid)";
  if (excitation.force.size() != wave.components().size())
    return fmt::format("the excitation has {} components, the wave {}", excitation.force.size(), wave.components().size());
  for (std::size_t i = 0; i < excitation.frequency.size(); ++i) {
    const double omega = excitation.frequency[i];
    const double on_grid = (grid.first_harmonic + static_cast<double>(i)) * grid.frequency_step;
    if (!(std::abs(omega - on_grid) <= 4.0 * std::numeric_limits<double>::epsilon() * omega))
      return fmt::format("the excitation's component {} has omega = {:.17g} rad/s, the wave's grid {:.17g} rad/s", i, omega,
                         on_grid);
  }
  return {};
}

}  // namespace

Eigen::Vector3d excitation_standard_deviation(const BemExcitation& excitation) {
  Eigen::Vector3d power = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3cd& f : excitation.force) power += 0.5 * f.cwiseAbs2();
  return power.cwiseSqrt();
}

Eigen::Vector3d excitation_tolerance(const BemExcitation& excitation, double fraction) {
  if (!(fraction > 0.0) || !std::isfinite(fraction))
    throw std::invalid_argument(
        fmt::format("excitation tolerance: fraction {} of the standard deviation; valid range > 0, finite", fraction));
  return fraction * excitation_standard_deviation(excitation);
}

ExcitationRecordOutcome ExcitationRecord::build(const BemExcitation& excitation, const WaveField& wave,
                                                const ExcitationRecordOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  check(excitation, options);
  ExcitationRecordOutcome outcome;
  outcome.refusal = grid_mismatch(excitation, wave);
  if (!outcome.refusal.empty()) return outcome;

  ExcitationRecord result;
  result.tolerance_ = options.tolerance;
  // Channels divided by ε_c (a zero channel by 1: it records zeros), so one tolerance of 1 holds each
  // channel to its own ε_c.
  for (int c = 0; c < 3; ++c) result.channel_scale_(c) = options.tolerance(c) > 0.0 ? options.tolerance(c) : 1.0;
  const std::size_t count = excitation.force.size();
  hydro::HarmonicSums sums;
  sums.frequency_step = wave.harmonic_grid().frequency_step;
  sums.first_harmonic = static_cast<std::int64_t>(std::llround(wave.harmonic_grid().first_harmonic));
  sums.time_sign = 1;  // e^{+iω t}: BemExcitation's Re{F e^{i(ω t + ψ)}}
  sums.real_parts.assign(3, std::vector<std::complex<double>>(count));  // the forces are real parts: two to a channel
  for (std::size_t i = 0; i < count; ++i) {
    const std::complex<double> phasor = std::polar(1.0, excitation.phase[i]);
    for (int c = 0; c < 3; ++c)
      sums.real_parts[static_cast<std::size_t>(c)][i] = excitation.force[i](c) * phasor / result.channel_scale_(c);
  }
  hydro::HarmonicRecordOptions record_options;
  record_options.duration = options.duration;
  record_options.tolerance = 1.0;
  record_options.memory_limit = options.memory_limit;
  try {
    result.record_ = hydro::HarmonicRecord::build(sums, record_options);
  } catch (const std::length_error& e) {
    outcome.refusal = e.what();  // above the memory limit: the size is in the message
    return outcome;
  } catch (const std::runtime_error& e) {
    outcome.refusal = e.what();  // the tolerance not reached, or FFTW could not plan
    return outcome;
  }
  result.exact_ = excitation;
  result.build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.record = std::move(result);
  return outcome;
}

Eigen::Vector3d ExcitationRecord::at(double t) const {
  if (!record_.covers(t)) return exact_.at(t);
  std::complex<double> recorded[2];  // surge and heave force in one channel, pitch moment in the next
  record_.evaluate(t, recorded);
  return {channel_scale_(0) * record_.real_channel(recorded, 0), channel_scale_(1) * record_.real_channel(recorded, 1),
          channel_scale_(2) * record_.real_channel(recorded, 2)};
}

}  // namespace ffrf::sea
