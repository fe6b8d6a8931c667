// Constant, convolution and state-space radiation models stepped at a fixed step (see radiation_models.hpp).
#include "hydro/radiation_models.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace ffrf::hydro {

ConstantRadiationModel::ConstantRadiationModel(const ConstantRadiation& c) : added_mass_(c.added_mass), damping_(c.damping) {}

ConvolutionRadiationModel::ConvolutionRadiationModel(const RetardationFunction& kernel)
    : step_(kernel.time_step), added_mass_(kernel.infinite_frequency_added_mass) {
  if (kernel.kernel.size() < 2)
    throw std::invalid_argument(fmt::format("convolution radiation: {} kernel samples; valid: at least 2", kernel.kernel.size()));
  const auto n = static_cast<Eigen::Index>(kernel.kernel.size()) - 1;  // K_1 .. K_N
  current_ = 0.5 * step_ * kernel.kernel.front();
  weighted_kernel_.resize(3, 3 * n);
  for (Eigen::Index k = 1; k <= n; ++k)
    weighted_kernel_.middleCols<3>(3 * (k - 1)) = (k == n ? 0.5 : 1.0) * step_ * kernel.kernel[static_cast<std::size_t>(k)];
  history_.setZero(3, n);
}

// Σ_{k=1}^{N} h w_k K_k ẋ_{n+1−k}: the newest stored velocity is ẋ_n (k = 1).
PlanarVector ConvolutionRadiationModel::history_force() const {
  PlanarVector force = PlanarVector::Zero();
  const Eigen::Index n = history_.cols();
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::Index slot = newest_ - k;
    if (slot < 0) slot += n;
    force.noalias() += weighted_kernel_.middleCols<3>(3 * k) * history_.col(slot);
  }
  return force;
}

void ConvolutionRadiationModel::push(const PlanarVector& velocity) {
  newest_ = newest_ + 1 == history_.cols() ? 0 : newest_ + 1;
  history_.col(newest_) = velocity;
}

void ConvolutionRadiationModel::reset() {
  history_.setZero();
  newest_ = 0;
}

StateSpaceRadiationModel::StateSpaceRadiationModel(const RadiationStateSpace& model, const PlanarMatrix& infinite_frequency_added_mass,
                                                   double step)
    : model_(model), added_mass_(infinite_frequency_added_mass) {
  if (!(step > 0.0)) throw std::invalid_argument(fmt::format("state-space radiation: step {} s; valid range > 0", step));
  const auto r = model.a.rows();
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(r, r);
  const Eigen::PartialPivLU<Eigen::MatrixXd> implicit(identity - 0.5 * step * model.a);
  propagator_ = implicit.solve(identity + 0.5 * step * model.a);
  input_ = implicit.solve(0.5 * step * model.b);
  output_propagator_ = model.c * propagator_;
  output_input_ = model.c * input_;
  current_ = output_input_;
  state_.setZero(r);
  scratch_.setZero(r);
}

PlanarVector StateSpaceRadiationModel::history_force() const {
  PlanarVector force;
  force.noalias() = output_propagator_ * state_;
  force.noalias() += output_input_ * last_velocity_;
  return force;
}

// No allocation: the new state goes to the preallocated scratch, then the two swap.
void StateSpaceRadiationModel::push(const PlanarVector& velocity) {
  const PlanarVector sum = last_velocity_ + velocity;
  scratch_.noalias() = propagator_ * state_;
  scratch_.noalias() += input_ * sum;
  state_.swap(scratch_);
  last_velocity_ = velocity;
}

void StateSpaceRadiationModel::reset() {
  state_.setZero();
  last_velocity_.setZero();
}

Eigen::VectorXd StateSpaceRadiationModel::state_derivative(const Eigen::VectorXd& z, const PlanarVector& velocity) const {
  return model_.a * z + model_.b * velocity;
}

PlanarVector StateSpaceRadiationModel::memory_force_of_state(const Eigen::VectorXd& z) const { return model_.c * z; }

}  // namespace ffrf::hydro
