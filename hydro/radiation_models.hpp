// The three radiation models of the Cummins equation, stepped at a fixed step h
// (docs/hydrodynamics.md §3.4). Each gives the radiation force at the end of a step as
//   F_rad(t_{n+1}) = −(A_model ẍ_{n+1}) − μ_{n+1},   μ_{n+1} = history + D ẋ_{n+1},
// so that an implicit integrator solves for ẋ_{n+1} with D added to its damping, then calls push:
//  * ConstantRadiationModel: A_model = A(ω_c), μ = B(ω_c) ẋ (D = B, no history): the cheapest,
//    exact only at ω_c.
//  * ConvolutionRadiationModel (the reference): A_model = A∞, μ by the trapezoidal rule on the
//    sampled kernel (h = its dt, N samples to T_c):
//      μ_{n+1} = h [½K_0 ẋ_{n+1} + Σ_{k=1}^{N−1} K_k ẋ_{n+1−k} + ½K_N ẋ_{n+1−N}],  ẋ = 0 before t = 0.
//    Cost per step 9N multiply-adds and 3N doubles of velocity history (N = T_c/h, ~700 for the
//    fixture's barge at h = 0.05 s).
//  * StateSpaceRadiationModel: A_model = A∞, ż = A z + B ẋ, μ = C z, discretised by the trapezoidal
//    rule (A-stable, second order): z_{n+1} = P z_n + Q (ẋ_n + ẋ_{n+1}), P = (I − hA/2)⁻¹(I + hA/2),
//    Q = (I − hA/2)⁻¹ hB/2; D = C Q, history = C (P z_n + Q ẋ_n). Cost per step O(r² + 6r).
// Variable-step integrators use the state-space model's continuous form (state_derivative).
#pragma once

#include <Eigen/Dense>

#include "hydro/planar_coefficients.hpp"
#include "hydro/retardation.hpp"
#include "hydro/state_space_fit.hpp"

namespace ffrf::hydro {

class RadiationModel {
 public:
  virtual ~RadiationModel() = default;
  virtual const PlanarMatrix& added_mass() const = 0;           // A_model
  virtual const PlanarMatrix& current_damping() const = 0;      // D
  virtual PlanarVector history_force() const = 0;               // μ_{n+1} − D ẋ_{n+1}
  virtual void push(const PlanarVector& velocity) = 0;          // ẋ_{n+1}: advance one step
  virtual void reset() = 0;                                     // at rest, t = 0
  PlanarVector memory_force(const PlanarVector& velocity) const { return history_force() + current_damping() * velocity; }
};

class ConstantRadiationModel final : public RadiationModel {
 public:
  explicit ConstantRadiationModel(const ConstantRadiation& coefficients);
  const PlanarMatrix& added_mass() const override { return added_mass_; }
  const PlanarMatrix& current_damping() const override { return damping_; }
  PlanarVector history_force() const override { return PlanarVector::Zero(); }
  void push(const PlanarVector&) override {}
  void reset() override {}

 private:
  PlanarMatrix added_mass_, damping_;
};

class ConvolutionRadiationModel final : public RadiationModel {
 public:
  explicit ConvolutionRadiationModel(const RetardationFunction& kernel);  // step h = kernel.time_step
  const PlanarMatrix& added_mass() const override { return added_mass_; }
  const PlanarMatrix& current_damping() const override { return current_; }
  PlanarVector history_force() const override;
  void push(const PlanarVector& velocity) override;
  void reset() override;
  double step() const { return step_; }
  std::size_t history_length() const { return static_cast<std::size_t>(history_.cols()); }

 private:
  double step_;
  PlanarMatrix added_mass_, current_;
  Eigen::Matrix<double, 3, Eigen::Dynamic> weighted_kernel_;  // [h w_1 K_1 | ... | h w_N K_N], w = 1, ..., ½
  Eigen::Matrix<double, 3, Eigen::Dynamic> history_;         // ring buffer of ẋ_n, ẋ_{n−1}, ...
  Eigen::Index newest_ = 0;
};

class StateSpaceRadiationModel final : public RadiationModel {
 public:
  StateSpaceRadiationModel(const RadiationStateSpace& model, const PlanarMatrix& infinite_frequency_added_mass, double step);
  const PlanarMatrix& added_mass() const override { return added_mass_; }
  const PlanarMatrix& current_damping() const override { return current_; }
  PlanarVector history_force() const override;
  void push(const PlanarVector& velocity) override;
  void reset() override;
  // Continuous form for ODE solvers: ż = A z + B ẋ, μ = C z.
  Eigen::VectorXd state_derivative(const Eigen::VectorXd& z, const PlanarVector& velocity) const;
  PlanarVector memory_force_of_state(const Eigen::VectorXd& z) const;
  int order() const { return static_cast<int>(state_.size()); }

 private:
  const RadiationStateSpace model_;
  PlanarMatrix added_mass_, current_;
  Eigen::MatrixXd propagator_, input_;  // P, Q
  Eigen::Matrix<double, 3, Eigen::Dynamic> output_propagator_, output_input_;  // C P, C Q
  Eigen::VectorXd state_, scratch_;
  PlanarVector last_velocity_ = PlanarVector::Zero();
};

}  // namespace ffrf::hydro
