// The realization fit against kernels of known order (an exponential is order 1 with pole −a, a
// damped cosine order 2 with poles −α ± iβ) and against the fixture's kernel: the impulse response
// recomputed here sample by sample within the stated error, stability, and the frequency response
// against the file's B(ω) and A(ω) − A∞ (a different quantity from the one fitted).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include "hydro/state_space_fit.hpp"
#include "hydro/wamit_reader.hpp"
#include "kernel_pairs.hpp"
#include "linalg/dense_solvers.hpp"

namespace {

using namespace ffrf::hydro;
using ffrf::hydro::test::DampedCosine;
using ffrf::hydro::test::heave_only;
using ffrf::hydro::test::Lorentzian;

TEST(StateSpaceFit, ExponentialKernelIsOrderOneWithItsDecayRate) {
  const Lorentzian pair;
  const auto k = retardation_function(heave_only(pair, 0.01, 40.0), {.time_step = 0.05, .truncation_time = 15.0});
  const auto ss = fit_state_space(k, {.tolerance = 1e-3});
  EXPECT_EQ(ss.order, 1);
  EXPECT_NEAR(ss.a(0, 0), -pair.a, 1e-4 * pair.a);
  EXPECT_NEAR(impulse_response(ss, 2.0)(1, 1), pair.kernel(2.0), 1e-4 * pair.kernel(0.0));
}

TEST(StateSpaceFit, DampedCosineIsOrderTwoWithItsPoles) {
  const DampedCosine pair;
  const auto k = retardation_function(heave_only(pair, 0.005, 40.0), {.time_step = 0.05, .truncation_time = 25.0});
  const auto ss = fit_state_space(k, {.tolerance = 1e-3});
  ASSERT_EQ(ss.order, 2);
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(ss.a);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(eig.eigenvalues()(i).real(), -pair.alpha, 1e-4);
    EXPECT_NEAR(std::abs(eig.eigenvalues()(i).imag()), pair.beta, 1e-4);
  }
}

TEST(StateSpaceFit, FixtureKernelWithinTheStatedErrorStableAndMatchingTheFrequencyData) {
  const auto radiation = read_wamit_radiation(std::string(FFRF_SOURCE_DIR "/tests/hydro/data/barge.1"), {1.0, 1000.0, 9.81});
  const auto k = retardation_function(radiation);
  double previous_error = 1.0;
  int previous_order = 0;
  for (double tolerance : {0.05, 0.02, 0.01}) {
    const auto ss = fit_state_space(k, {.tolerance = tolerance});
    // The impulse-response error, recomputed here from C e^{At} B at every kernel sample.
    const PlanarVector scale(1 / std::sqrt(k.kernel[0](0, 0)), 1 / std::sqrt(k.kernel[0](1, 1)), 1 / std::sqrt(k.kernel[0](2, 2)));
    double error = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < k.kernel.size(); ++i) {
      const PlanarMatrix diff = scale.asDiagonal() * (k.kernel[i] - impulse_response(ss, static_cast<double>(i) * k.time_step)) * scale.asDiagonal();
      error += diff.squaredNorm();
      norm += (scale.asDiagonal() * k.kernel[i] * scale.asDiagonal()).squaredNorm();
    }
    EXPECT_LE(std::sqrt(error / norm), tolerance) << "tolerance " << tolerance;
    EXPECT_NEAR(std::sqrt(error / norm), ss.impulse_error, 1e-6);
    EXPECT_LT(ss.slowest_decay, 0.0);
    EXPECT_GT(ss.order, previous_order);
    EXPECT_LT(ss.impulse_error, previous_error);
    previous_order = ss.order;
    previous_error = ss.impulse_error;
    // Frequency response: Re K̂(iω) = B(ω), Im K̂(iω) = ω (A(ω) − A∞), heave and pitch, against the
    // file, relative to the largest |B_ii|: within 3 × the impulse tolerance.
    for (int d : {1, 2}) {
      double largest = 0.0, damping_error = 0.0, mass_error = 0.0;
      for (std::size_t i = 0; i < radiation.frequency.size(); ++i) {
        const double w = radiation.frequency[i];
        const auto response = frequency_response(ss, w);
        largest = std::max(largest, radiation.damping[i](d, d));
        damping_error = std::max(damping_error, std::abs(response(d, d).real() - radiation.damping[i](d, d)));
        mass_error = std::max(mass_error, std::abs(response(d, d).imag() - w * (radiation.added_mass[i](d, d) - radiation.infinite_frequency_added_mass(d, d))));
      }
      EXPECT_LT(damping_error, 3 * tolerance * largest) << "dof " << d << " tolerance " << tolerance;
      EXPECT_LT(mass_error, 3 * tolerance * largest) << "dof " << d << " tolerance " << tolerance;
    }
  }
}

TEST(StateSpaceFit, NamesTheBestErrorWhenTheOrderCapIsTooLow) {
  const auto radiation = read_wamit_radiation(std::string(FFRF_SOURCE_DIR "/tests/hydro/data/barge.1"), {1.0, 1000.0, 9.81});
  try {
    fit_state_space(retardation_function(radiation), {.tolerance = 1e-3, .max_order = 3});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no stable model up to order 3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("raise the maximum order"), std::string::npos) << e.what();
  }
}

}  // namespace
