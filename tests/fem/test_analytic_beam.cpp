// The analytic frequency references against published roots of the Euler–Bernoulli frequency
// equations (Blevins, "Formulas for natural frequency and mode shape", table 8-1).
#include <gtest/gtest.h>

#include <numbers>

#include "fem/analytic_beam.hpp"

namespace {

using namespace ffrf::fem;
const BeamMesh analytic_mesh{10.0, 4, {2.1e11, 0.01, 8.333e-6, 78.5}};

TEST(AnalyticBeam, ClampedFreeRootsMatchPublishedValues) {
  const double published[] = {1.875104069, 4.694091133, 7.854757438, 10.995540735, 14.137168391};
  const auto modes = analytic_bending_modes(analytic_mesh, Boundary::clamped_free, 5);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(modes[i].beta_l, published[i], 1e-9) << "mode " << i + 1;
  const double ei = analytic_mesh.section.bending_rigidity(), rho = analytic_mesh.section.mass_per_length;
  EXPECT_NEAR(modes[0].angular_frequency, published[0] * published[0] * std::sqrt(ei / (rho * std::pow(analytic_mesh.length, 4))), 1e-8);
}

TEST(AnalyticBeam, FreeFreeRootsMatchPublishedValues) {
  const double published[] = {4.730040745, 7.853204624, 10.995607838};
  const auto modes = analytic_bending_modes(analytic_mesh, Boundary::free_free, 3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(modes[i].beta_l, published[i], 1e-9) << "mode " << i + 1;
  EXPECT_EQ(rigid_mode_count(Boundary::free_free), 3);
}

TEST(AnalyticBeam, AxialAndPinnedModes) {
  const double c = std::sqrt(analytic_mesh.section.axial_rigidity() / analytic_mesh.section.mass_per_length);
  const auto axial = analytic_axial_modes(analytic_mesh, Boundary::clamped_free, 2);
  EXPECT_NEAR(axial[1].angular_frequency, 1.5 * std::numbers::pi * c / analytic_mesh.length, 1e-9);
  EXPECT_NEAR(analytic_axial_modes(analytic_mesh, Boundary::free_free, 1)[0].angular_frequency, std::numbers::pi * c / analytic_mesh.length, 1e-9);
  EXPECT_NEAR(analytic_bending_modes(analytic_mesh, Boundary::pinned_pinned, 2)[1].beta_l, 2 * std::numbers::pi, 1e-15);
}

}  // namespace
