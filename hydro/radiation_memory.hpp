// The radiation force of the Cummins equation for a variable-step integrator (CVODE, IDA, ARKODE,
// generalized-α in the crane): F_rad(t) = −A_model ẍ(t) − μ(t), μ evaluated at any time t from the
// hull velocity ẋ(t) of the state being tried and a velocity history recorded from accepted states
// (docs/hydrodynamics.md §3.5). The history is piecewise linear between recorded samples
// (t_k, ẋ_k), and linear from the last sample (t_n, ẋ_n) to the trial (t, ẋ(t)):
//  * constant:    A_model = A(ω_c), μ = B(ω_c) ẋ(t) (no history).
//  * convolution: A_model = A∞, μ(t) = ∫₀^{min(t, T_c)} K(s) ẋ(t − s) ds by the trapezoidal rule on the
//    kernel's samples s_j = j·dt (the reference). Cost per evaluation O(N), N = T_c/dt.
//  * state-space: A_model = A∞, K(t) ≈ C e^{At} B fitted (state_space_fit.hpp) and diagonalized,
//    A = V Λ V⁻¹; the modal states w = V⁻¹z obey ẇ_i = λ_i w_i + b_iᵀẋ and are advanced exactly
//    for the piecewise-linear ẋ (exponential integration): over δ = t − t_n,
//      w_i(t) = e^{λδ} w_i(t_n) + b_iᵀ[ẋ_n (φ0 − φ1) + ẋ(t) φ1],  φ0 = (e^{λδ} − 1)/λ,
//      φ1 = (e^{λδ} − 1 − λδ)/(λ²δ),  μ = Re Σ c_i w_i.  Cost per evaluation O(r).
// ∂μ/∂ẋ(t) (velocity_derivative) is what a Newton iteration adds to the hull's damping. The
// history's accuracy is the recording interval's: linear interpolation, O(Δt²ẍ').
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <string_view>
#include <vector>

#include "hydro/planar_coefficients.hpp"
#include "hydro/retardation.hpp"
#include "hydro/state_space_fit.hpp"

namespace ffrf::hydro {

enum class RadiationKind { constant, state_space, convolution };
std::string_view to_string(RadiationKind kind);  // "constant", "state-space", "convolution"
bool parse_radiation_kind(std::string_view text, RadiationKind& kind);
inline constexpr std::string_view kRadiationChoices = "constant|state-space|convolution";

// Immutable data of one radiation model (shared by the runs that use it).
struct RadiationMemoryModel {
  RadiationKind kind = RadiationKind::constant;
  PlanarMatrix added_mass = PlanarMatrix::Zero();  // A(ω_c) (constant) or A∞
  PlanarMatrix damping = PlanarMatrix::Zero();     // B(ω_c) (constant only)
  RetardationFunction kernel;                      // convolution only
  Eigen::VectorXcd poles;                          // λ_i (state-space)
  Eigen::MatrixXcd input;                          // V⁻¹B (r × 3)
  Eigen::MatrixXcd output;                         // C V (3 × r)
  int order = 0;                                   // state-space order r
  double fit_error = 0.0;                          // state-space e_r
};

RadiationMemoryModel constant_memory(const ConstantRadiation& coefficients);
RadiationMemoryModel convolution_memory(const RetardationFunction& kernel);
// Throws std::runtime_error when A is not diagonalizable to working accuracy (names the condition).
RadiationMemoryModel state_space_memory(const RadiationStateSpace& fit, const PlanarMatrix& infinite_frequency_added_mass);
// The model seen from another point of the hull: with ẋ_O = T ẋ_G and F_G = Tᵀ F_O (a rigid-body
// transfer), A, B, K, b and c become TᵀAT, TᵀBT, TᵀKT, b T, Tᵀc.
RadiationMemoryModel transferred(RadiationMemoryModel model, const PlanarMatrix& transfer);

// The run state: the velocity history and, for the state-space model, the modal states at the last
// recorded sample. Allocation-free in force() and velocity_derivative().
class RadiationMemory {
 public:
  RadiationMemory() = default;
  explicit RadiationMemory(std::shared_ptr<const RadiationMemoryModel> model);

  bool active() const { return model_ != nullptr; }
  const RadiationMemoryModel& model() const { return *model_; }
  const PlanarMatrix& added_mass() const { return model_->added_mass; }
  PlanarVector force(double t, const PlanarVector& velocity) const;  // μ(t)
  PlanarMatrix velocity_derivative(double t) const;                 // ∂μ/∂ẋ(t)
  // An accepted state's velocity at t. t = 0 starts a new record (at rest before it); a t not after
  // the last recorded one is ignored (a repeated output).
  void record(double t, const PlanarVector& velocity);
  void reset();
  std::size_t recorded() const { return times_.size(); }

 private:
  PlanarVector velocity_at(double tau, double t, const PlanarVector& velocity, std::size_t& cursor) const;
  void advance_states(double t, const PlanarVector& velocity, Eigen::VectorXcd& states) const;

  std::shared_ptr<const RadiationMemoryModel> model_;
  std::vector<double> times_;
  std::vector<PlanarVector> velocities_;
  Eigen::VectorXcd states_;           // w at the last recorded time (state-space)
  mutable Eigen::VectorXcd scratch_;  // w at a trial time
};

}  // namespace ffrf::hydro
