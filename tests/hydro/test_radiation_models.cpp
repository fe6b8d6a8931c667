// The stepped radiation models against the closed-form memory force of an exponential kernel,
//   K = a b e^{−at}, ẋ = sin Ωt (t ≥ 0):  μ(t) = a b [a sin Ωt − Ω cos Ωt + Ω e^{−at}] / (a² + Ω²),
// second-order convergence of the convolution's trapezoidal rule, and the steady state of all three
// models at one frequency: −A∞ẍ − μ equals the constant model's −A(Ω)ẍ − B(Ω)ẋ (Kramers–Kronig).
#include <gtest/gtest.h>

#include <cmath>

#include "hydro/radiation_models.hpp"
#include "kernel_pairs.hpp"

namespace {

using namespace ffrf::hydro;
using ffrf::hydro::test::heave_only;
using ffrf::hydro::test::Lorentzian;

constexpr double kOmega = 0.9;

double exact_memory(const Lorentzian& p, double t) {
  return p.a * p.b * (p.a * std::sin(kOmega * t) - kOmega * std::cos(kOmega * t) + kOmega * std::exp(-p.a * t)) /
         (p.a * p.a + kOmega * kOmega);
}

// Largest |μ − μ_exact| over 0..30 s with ẋ = sin Ωt fed step by step.
double memory_error(RadiationModel& model, const Lorentzian& p, double h) {
  model.reset();
  model.push(PlanarVector::Zero());  // ẋ(0) = 0
  double error = 0.0;
  for (int n = 1; n * h <= 30.0; ++n) {
    const double t = n * h;
    const PlanarVector v(0.0, std::sin(kOmega * t), 0.0);
    error = std::max(error, std::abs(model.memory_force(v)(1) - exact_memory(p, t)));
    model.push(v);
  }
  return error;
}

TEST(RadiationModels, ConvolutionConvergesToTheClosedFormMemoryAtSecondOrder) {
  const Lorentzian p;
  const auto r = heave_only(p, 0.01, 40.0);
  std::array<double, 2> errors{};
  for (int i = 0; i < 2; ++i) {
    const double h = i == 0 ? 0.05 : 0.025;
    ConvolutionRadiationModel model(retardation_function(r, {.time_step = h, .truncation_time = 30.0}));
    errors[static_cast<std::size_t>(i)] = memory_error(model, p, h);
  }
  const double scale = p.a * p.b / std::sqrt(p.a * p.a + kOmega * kOmega);  // amplitude of μ
  EXPECT_LT(errors[0], 1e-3 * scale);
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.6);  // O(h²) (the kernel's own 7e-6 error sets a floor)
}

TEST(RadiationModels, StateSpaceMatchesTheClosedFormMemory) {
  const Lorentzian p;
  const auto k = retardation_function(heave_only(p, 0.01, 40.0), {.time_step = 0.05, .truncation_time = 15.0});
  StateSpaceRadiationModel model(fit_state_space(k, {.tolerance = 1e-3}), k.infinite_frequency_added_mass, 0.05);
  const double scale = p.a * p.b / std::sqrt(p.a * p.a + kOmega * kOmega);
  EXPECT_LT(memory_error(model, p, 0.05), 1e-3 * scale);
  EXPECT_EQ(model.order(), 1);
}

TEST(RadiationModels, AllThreeModelsGiveTheSameSteadyForceAtOneFrequency) {
  const Lorentzian p;
  const double a_inf = 3.0e6;
  const auto r = heave_only(p, 0.01, 40.0, a_inf);
  const auto k = retardation_function(r, {.time_step = 0.05, .truncation_time = 30.0});
  ConvolutionRadiationModel convolution(k);
  StateSpaceRadiationModel state_space(fit_state_space(k, {.tolerance = 1e-3}), k.infinite_frequency_added_mass, 0.05);
  ConstantRadiation at_omega;
  at_omega.added_mass(1, 1) = a_inf + p.added_mass_change(kOmega);
  at_omega.damping(1, 1) = p.damping(kOmega);
  ConstantRadiationModel constant(at_omega);
  std::array<RadiationModel*, 3> models{&convolution, &state_space, &constant};
  for (auto* m : models) m->reset();
  const double h = 0.05;
  double worst = 0.0;
  for (int n = 0; n * h <= 80.0; ++n) {
    const double t = n * h;
    const PlanarVector v(0.0, std::sin(kOmega * t), 0.0), acc(0.0, kOmega * std::cos(kOmega * t), 0.0);
    std::array<double, 3> force{};
    for (std::size_t i = 0; i < 3; ++i) force[i] = -(models[i]->added_mass() * acc)(1) - models[i]->memory_force(v)(1);
    if (t > 40.0) worst = std::max({worst, std::abs(force[0] - force[2]), std::abs(force[1] - force[2])});
    for (auto* m : models) m->push(v);
  }
  EXPECT_LT(worst, 1e-3 * p.b);
}

TEST(RadiationModels, ConvolutionCostIsTheHistoryLength) {
  const auto k = retardation_function(heave_only(Lorentzian{}, 0.01, 10.0), {.time_step = 0.05, .truncation_time = 20.0});
  const ConvolutionRadiationModel model(k);
  EXPECT_EQ(model.history_length(), 400u);  // N = T_c / h samples of ẋ kept
  EXPECT_DOUBLE_EQ(model.current_damping()(1, 1), 0.5 * 0.05 * k.kernel[0](1, 1));
}

}  // namespace
