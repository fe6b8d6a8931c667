// BEM wave excitation for the wave field's components (see the header).
#include "sea/bem_excitation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

namespace ffrf::sea {

Eigen::Vector3d BemExcitation::at(double t) const {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < force.size(); ++i) {
    const double angle = frequency[i] * t + phase[i];
    const double c = std::cos(angle), s = std::sin(angle);
    total += force[i].real() * c - force[i].imag() * s;  // Re{F e^{iθ}}
  }
  return total;
}

Eigen::Matrix3d rigid_transfer(const Eigen::Vector2d& offset) {
  Eigen::Matrix3d t = Eigen::Matrix3d::Identity();
  t(0, 2) = -offset.y();
  t(1, 2) = offset.x();
  return t;
}

hydro::PlanarComplexVector excitation_at(const hydro::PlanarExcitation& table, double direction, double omega) {
  const double wanted = direction > 0.0 ? 0.0 : 180.0;
  const auto heading = std::find_if(table.heading_degrees.begin(), table.heading_degrees.end(),
                                    [&](double beta) { return std::abs(std::remainder(beta - wanted, 360.0)) < 1e-6; });
  if (heading == table.heading_degrees.end()) {
    throw std::invalid_argument(table.source + ": no excitation for the heading β = " + std::to_string(wanted) +
                                " deg the wave travels along (" + (direction > 0.0 ? "following" : "head") +
                                " sea); the BEM run must include it");
  }
  const auto& f = table.frequency;
  if (f.empty() || omega < f.front() * (1.0 - 1e-9) || omega > f.back() * (1.0 + 1e-9)) {
    throw std::invalid_argument(table.source + ": the wave component ω = " + std::to_string(omega) +
                                " rad/s lies outside the excitation table's " + std::to_string(f.empty() ? 0.0 : f.front()) +
                                " … " + std::to_string(f.empty() ? 0.0 : f.back()) +
                                " rad/s; give the BEM run those periods or change the wave");
  }
  const auto& force = table.force[static_cast<std::size_t>(heading - table.heading_degrees.begin())];
  const std::size_t upper = static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), omega) - f.begin());
  if (upper == 0) return force.front();
  if (upper >= f.size()) return force.back();
  const double w = (omega - f[upper - 1]) / (f[upper] - f[upper - 1]);
  return force[upper - 1] * (1.0 - w) + force[upper] * w;
}

BemExcitation bem_excitation(const hydro::PlanarExcitation& table, const WaveField& wave, double origin_x,
                             const Eigen::Vector2d& origin_offset) {
  const Eigen::Matrix3cd transfer_t = rigid_transfer(origin_offset).transpose().cast<std::complex<double>>();
  BemExcitation out;
  for (const WaveComponent& c : wave.components()) {
    out.force.push_back(c.amplitude * (transfer_t * excitation_at(table, wave.direction(), c.angular_frequency)));
    out.frequency.push_back(c.angular_frequency);
    out.phase.push_back(-wave.direction() * (c.wave_number * origin_x + c.phase));
  }
  return out;
}

}  // namespace ffrf::sea
