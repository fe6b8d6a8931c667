// Modal coordinates in the coupled crane against the nodal model of the same mesh:
//  * a modal basis spanning all free nodal DOFs gives the nodal time history (same physics in
//    other coordinates) to 1e-7 relative;
//  * the modal truncation error falls as the number of vibration modes k grows;
//  * with static correction modes, k = 2 is at least 10× more accurate in cargo heave than without
//    (the static deflection under the cargo is carried by the static modes).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cstdio>

#include "multibody/error_metrics.hpp"
#include "study/error_measure.hpp"
#include "../scene/crane_test_support.hpp"
#include "linalg/dense_solvers.hpp"

namespace modal_crane_test {

using namespace ffrf;
using multibody::OutputChannel;

multibody::RunSettings settings(double duration, double tolerance) {
  multibody::RunSettings s;
  s.relative_tolerance = s.absolute_tolerance = tolerance;
  s.duration = duration;
  s.output_interval = 0.05;
  return s;
}

multibody::RunResult run_from_equilibrium(multibody::CraneEquations& equations, const multibody::RunSettings& s) {
  return multibody::simulate(equations, multibody::solve_static_equilibrium(equations, equations.initial_guess()).z, s);
}

TEST(ModalCrane, FullModalBasisReproducesTheNodalTimeHistory) {
  const scene::Scene scene = test::reference_scene();
  const int elements = 3;
  auto beam = scene::boom_beam(scene, elements);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense{Eigen::MatrixXd(beam->stiffness), Eigen::MatrixXd(beam->mass)};
  modal::ModalBasis basis;
  basis.vectors = dense.eigenvectors();  // all 9 M-orthonormal modes
  basis.vibration_count = static_cast<int>(basis.vectors.cols());
  auto modal_equations = multibody::make_crane_equations(scene::build_crane_parameters(scene, modal::ModalCoordinates(beam, basis)));
  auto nodal_equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, elements, 0, false});
  const auto s = settings(30.0, 1e-11);
  const auto modal_run = run_from_equilibrium(*modal_equations, s);
  const auto nodal_run = run_from_equilibrium(*nodal_equations, s);
  double worst = 0.0;
  for (OutputChannel c : multibody::all_channels) {
    const auto a = test::column(modal_run, [c](const multibody::CraneOutputs& o) { return multibody::channel_value(o, c); });
    const auto b = test::column(nodal_run, [c](const multibody::CraneOutputs& o) { return multibody::channel_value(o, c); });
    worst = std::max(worst, test::relative_history_error(a, b));
  }
  std::printf("full modal basis vs nodal: worst relative history error %.3g\n", worst);
  EXPECT_LT(worst, 1e-7);
}

TEST(ModalCrane, ErrorFallsWithModeCountAndStaticModesCarryTheQuasiStaticLoad) {
  const scene::Scene scene = test::reference_scene();
  const double duration = 50.0;  // ramp (20 s) + three wave periods
  const double window = study::ramp_end(scene);
  auto nodal_equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 16, 0, false});
  const auto s = settings(duration, 1e-9);
  const auto reference = run_from_equilibrium(*nodal_equations, s);
  auto cargo_heave_error = [&](int k, bool with_static) {
    auto equations = scene::build_crane_equations(scene, {scene::BoomKind::modal, 16, k, with_static});
    return multibody::compare_runs(run_from_equilibrium(*equations, s), reference, window)[OutputChannel::cargo_heave].normalized_rms;
  };
  const double e1 = cargo_heave_error(1, false), e2 = cargo_heave_error(2, false), e4 = cargo_heave_error(4, false);
  const double e8 = cargo_heave_error(8, false), e2s = cargo_heave_error(2, true);
  std::printf("cargo heave normalized RMS error vs nodal N=16: k=1 %.3g, k=2 %.3g, k=4 %.3g, k=8 %.3g, k=2+static %.3g\n",
              e1, e2, e4, e8, e2s);
  EXPECT_LT(e2, e1);
  EXPECT_LT(e4, e2);
  EXPECT_LT(e8, e4);
  EXPECT_LT(10.0 * e2s, e2) << "static modes must make k = 2 at least 10x more accurate";
}

}  // namespace modal_crane_test

namespace modal_crane_test {

TEST(ModalCrane, ModeCacheSolvesOncePerMeshAndGivesTheSameModel) {
  using namespace ffrf;
  const scene::Scene scene = test::reference_scene();
  modal::ModeCache cache;
  for (int k : {1, 2, 4, 8, 12}) {
    for (bool with_static : {false, true}) {
      const scene::BoomChoice choice{scene::BoomKind::modal, 16, k, with_static};
      const modal::ModalCoordinates cached = scene::modal_coordinates(scene, choice, &cache);
      const modal::ModalCoordinates direct = scene::modal_coordinates(scene, choice);
      ASSERT_EQ(cached.size(), direct.size());
      // Same subspace and the same reduced physics: equal stiffness spectra and static tip response.
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> a(cached.stiffness()), b(direct.stiffness());
      EXPECT_LT((a.eigenvalues() - b.eigenvalues()).norm(), 1e-8 * b.eigenvalues().norm()) << choice.label();
    }
  }
  EXPECT_EQ(cache.eigen_solves(), 1) << "one eigen solve for the whole mode-count sweep on one mesh";
}

}  // namespace modal_crane_test
