// `ffrf rao` on one model per boom (study/rao.cpp): each boom model is built and linearised once,
// and the excitation at each ω comes from that model in the regular wave (scene::with_waters). The
// second method is the path it replaced, written out here: a crane built from scratch in the regular
// wave at every frequency (scene::build_crane_equations), its excitation, the [bem] hull's Z(iω), and the
// response — equal within 1e-12 on the reference scene and on the BEM barge.
// Also the memory hull's natural modes: a Newton start that cannot converge (no steps allowed, or an
// impedance that is not finite) keeps the constant system's root and says so (NaturalMode::unrefined).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "multibody/linearisation.hpp"
#include "study/rao.hpp"
#include "study/rao_bem.hpp"
#include "study/run_pipeline.hpp"
#include "study_test_support.hpp"

namespace ffrf {
namespace {

std::vector<double> frequencies(double shortest, double longest, int count) {
  std::vector<double> omegas;
  for (int i = 0; i < count; ++i) omegas.push_back(2.0 * std::numbers::pi / (longest + (shortest - longest) * i / (count - 1)));
  return omegas;
}

// The pre-sharing path: the crane built again in each frequency's regular wave.
std::array<std::vector<std::complex<double>>, multibody::linear_output_count> per_frequency_builds(
    const scene::Scene& scene, const scene::BoomChoice& choice, const std::vector<double>& omegas, double a) {
  scene::Scene calm = scene;
  calm.wave.reset();
  calm.sea.reset();
  modal::ModeCache modes;
  study::PreparedRun prepared = study::prepare_run(calm, choice, &modes);
  const multibody::LinearisedCrane linear = multibody::linearise_crane(*prepared.equations, prepared.statics.z);
  const multibody::OutputMap outputs = multibody::linear_outputs(*prepared.equations, linear);
  const study::HullImpedance impedance = scene.bem ? study::bem_hull_impedance(scene, study::BemRadiationSource::file) : nullptr;
  std::array<std::vector<std::complex<double>>, multibody::linear_output_count> response;
  for (const double omega : omegas) {
    const auto waved = scene::build_crane_equations(study::with_regular_wave(scene, 2.0 * a, 2.0 * std::numbers::pi / omega, 0.0), choice, &modes);
    const Eigen::VectorXcd force = multibody::wave_excitation(*waved, linear, omega, a);
    Eigen::MatrixXd mass = linear.mass, damping = linear.damping;
    if (impedance) {
      const Eigen::Matrix3cd z = impedance(std::complex<double>(0.0, omega));
      mass.block<3, 3>(linear.hull_at, linear.hull_at) -= z.real() / (omega * omega);
      damping.block<3, 3>(linear.hull_at, linear.hull_at) += z.imag() / omega;
    }
    const Eigen::VectorXcd x = study::frequency_response(mass, damping, linear.stiffness, force, omega);
    const Eigen::VectorXcd y = outputs.position.cast<std::complex<double>>() * x +
                               std::complex<double>(0.0, omega) * (outputs.velocity.cast<std::complex<double>>() * x);
    for (int k = 0; k < multibody::linear_output_count; ++k) response[static_cast<std::size_t>(k)].push_back(y(k));
  }
  return response;
}

void expect_per_frequency_builds(const std::string& file, double shortest, double longest) {
  const scene::Scene scene = test::scene_file(file);
  study::RaoRequest request;
  request.angular_frequencies = frequencies(shortest, longest, 12);
  const study::RaoResult result = study::response_amplitude_operators(scene, request);
  ASSERT_EQ(result.models.size(), study::rao_models(scene).size());
  double worst = 0.0;
  for (const study::ModelRao& model : result.models) {
    const auto before = per_frequency_builds(scene, model.choice, request.angular_frequencies, request.excitation_amplitude);
    for (std::size_t k = 0; k < before.size(); ++k) {
      double scale = 0.0;
      for (const auto& value : before[k]) scale = std::max(scale, std::abs(value));
      if (scale == 0.0) continue;  // the rigid boom's deflection
      ASSERT_EQ(model.response[k].size(), before[k].size());
      for (std::size_t i = 0; i < before[k].size(); ++i) {
        const double difference = std::abs(model.response[k][i] - before[k][i]);
        worst = std::max(worst, difference / std::abs(before[k][i]));
        EXPECT_LE(difference, 1e-12 * std::abs(before[k][i]))
            << file << " " << model.choice.label() << " " << multibody::to_string(static_cast<multibody::LinearOutput>(k)) << " at ω = "
            << request.angular_frequencies[i];
      }
    }
  }
  std::printf("%s: worst relative difference to per-frequency builds %.3g\n", file.c_str(), worst);
}

TEST(RaoSharedModel, OneModelPerBoomGivesThePerFrequencyBuildsRaosOnTheReferenceScene) {
  expect_per_frequency_builds("paper_floating_crane.toml", 4.0, 30.0);
}

TEST(RaoSharedModel, OneModelPerBoomGivesThePerFrequencyBuildsRaosOnTheBemBarge) {
  expect_per_frequency_builds("bem_barge_crane.toml", 5.0, 20.0);
}

// The BEM barge's rigid crane linearised in calm water, and its hull impedance (the convolution's kernel).
struct MemoryHull {
  multibody::LinearisedCrane linear;
  study::HullImpedance impedance;
  double refine_below = 0.0;
};
MemoryHull memory_hull() {
  scene::Scene scene = test::scene_file("bem_barge_crane.toml");
  scene.wave.reset();
  scene.sea.reset();
  study::PreparedRun prepared = study::prepare_run(scene, {scene::BoomKind::rigid, 1});
  return {multibody::linearise_crane(*prepared.equations, prepared.statics.z),
          study::bem_hull_impedance(scene, study::BemRadiationSource::model), 2.0 * scene.bem->radiation.frequency.back()};
}

TEST(RaoSharedModel, ANewtonStartThatCannotConvergeIsFlaggedAndKeepsTheConstantRoot) {
  const MemoryHull hull = memory_hull();
  const std::vector<study::NaturalMode> constant = study::natural_modes(hull.linear);
  const std::vector<study::NaturalMode> refined = study::natural_modes(hull.linear, hull.impedance, hull.refine_below);
  ASSERT_EQ(refined.size(), constant.size());
  int asked = 0, moved = 0;
  for (std::size_t j = 0; j < refined.size(); ++j) {
    EXPECT_EQ(refined[j].unrefined, "") << "mode " << j + 1 << " converges with the default 40 steps";
    asked += constant[j].angular_frequency <= hull.refine_below;
    moved += std::abs(refined[j].angular_frequency - constant[j].angular_frequency) > 1e-6 * constant[j].angular_frequency;
  }
  ASSERT_GT(asked, 0);
  EXPECT_GT(moved, 0) << "the memory moves some roots: refinement is not a no-op here";

  // No Newton step allowed: every mode asked to be refined is flagged and is the constant system's.
  const std::vector<study::NaturalMode> capped = study::natural_modes(hull.linear, hull.impedance, hull.refine_below, 0);
  ASSERT_EQ(capped.size(), constant.size());
  int flagged = 0;
  for (std::size_t j = 0; j < capped.size(); ++j) {
    EXPECT_EQ(capped[j].angular_frequency, constant[j].angular_frequency);
    EXPECT_EQ(capped[j].damping_ratio, constant[j].damping_ratio);
    const bool asked_here = constant[j].angular_frequency <= hull.refine_below;
    EXPECT_EQ(capped[j].unrefined.empty(), !asked_here) << "mode " << j + 1;
    if (asked_here) {
      EXPECT_NE(capped[j].unrefined.find("did not converge in 0 steps"), std::string::npos) << capped[j].unrefined;
    }
    flagged += !capped[j].unrefined.empty();
  }
  EXPECT_EQ(flagged, asked);

  // An impedance that is not finite: Newton stops at its first step, the constant roots stay.
  const study::HullImpedance broken = [](std::complex<double>) {
    return Eigen::Matrix3cd::Constant(std::numeric_limits<double>::quiet_NaN());
  };
  const std::vector<study::NaturalMode> stopped = study::natural_modes(hull.linear, broken, hull.refine_below);
  for (std::size_t j = 0; j < stopped.size(); ++j) {
    EXPECT_EQ(stopped[j].angular_frequency, constant[j].angular_frequency);
    if (constant[j].angular_frequency <= hull.refine_below) {
      EXPECT_NE(stopped[j].unrefined.find("not finite"), std::string::npos) << "mode " << j + 1 << ": " << stopped[j].unrefined;
    }
  }
}

}  // namespace
}  // namespace ffrf
