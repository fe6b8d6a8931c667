// FE natural frequencies of the cantilever (cases/cantilever.toml's beam) against Euler–Bernoulli
// theory, through the production path (assembly, ARPACK, mode classification): bending f1..f4 with
// N = 64 to 1e-6 (βL = 1.875104069, 4.694091133, 7.854757438, 10.995540735), axial f1, f2 with
// N = 64 to 1e-3 (c = π/2, 3π/2), and the convergence order of the bending frequencies in N from a
// log–log least-squares fit, close to 4 (cubic Hermite elements: O(h⁴) eigenvalue error).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "fem/assembly.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/mode_kind.hpp"

namespace {

using namespace ffrf;

const double length = 10.0, youngs = 2.1e11, area = 0.01, inertia = 8.333e-6, rho_a = 7850.0 * 0.01;

std::vector<modal::ClassifiedMode> cantilever_modes(int elements, int count) {
  const fem::BeamMesh mesh{length, elements, {youngs, area, inertia, rho_a}};
  const fem::FreeMatrices m = fem::assemble_free(mesh, fem::Boundary::clamped_free);
  modal::EigenRequest request;
  request.nev = count;
  const modal::EigenPairs pairs = modal::solve_generalized(m.stiffness, m.mass, request, modal::EigenSolverKind::arpack);
  return modal::classify_modes(mesh, fem::Boundary::clamped_free, m.dofs, m.mass, pairs.eigenvalues, pairs.eigenvectors);
}

std::vector<double> frequencies_of(const std::vector<modal::ClassifiedMode>& modes, fem::ModeKind kind) {
  std::vector<double> f;
  for (const auto& m : modes)
    if (m.kind == kind) f.push_back(m.angular_frequency / (2 * std::numbers::pi));
  return f;
}

TEST(BeamFrequencies, CantileverBendingAndAxialMatchEulerBernoulli) {
  const auto modes = cantilever_modes(64, 8);
  const auto bending = frequencies_of(modes, fem::ModeKind::bending);
  const auto axial = frequencies_of(modes, fem::ModeKind::axial);
  ASSERT_GE(bending.size(), 4u);
  ASSERT_GE(axial.size(), 1u);
  const double beta_l[] = {1.875104069, 4.694091133, 7.854757438, 10.995540735};
  for (int i = 0; i < 4; ++i) {
    const double exact = beta_l[i] * beta_l[i] / (2 * std::numbers::pi * length * length) * std::sqrt(youngs * inertia / rho_a);
    EXPECT_NEAR(bending[i] / exact, 1.0, 1e-6) << "bending mode " << i + 1;
  }
  // The second axial mode lies above the 8 lowest modes; ask for enough.
  const auto more = frequencies_of(cantilever_modes(64, 24), fem::ModeKind::axial);
  ASSERT_GE(more.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const double exact = (2 * i + 1) * std::numbers::pi / 2 / (2 * std::numbers::pi * length) * std::sqrt(youngs * area / rho_a);
    EXPECT_NEAR(more[i] / exact, 1.0, 1e-3) << "axial mode " << i + 1;
  }
}

TEST(BeamFrequencies, BendingFrequenciesConvergeAtFourthOrder) {
  const double beta_l[] = {1.875104069, 4.694091133, 7.854757438, 10.995540735};
  for (int mode = 0; mode < 4; ++mode) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int count = 0;
    for (int elements : {8, 16, 32}) {
      const auto bending = frequencies_of(cantilever_modes(elements, 8), fem::ModeKind::bending);
      const double exact = beta_l[mode] * beta_l[mode] / (2 * std::numbers::pi * length * length) * std::sqrt(youngs * inertia / rho_a);
      const double x = std::log(static_cast<double>(elements)), y = std::log(std::abs(bending[mode] - exact) / exact);
      sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
    }
    const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
    std::printf("bending mode %d: convergence order %.3f\n", mode + 1, -slope);
    EXPECT_NEAR(-slope, 4.0, 0.25) << "bending mode " << mode + 1;
  }
}

}  // namespace
