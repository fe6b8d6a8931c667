// The radiation memory of the crane's variable-step integrators (hydro/radiation_memory.hpp) against
// the closed-form memory force of an exponential kernel,
//   K = a b e^{−at}, ẋ = sin Ωt (t ≥ 0):  μ(t) = a b [a sin Ωt − Ω cos Ωt + Ω e^{−at}] / (a² + Ω²),
// with the history recorded every h and the force asked at trial times between the records (as a
// BDF step does); second-order convergence of the convolution in h; ∂μ/∂ẋ against differences of
// μ; the steady state of all three models at one frequency: −A∞ẍ − μ equals the constant model's
// −A(Ω)ẍ − B(Ω)ẋ (Kramers–Kronig).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>

#include "hydro/radiation_memory.hpp"
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

PlanarVector heave_velocity(double t) { return PlanarVector(0.0, std::sin(kOmega * t), 0.0); }

// Largest |μ − μ_exact| over 0..30 s: records every h, the force asked at t_n + θh (θ = 0.3, 1, 1.6:
// inside the last interval, at the next record time, beyond it before it is recorded).
double memory_error(const RadiationMemoryModel& data, const Lorentzian& p, double h) {
  RadiationMemory memory(std::make_shared<const RadiationMemoryModel>(data));
  memory.record(0.0, PlanarVector::Zero());
  double error = 0.0;
  for (int n = 0; n * h <= 30.0; ++n) {
    const double t = n * h;
    for (const double theta : {0.3, 1.0, 1.6}) {
      const double trial = t + theta * h;
      error = std::max(error, std::abs(memory.force(trial, heave_velocity(trial))(1) - exact_memory(p, trial)));
    }
    memory.record(t + h, heave_velocity(t + h));
  }
  return error;
}

double amplitude(const Lorentzian& p) { return p.a * p.b / std::sqrt(p.a * p.a + kOmega * kOmega); }

TEST(RadiationMemory, ConvolutionConvergesToTheClosedFormMemoryAtSecondOrder) {
  const Lorentzian p;
  const auto r = heave_only(p, 0.01, 40.0);
  std::array<double, 2> errors{};
  for (int i = 0; i < 2; ++i) {
    const double h = i == 0 ? 0.05 : 0.025;
    errors[static_cast<std::size_t>(i)] =
        memory_error(convolution_memory(retardation_function(r, {.time_step = h, .truncation_time = 30.0})), p, h);
  }
  EXPECT_LT(errors[0], 1e-3 * amplitude(p));
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.8);  // O(h²) (the kernel's own 7e-6 error sets a floor)
}

TEST(RadiationMemory, StateSpaceMatchesTheClosedFormMemory) {
  const Lorentzian p;
  const auto k = retardation_function(heave_only(p, 0.01, 40.0), {.time_step = 0.05, .truncation_time = 15.0});
  const auto model = state_space_memory(fit_state_space(k, {.tolerance = 1e-3}), k.infinite_frequency_added_mass);
  EXPECT_EQ(model.order, 1);
  EXPECT_NEAR(model.poles(0).real(), -p.a, 1e-4);
  // Exact exponential integration: only the linear interpolation of ẋ between records (O(h²)).
  EXPECT_LT(memory_error(model, p, 0.05), 1e-3 * amplitude(p));
}

TEST(RadiationMemory, VelocityDerivativeIsTheDifferenceQuotientOfTheForce) {
  const Lorentzian p;
  const auto k = retardation_function(heave_only(p, 0.01, 40.0), {.time_step = 0.05, .truncation_time = 15.0});
  for (const auto& data : {convolution_memory(k), state_space_memory(fit_state_space(k, {.tolerance = 1e-3}), k.infinite_frequency_added_mass)}) {
    RadiationMemory memory(std::make_shared<const RadiationMemoryModel>(data));
    for (int n = 0; n <= 40; ++n) memory.record(n * 0.05, heave_velocity(n * 0.05));
    for (const double trial : {2.0, 2.013, 2.07, 2.11}) {
      const PlanarVector v = heave_velocity(trial), dv(0.0, 1e-3, 0.0);
      const double difference = (memory.force(trial, v + dv)(1) - memory.force(trial, v - dv)(1)) / 2e-3;
      EXPECT_NEAR(memory.velocity_derivative(trial)(1, 1), difference, 1e-6 * std::abs(difference) + 1e-9 * p.b)
          << to_string(data.kind) << " at t = " << trial;
    }
  }
}

TEST(RadiationMemory, AllThreeModelsGiveTheSameSteadyForceAtOneFrequency) {
  const Lorentzian p;
  const double a_inf = 3.0e6;
  const auto k = retardation_function(heave_only(p, 0.01, 40.0, a_inf), {.time_step = 0.05, .truncation_time = 30.0});
  ConstantRadiation at_omega;
  at_omega.added_mass(1, 1) = a_inf + p.added_mass_change(kOmega);
  at_omega.damping(1, 1) = p.damping(kOmega);
  std::array<RadiationMemory, 3> models{
      RadiationMemory(std::make_shared<const RadiationMemoryModel>(convolution_memory(k))),
      RadiationMemory(std::make_shared<const RadiationMemoryModel>(
          state_space_memory(fit_state_space(k, {.tolerance = 1e-3}), k.infinite_frequency_added_mass))),
      RadiationMemory(std::make_shared<const RadiationMemoryModel>(constant_memory(at_omega)))};
  const double h = 0.05;
  double worst = 0.0;
  for (int n = 0; n * h <= 80.0; ++n) {
    const double t = n * h;
    const PlanarVector v = heave_velocity(t), acc(0.0, kOmega * std::cos(kOmega * t), 0.0);
    std::array<double, 3> force{};
    for (std::size_t i = 0; i < 3; ++i) force[i] = -(models[i].added_mass() * acc)(1) - models[i].force(t, v)(1);
    if (t > 40.0) worst = std::max({worst, std::abs(force[0] - force[2]), std::abs(force[1] - force[2])});
    for (auto& m : models) m.record(t, v);
  }
  EXPECT_LT(worst, 1e-3 * p.b);
}

TEST(RadiationMemory, ARecordAtTimeZeroStartsANewRunAndRepeatsAreIgnored) {
  const Lorentzian p;
  const auto k = retardation_function(heave_only(p, 0.01, 40.0), {.time_step = 0.05, .truncation_time = 15.0});
  RadiationMemory memory(std::make_shared<const RadiationMemoryModel>(convolution_memory(k)));
  for (int n = 0; n <= 20; ++n) memory.record(n * 0.05, heave_velocity(n * 0.05));
  memory.record(0.5, PlanarVector(0.0, 99.0, 0.0));  // a repeated output: ignored
  EXPECT_EQ(memory.recorded(), 21u);
  const double before = memory.force(1.02, heave_velocity(1.02))(1);
  EXPECT_NEAR(before, exact_memory(p, 1.02), 1e-3 * amplitude(p));
  memory.record(0.0, PlanarVector::Zero());
  EXPECT_EQ(memory.recorded(), 1u);
  EXPECT_NEAR(memory.force(0.0, PlanarVector::Zero())(1), 0.0, 1e-12);
}

}  // namespace
