// `ffrf rao` on a [bem] scene (cases/bem_barge_crane.toml: WAMIT A(ω), B(ω), X(ω), convolution
// radiation; study/rao_bem.hpp): the time domain against the frequency domain — regular-wave time-domain runs (CVODE, the
// Cummins convolution, the .3 excitation, the box's calm-water hydrostatics) reproduce the RAOs within
// 1 % in amplitude for hull heave, hull pitch and cargo heave, rigid, nodal and modal booms — and why
// the check must fit the memory hull's own free modes; the long-wave limit (the hull and the cargo
// rise with the surface: WAMIT's excitation against ffrf's own pressure integration); the files'
// radiation against the kernel the time domain realises; the band error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>

#include "scene/scene_loader.hpp"
#include "study/rao.hpp"
#include "study/rao_check.hpp"
#include "study_test_support.hpp"

namespace ffrf {
namespace {

using multibody::LinearOutput;

study::TimeDomainCheckRequest linear_check() {
  study::TimeDomainCheckRequest request;
  request.periods = {8.0, 10.0, 14.0};
  // 2 cm: at 8 s the wave is next to the cargo's pendulum mode (7.93 s), whose swing a 0.2 m wave
  // makes nonlinear (1.1 % off the RAO; 0.07 % at 2 cm).
  request.wave_height = 0.02;
  return request;
}

void print(const study::TimeDomainCheck& check) {
  for (const auto& period : check.periods) {
    for (const auto& c : period.channels) {
      std::printf("%s T=%.0f s %-11s RAO %.6g (model %.6g) time domain %.6g: deviation %+.2e (model %+.2e), phase %+.1e rad, "
                  "residual %.1e, %d free modes, %ld steps\n",
                  check.choice.label().c_str(), period.period, std::string(multibody::to_string(c.output)).c_str(),
                  c.frequency_domain, c.model_frequency_domain, c.time_domain, c.deviation(), c.model_deviation(),
                  c.phase_difference, c.fit_residual, period.fitted_modes, period.stats.steps);
    }
  }
}

TEST(RaoBem, RegularWaveRunsReproduceTheBemRaosOfRigidNodalAndModalBooms) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  ASSERT_TRUE(scene.bem && scene.bem->radiation_model == hydro::RadiationKind::convolution);
  for (const scene::BoomChoice& choice : study::rao_models(scene)) {
    const study::TimeDomainCheck check = study::check_time_domain(scene, choice, linear_check());
    print(check);
    for (const auto& period : check.periods) {
      for (const auto& c : period.channels) {
        EXPECT_LT(std::abs(c.deviation()), 0.01) << choice.label() << " T = " << period.period << " " << multibody::to_string(c.output);
        EXPECT_LT(std::abs(c.model_deviation()), 0.01) << choice.label() << " " << period.period;
        EXPECT_LT(std::abs(c.phase_difference), 0.01) << choice.label() << " " << period.period;
      }
    }
    EXPECT_TRUE(check.passed());
  }
}

// The diagnosis of the first try's 34 %: a memory hull's transient (heave and pitch at 6 s, ζ ≈ 0.07–0.08,
// not dead three periods after the ramp) is not the constant system's (A∞, ½·dt·K(0): longer damping
// time, another frequency); fitted with the constant system's modes, the harmonic absorbs it.
TEST(RaoBem, TheCheckMustFitTheMemoryHullsOwnFreeModes) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  study::TimeDomainCheckRequest request = linear_check();
  request.periods = {8.0};
  const study::TimeDomainCheck own = study::check_time_domain(scene, {scene::BoomKind::rigid, 1}, request);
  request.memory_free_modes = false;
  const study::TimeDomainCheck constant = study::check_time_domain(scene, {scene::BoomKind::rigid, 1}, request);
  print(own);
  print(constant);
  EXPECT_LT(own.worst_deviation(), 0.01);
  EXPECT_GT(constant.worst_deviation(), 0.05);
}

// Next to the cargo's pendulum mode (7.93 s) a 0.2 m wave is not small: at 8 s the check fails a
// 0.5 % tolerance, the run at half the height deviates at most 0.6 × as much (amplitude-dependent:
// nonlinear response, not a defect of the linearisation), and the height suggested from the
// measured scaling passes.
TEST(RaoBem, AFailureNextToAResonanceShrinksWithTheWaveHeight) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  study::TimeDomainCheckRequest request;
  request.periods = {8.0};
  request.tolerance = 0.005;
  const study::TimeDomainCheck check = study::check_time_domain(scene, {scene::BoomKind::rigid, 1}, request);
  print(check);
  ASSERT_FALSE(check.passed());
  const study::PeriodCheck& period = check.periods.front();
  ASSERT_TRUE(period.probe && period.nearest_mode);
  std::printf("nearest mode %s T = %.4g s zeta = %.3g; half height %.3g m: %.3e (p = %.2f)\n", period.nearest_mode->dominant.c_str(),
              period.nearest_mode->period(), period.nearest_mode->damping_ratio, period.probe->wave_height, period.probe->worst_deviation,
              period.probe->exponent);
  EXPECT_TRUE(period.amplitude_dependent());
  EXPECT_NEAR(period.nearest_mode->period(), 8.0, 0.5);
  const std::optional<double> height = check.suggested_wave_height();
  ASSERT_TRUE(height);
  EXPECT_LT(*height, request.wave_height);
  request.wave_height = *height;
  request.probe_nonlinearity = false;
  EXPECT_TRUE(study::check_time_domain(scene, {scene::BoomKind::rigid, 1}, request).passed()) << *height;
}

