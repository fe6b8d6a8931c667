// The shared mode cache and ARPACK's guard:
//  * a mode-count sweep k = 1…12 on one mesh costs one eigen solve, and each k gets the leading k
//    pairs of that solve, whichever order the requests come in (bit-identical bases, so a parallel
//    sweep and a single run agree exactly);
//  * the cached eigenvalues agree with an independent dense solve of the same K, M (second method);
//  * ARPACK keeps Fortran SAVE state, so modal/ serializes it: solves from several threads at once
//    return exactly what the same solves return one after another.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <thread>
#include <vector>

#include "fem/beam_model.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/mode_cache.hpp"

namespace {

using namespace ffrf;

const fem::BeamMesh kMesh{120.0, 16, {2.1e11, 1.27, 11.4, 1.0e4}};  // the reference crane's boom

bool identical(const modal::EigenPairs& a, const modal::EigenPairs& b) {
  return a.eigenvalues.size() == b.eigenvalues.size() && (a.eigenvalues.array() == b.eigenvalues.array()).all() &&
         a.eigenvectors.cols() == b.eigenvectors.cols() && (a.eigenvectors.array() == b.eigenvectors.array()).all();
}

TEST(ModeCache, OneSolveServesTheModeCountSweepInAnyOrder) {
  modal::ModeCache ascending, descending;
  std::vector<modal::EigenPairs> up(13), down(13);
  for (int k = 1; k <= 12; ++k) up[k] = ascending.lowest_modes(kMesh, fem::Boundary::clamped_free, k, modal::EigenSolverKind::arpack);
  for (int k = 12; k >= 1; --k) down[k] = descending.lowest_modes(kMesh, fem::Boundary::clamped_free, k, modal::EigenSolverKind::arpack);
  EXPECT_EQ(ascending.eigen_solves(), 1);
  EXPECT_EQ(descending.eigen_solves(), 1);
  for (int k = 1; k <= 12; ++k) {
    EXPECT_TRUE(identical(up[k], down[k])) << "k = " << k;
    EXPECT_TRUE((up[k].eigenvalues.array() == up[12].eigenvalues.head(k).array()).all()) << "k = " << k;
  }
  // A larger request is served by a second solve; the first stays as it was.
  const modal::EigenPairs more = ascending.lowest_modes(kMesh, fem::Boundary::clamped_free, 13, modal::EigenSolverKind::arpack);
  EXPECT_EQ(more.eigenvalues.size(), 13);
  EXPECT_EQ(ascending.eigen_solves(), 2);
  EXPECT_TRUE(identical(ascending.lowest_modes(kMesh, fem::Boundary::clamped_free, 4, modal::EigenSolverKind::arpack), up[4]));
  // Another mesh is another problem.
  fem::BeamMesh finer = kMesh;
  finer.element_count = 32;
  ascending.lowest_modes(finer, fem::Boundary::clamped_free, 2, modal::EigenSolverKind::arpack);
  EXPECT_EQ(ascending.eigen_solves(), 3);
}

TEST(ModeCache, EigenvaluesAgreeWithADenseSolve) {
  modal::ModeCache cache;
  const modal::EigenPairs cached = cache.lowest_modes(kMesh, fem::Boundary::clamped_free, 8, modal::EigenSolverKind::arpack);
  const fem::BeamModel beam = fem::make_beam_model(kMesh, fem::Boundary::clamped_free);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Eigen::MatrixXd(beam.stiffness),
                                                                        Eigen::MatrixXd(beam.mass), Eigen::EigenvaluesOnly);
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(cached.eigenvalues(i) / dense.eigenvalues()(i), 1.0, 1e-10) << "mode " << i + 1;
}

TEST(ArpackGuard, ConcurrentSolvesEqualSerialSolves) {
  // Problems of different sizes, so interleaved SAVE state would corrupt them.
  std::vector<fem::BeamModel> beams;
  for (int elements : {8, 12, 16, 24, 32, 48}) {
    fem::BeamMesh mesh = kMesh;
    mesh.element_count = elements;
    beams.push_back(fem::make_beam_model(mesh, fem::Boundary::clamped_free));
  }
  const auto solve = [&](std::size_t i) {
    modal::EigenRequest request;
    request.nev = 6 + static_cast<int>(i);
    return modal::solve_generalized(beams[i].stiffness, beams[i].mass, request, modal::EigenSolverKind::arpack);
  };
  std::vector<modal::EigenPairs> serial;
  for (std::size_t i = 0; i < beams.size(); ++i) serial.push_back(solve(i));
  constexpr int rounds = 10;
  std::vector<std::vector<modal::EigenPairs>> concurrent(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < concurrent.size(); ++t) {
    threads.emplace_back([&, t] {
      for (int round = 0; round < rounds; ++round) {
        for (std::size_t i = 0; i < beams.size(); ++i) concurrent[t].push_back(solve((i + t) % beams.size()));
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (std::size_t t = 0; t < concurrent.size(); ++t) {
    for (std::size_t n = 0; n < concurrent[t].size(); ++n) {
      EXPECT_TRUE(identical(concurrent[t][n], serial[(n % beams.size() + t) % beams.size()])) << "thread " << t << ", solve " << n;
    }
  }
}

}  // namespace
