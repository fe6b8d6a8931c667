// Radiation memory for variable-step integrators (see the header; docs/hydrodynamics.md §3.5).
#include "hydro/radiation_memory.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include "linalg/dense_solvers.hpp"

namespace ffrf::hydro {

std::string_view to_string(RadiationKind kind) {
  switch (kind) {
    case RadiationKind::constant: return "constant";
    case RadiationKind::state_space: return "state-space";
    case RadiationKind::convolution: return "convolution";
  }
  return "?";
}

bool parse_radiation_kind(std::string_view text, RadiationKind& kind) {
  for (RadiationKind k : {RadiationKind::constant, RadiationKind::state_space, RadiationKind::convolution}) {
    if (text == to_string(k)) {
      kind = k;
      return true;
    }
  }
  return false;
}

RadiationMemoryModel constant_memory(const ConstantRadiation& coefficients) {
  RadiationMemoryModel model;
  model.kind = RadiationKind::constant;
  model.added_mass = coefficients.added_mass;
  model.damping = coefficients.damping;
  return model;
}

RadiationMemoryModel convolution_memory(const RetardationFunction& kernel) {
  if (kernel.kernel.size() < 2 || !(kernel.time_step > 0.0)) {
    throw std::invalid_argument("convolution radiation: the kernel needs at least two samples and a time step > 0");
  }
  RadiationMemoryModel model;
  model.kind = RadiationKind::convolution;
  model.added_mass = kernel.infinite_frequency_added_mass;
  model.kernel = kernel;
  return model;
}

RadiationMemoryModel state_space_memory(const RadiationStateSpace& fit, const PlanarMatrix& infinite_frequency_added_mass) {
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(fit.a);
  if (eigen.info() != Eigen::Success) throw std::runtime_error("state-space radiation: the eigen-decomposition of A failed");
  const Eigen::MatrixXcd vectors = eigen.eigenvectors();
  const Eigen::FullPivLU<Eigen::MatrixXcd> lu(vectors);
  const Eigen::MatrixXcd rebuilt = vectors * eigen.eigenvalues().asDiagonal() * lu.inverse();
  const double mismatch = (rebuilt - fit.a.cast<std::complex<double>>()).norm() / fit.a.norm();
  if (!lu.isInvertible() || !(mismatch < 1e-8)) {
    throw std::runtime_error("state-space radiation: A of the order-" + std::to_string(fit.order) +
                             " fit is not diagonalizable to working accuracy (V Λ V⁻¹ misses A by " +
                             std::to_string(mismatch) + "); try another --fit tolerance");
  }
  RadiationMemoryModel model;
  model.kind = RadiationKind::state_space;
  model.added_mass = infinite_frequency_added_mass;
  model.poles = eigen.eigenvalues();
  model.input = lu.solve(fit.b.cast<std::complex<double>>());
  model.output = fit.c.cast<std::complex<double>>() * vectors;
  model.order = fit.order;
  model.fit_error = fit.impulse_error;
  return model;
}

RadiationMemoryModel transferred(RadiationMemoryModel model, const PlanarMatrix& transfer) {
  const PlanarMatrix& t = transfer;
  model.added_mass = t.transpose() * model.added_mass * t;
  model.damping = t.transpose() * model.damping * t;
  for (PlanarMatrix& k : model.kernel.kernel) k = t.transpose() * k * t;
  model.kernel.infinite_frequency_added_mass = t.transpose() * model.kernel.infinite_frequency_added_mass * t;
  if (model.order > 0) {
    model.input = model.input * t.cast<std::complex<double>>();
    model.output = t.transpose().cast<std::complex<double>>() * model.output;
  }
  return model;
}

RadiationMemory::RadiationMemory(std::shared_ptr<const RadiationMemoryModel> model) : model_(std::move(model)) {
  if (model_ && model_->order > 0) {
    states_ = Eigen::VectorXcd::Zero(model_->order);
    scratch_ = states_;
  }
  times_.reserve(4096);
  velocities_.reserve(4096);
}

void RadiationMemory::reset() {
  times_.clear();
  velocities_.clear();
  if (states_.size() > 0) states_.setZero();
}

namespace {

// φ0 = (e^z − 1)/λ and φ1 = (e^z − 1 − z)/(λ z) for z = λδ (series for small |z|).
void exponential_weights(std::complex<double> lambda, double delta, std::complex<double>& decay,
                         std::complex<double>& phi0, std::complex<double>& phi1) {
  const std::complex<double> z = lambda * delta;
  decay = std::exp(z);
  if (std::abs(z) < 1e-3) {
    phi0 = delta * (1.0 + z / 2.0 + z * z / 6.0 + z * z * z / 24.0);
    phi1 = delta * (0.5 + z / 6.0 + z * z / 24.0 + z * z * z / 120.0);
  } else {
    phi0 = (decay - 1.0) / lambda;
    phi1 = (decay - 1.0 - z) / (lambda * z);
  }
}

}  // namespace

void RadiationMemory::advance_states(double t, const PlanarVector& velocity, Eigen::VectorXcd& states) const {
  const double last_time = times_.empty() ? 0.0 : times_.back();
  const PlanarVector last_velocity = times_.empty() ? PlanarVector::Zero() : velocities_.back();
  const double delta = t - last_time;
  if (!(delta > 0.0)) {
    states = states_;
    return;
  }
  const RadiationMemoryModel& m = *model_;
  for (int i = 0; i < m.order; ++i) {
    std::complex<double> decay, phi0, phi1;
    exponential_weights(m.poles(i), delta, decay, phi0, phi1);
    std::complex<double> drive = 0.0;
    for (int j = 0; j < 3; ++j) drive += m.input(i, j) * (last_velocity(j) * (phi0 - phi1) + velocity(j) * phi1);
    states(i) = decay * states_(i) + drive;
  }
}

PlanarVector RadiationMemory::velocity_at(double tau, double t, const PlanarVector& velocity, std::size_t& cursor) const {
  const double last_time = times_.empty() ? 0.0 : times_.back();
  if (tau >= last_time) {
    const PlanarVector last_velocity = times_.empty() ? PlanarVector::Zero() : velocities_.back();
    if (!(t > last_time)) return velocity;
    return last_velocity + (velocity - last_velocity) * ((tau - last_time) / (t - last_time));
  }
  if (times_.empty() || tau <= times_.front()) return PlanarVector::Zero();  // at rest before the record
  while (cursor > 0 && times_[cursor - 1] > tau) --cursor;  // times_[cursor − 1] ≤ tau < times_[cursor]
  const std::size_t k = cursor - 1;
  const double w = (tau - times_[k]) / (times_[cursor] - times_[k]);
  return velocities_[k] + (velocities_[cursor] - velocities_[k]) * w;
}

PlanarVector RadiationMemory::force(double t, const PlanarVector& velocity) const {
  const RadiationMemoryModel& m = *model_;
  switch (m.kind) {
    case RadiationKind::constant: return m.damping * velocity;
    case RadiationKind::state_space: {
      advance_states(t, velocity, scratch_);
      PlanarVector memory = PlanarVector::Zero();
      for (int i = 0; i < m.order; ++i) {
        for (int r = 0; r < 3; ++r) memory(r) += (m.output(r, i) * scratch_(i)).real();
      }
      return memory;
    }
    case RadiationKind::convolution: {
      const auto& kernel = m.kernel.kernel;
      const double dt = m.kernel.time_step;
      const std::size_t last = kernel.size() - 1;
      PlanarVector sum = 0.5 * (kernel[0] * velocity);
      std::size_t cursor = times_.empty() ? 0 : times_.size() - 1;
      for (std::size_t j = 1; j <= last; ++j) {
        const double tau = t - static_cast<double>(j) * dt;
        if (tau <= 0.0) break;  // at rest before t = 0
        const double weight = j == last ? 0.5 : 1.0;
        sum.noalias() += weight * (kernel[j] * velocity_at(tau, t, velocity, cursor));
      }
      return dt * sum;
    }
  }
  return PlanarVector::Zero();
}

PlanarMatrix RadiationMemory::velocity_derivative(double t) const {
  const RadiationMemoryModel& m = *model_;
  switch (m.kind) {
    case RadiationKind::constant: return m.damping;
    case RadiationKind::state_space: {
      const double delta = t - (times_.empty() ? 0.0 : times_.back());
      PlanarMatrix derivative = PlanarMatrix::Zero();
      if (!(delta > 0.0)) return derivative;
      for (int i = 0; i < m.order; ++i) {
        std::complex<double> decay, phi0, phi1;
        exponential_weights(m.poles(i), delta, decay, phi0, phi1);
        for (int r = 0; r < 3; ++r) {
          for (int c = 0; c < 3; ++c) derivative(r, c) += (m.output(r, i) * m.input(i, c) * phi1).real();
        }
      }
      return derivative;
    }
    case RadiationKind::convolution: {
      const auto& kernel = m.kernel.kernel;
      const double dt = m.kernel.time_step;
      const double last_time = times_.empty() ? 0.0 : times_.back();
      PlanarMatrix derivative = 0.5 * dt * kernel[0];
      if (!(t > last_time)) return derivative;
      for (std::size_t j = 1; j < kernel.size(); ++j) {
        const double tau = t - static_cast<double>(j) * dt;
        if (tau < last_time || tau <= 0.0) break;
        const double weight = j + 1 == kernel.size() ? 0.5 : 1.0;
        derivative += weight * dt * ((tau - last_time) / (t - last_time)) * kernel[j];
      }
      return derivative;
    }
  }
  return PlanarMatrix::Zero();
}

void RadiationMemory::record(double t, const PlanarVector& velocity) {
  if (!active()) return;
  if (t <= 0.0) {
    reset();
    times_.push_back(0.0);
    velocities_.push_back(velocity);
    return;
  }
  if (!times_.empty() && t <= times_.back()) return;
  if (model_->order > 0) {
    advance_states(t, velocity, scratch_);
    states_ = scratch_;
  }
  times_.push_back(t);
  velocities_.push_back(velocity);
}

}  // namespace ffrf::hydro