// The state-space radiation (fit within 2 %): the run against the RAO of its own kernel, C(iω − A)⁻¹B,
// and against the files' (apart by the fit's error only).
TEST(RaoBem, StateSpaceRadiationRunsReproduceTheirOwnRao) {
  scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  scene.bem->radiation_model = hydro::RadiationKind::state_space;
  study::TimeDomainCheckRequest request = linear_check();
  request.periods = {8.0, 12.0};
  const study::TimeDomainCheck check = study::check_time_domain(scene, {scene::BoomKind::rigid, 1}, request);
  print(check);
  for (const auto& period : check.periods) {
    for (const auto& c : period.channels) {
      EXPECT_LT(std::abs(c.model_deviation()), 0.01) << period.period << " " << multibody::to_string(c.output);
      EXPECT_LT(std::abs(c.deviation()), 0.02) << period.period << " " << multibody::to_string(c.output);
    }
  }
}

TEST(RaoBem, LongWavesLiftTheHullAndTheCargoWithTheSurface) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  study::RaoRequest request;
  request.models = {{scene::BoomKind::rigid, 1}};
  for (const double period : {100.0, 150.0}) request.angular_frequencies.push_back(2.0 * std::numbers::pi / period);
  const study::RaoResult rao = study::response_amplitude_operators(scene, request);
  ASSERT_TRUE(rao.bem_radiation && *rao.bem_radiation == study::BemRadiationSource::file);
  // Quasi-static: the .3 file's heave force over ffrf's box restoring → 1 (two independent codes).
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& response = rao.models.front().response;
    std::printf("T = %.0f s: hull heave %.6f m/m, cargo heave %.6f m/m\n", 2.0 * std::numbers::pi / rao.angular_frequencies[i],
                std::abs(response[static_cast<std::size_t>(LinearOutput::hull_heave)][i]),
                std::abs(response[static_cast<std::size_t>(LinearOutput::cargo_heave)][i]));
    EXPECT_NEAR(std::abs(response[static_cast<std::size_t>(LinearOutput::hull_heave)][i]), 1.0, 1e-3);
    EXPECT_NEAR(std::abs(response[static_cast<std::size_t>(LinearOutput::cargo_heave)][i]), 1.0, 1e-3);
  }
}

// The physical RAO (the files' A, B) and the one of the kernel the time domain convolves (A∞ and the
// trapezoid transform of the truncated K) differ by the kernel's back-transform error only — away from
// the moored surge resonance (29.8 s, ζ = 3·10⁻⁵), where the RAO is the inverse of a damping B11(0.21
// rad/s) that a kernel truncated at T_c = 35 s does not resolve (3.4 % apart at 29.5 s).
TEST(RaoBem, FileRadiationAndTheConvolutionsKernelGiveTheSameRaos) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  study::RaoRequest request;
  request.models = {{scene::BoomKind::rigid, 1}};
  for (double period = 5.0; period <= 27.0; period += 0.5) request.angular_frequencies.push_back(2.0 * std::numbers::pi / period);
  const study::RaoResult file = study::response_amplitude_operators(scene, request);
  request.bem_radiation = study::BemRadiationSource::model;
  const study::RaoResult model = study::response_amplitude_operators(scene, request);
  double worst = 0.0;
  for (const LinearOutput output : study::checked_outputs()) {
    const auto k = static_cast<std::size_t>(output);
    for (std::size_t i = 0; i < request.angular_frequencies.size(); ++i) {
      const double a = std::abs(file.models.front().response[k][i]), b = std::abs(model.models.front().response[k][i]);
      worst = std::max(worst, std::abs(b / a - 1.0));

    }
  }
  std::printf("largest relative difference file/kernel over 5–27 s: %.2e\n", worst);
  EXPECT_LT(worst, 3e-3);
}

TEST(RaoBem, AFrequencyOutsideTheFilesIsANamedError) {
  const scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  study::RaoRequest request;
  request.models = {{scene::BoomKind::rigid, 1}};
  request.angular_frequencies = {1.0, 10.0};  // the fixture's .1 ends at 0.9 s (6.98 rad/s)
  try {
    (void)study::response_amplitude_operators(scene, request);
    FAIL() << "no error for ω = 10 rad/s";
  } catch (const scene::SceneError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("bem.radiation_file"), std::string::npos) << message;
    EXPECT_NE(message.find("barge.1"), std::string::npos) << message;
    EXPECT_NE(message.find("ω = 10 rad/s"), std::string::npos) << message;
    EXPECT_NE(message.find("valid range 0.0418879 … 6.98132 rad/s"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace ffrf
