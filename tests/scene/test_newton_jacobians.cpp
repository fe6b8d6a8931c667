// The structured linearizations the Newton solvers use (analytic elastic blocks, the wire's columns
// and the dense hull/cargo/frame columns by differences) against an independent second method:
// central differences of the equations' own right-hand side (minimal coordinates: −M⁻¹K = ∂z̈/∂z,
// −M⁻¹D = ∂z̈/∂ż) and of the full-coordinate residual Q − M a, on the reference crane (rigid, nodal
// N = 4 and 16 with static stiffening, modal k = 2 + static) at a moving, deformed state in the wave,
// and on the spinning hub with centrifugal stiffening. Also the bordered band LU against Eigen's dense
// LU, and the structure: nodal booms banded, modal ones dense.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"
#include "solve/bordered_band_matrix.hpp"
#include "multibody/crane_equations.hpp"
#include "solve/ida_newton.hpp"
#include "multibody/crane_statics.hpp"

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

namespace newton_jacobians_test {

using namespace ffrf;
using multibody::CraneEquations;
using solve::SecondOrderJacobian;

struct Case {
  std::string scene;
  scene::BoomChoice choice;
  double t;
};

std::unique_ptr<CraneEquations> build(const Case& c) {
  scene::Scene scene = scene::load_scene(std::string(FFRF_SOURCE_DIR "/cases/") + c.scene);
  return scene::build_crane_equations(scene, c.choice);
}

// A moving, deformed state: the static equilibrium plus deterministic offsets of 2 % of each
// coordinate's typical size (small enough that the wire, stretched 6 cm by the cargo, stays taut, so
// its terms count), velocities of half that size per second.
void moving_state(CraneEquations& eq, Eigen::VectorXd& z, Eigen::VectorXd& z_dot) {
  const Eigen::VectorXd scale = eq.coordinate_scale();
  z = eq.minimal_size() > 0 ? multibody::solve_static_equilibrium(eq, eq.initial_guess()).z : Eigen::VectorXd(0);
  z_dot.resize(z.size());
  for (int i = 0; i < z.size(); ++i) {
    z(i) += 0.02 * scale(i) * std::sin(1.7 * i + 0.4);
    z_dot(i) = 0.5 * scale(i) * std::cos(2.3 * i + 0.1);
  }
}

// Tolerance of the Newton matrices: the dense columns are forward differences (increments 1e-6 of each
// coordinate's size, multibody/crane_equations_jacobian.ipp), exact to ~1e-6 of the matrix's diagonal
// scaling; 1e-5 leaves room and still catches any missing or wrong term (those are O(1)).
constexpr double kNewtonMatrixTolerance = 1e-5;

// The Newton matrix S(γ) = M + γD + γ²K these blocks build, against the reference's: the largest
// |ΔS_ij| / √(|S_ii S_jj|) over γ = 10⁻³, 10⁻², 10⁻¹ (the steps' range), i.e. the error relative to
// the diagonal scaling that makes S's diagonal 1.
double newton_matrix_error(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& damping, const Eigen::MatrixXd& stiffness,
                           const Eigen::MatrixXd& ref_damping, const Eigen::MatrixXd& ref_stiffness) {
  double worst = 0.0;
  for (const double gamma : {1e-3, 1e-2, 1e-1}) {
    const Eigen::MatrixXd s = mass + gamma * damping + gamma * gamma * stiffness;
    const Eigen::MatrixXd ref = mass + gamma * ref_damping + gamma * gamma * ref_stiffness;
    const Eigen::VectorXd diagonal = ref.diagonal().cwiseAbs().cwiseSqrt();
    for (int j = 0; j < s.cols(); ++j) {
      for (int i = 0; i < s.rows(); ++i) {
        const double e = std::abs(s(i, j) - ref(i, j)) / (diagonal(i) * diagonal(j));
        if (e > worst && std::getenv("FFRF_DEBUG_JACOBIAN")) {
          std::printf("  gamma %g (%d, %d): %.6e vs %.6e\n", gamma, i, j, s(i, j), ref(i, j));
        }
        worst = std::max(worst, e);
      }
    }
  }
  return worst;
}

class NewtonJacobians : public ::testing::TestWithParam<Case> {};

TEST_P(NewtonJacobians, MinimalBlocksMatchDifferencesOfTheRightHandSide) {
  const Case c = GetParam();
  auto eq = build(c);
  const int n = eq->minimal_size();
  Eigen::VectorXd z, z_dot, z_ddot(n);
  moving_state(*eq, z, z_dot);
  eq->minimal_accelerations(c.t, z, z_dot, z_ddot);
  SecondOrderJacobian blocks(eq->minimal_structure());
  eq->minimal_jacobian(c.t, z, z_dot, z_ddot, blocks);
  const Eigen::MatrixXd mass = blocks.mass.dense();
  // Second method: central differences of z̈(z, ż), times M: K_ref = −M ∂z̈/∂z, D_ref = −M ∂z̈/∂ż
  // (steps 1e-4 of each coordinate's size, as below).
  const Eigen::VectorXd scale = eq->coordinate_scale();
  Eigen::MatrixXd ref_z(n, n), ref_v(n, n);
  Eigen::VectorXd plus(n), minus(n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd x = z, v = z_dot;
    const double h = 1e-4 * std::max(std::abs(z(j)), scale(j)), h_v = 1e-4 * std::max(std::abs(z_dot(j)), scale(j));
    x(j) += h;
    eq->minimal_accelerations(c.t, x, v, plus);
    x(j) -= 2 * h;
    eq->minimal_accelerations(c.t, x, v, minus);
    ref_z.col(j) = -mass * (plus - minus) / (2 * h);
    x(j) = z(j);
    v(j) += h_v;
    eq->minimal_accelerations(c.t, x, v, plus);
    v(j) -= 2 * h_v;
    eq->minimal_accelerations(c.t, x, v, minus);
    ref_v.col(j) = -mass * (plus - minus) / (2 * h_v);
  }
  const double error = newton_matrix_error(mass, blocks.damping.dense(), blocks.stiffness.dense(), ref_v, ref_z);
  std::printf("%s %s: Newton matrix error %.2e (n = %d, border %d, band %d ± %d)\n", c.scene.c_str(), c.choice.label().c_str(),
              error, n, blocks.structure().border, blocks.structure().band_size, blocks.structure().lower);
  EXPECT_LT(error, kNewtonMatrixTolerance);
  if (eq->cargo_offset() >= 0) {
    EXPECT_GT(eq->minimal_outputs(c.t, z, z_dot).wire_tension, 0.0);  // the wire's terms count
  }
}

TEST_P(NewtonJacobians, FullBlocksMatchDifferencesOfTheResidual) {
  const Case c = GetParam();
  auto eq = build(c);
  const int n = eq->full_size();
  Eigen::VectorXd z, z_dot;
  moving_state(*eq, z, z_dot);
  Eigen::VectorXd q(n), v(n), a(n);
  eq->full_from_minimal(c.t, z, z_dot, q, v);
  for (int i = 0; i < n; ++i) a(i) = 0.2 * std::sin(0.9 * i + 0.3);  // any acceleration: the blocks hold it fixed
  SecondOrderJacobian blocks(eq->full_structure());
  eq->full_jacobian(c.t, q, v, a, blocks);
  const auto residual = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& x_dot) {
    Eigen::VectorXd forces(n), inertia(n);
    eq->full_forces(c.t, x, x_dot, forces);
    eq->full_mass_times(x, a, inertia);
    return Eigen::VectorXd(forces - inertia);
  };
  Eigen::MatrixXd ref_k(n, n), ref_d(n, n);
  for (int j = 0; j < n; ++j) {
    // Steps of 1e-4 of each coordinate's size: the residual is nearly linear (central differences'
    // h² error is below 1e-10), and smaller steps only add round-off (1e-6 gives 1e-6 of noise).
    const double h = 1e-4 * std::max(std::abs(q(j)), 1e-2), h_v = 1e-4 * std::max(std::abs(v(j)), 1e-2);
    Eigen::VectorXd x = q, x_dot = v;
    x(j) += h;
    const Eigen::VectorXd plus = residual(x, x_dot);
    x(j) -= 2 * h;
    ref_k.col(j) = -(plus - residual(x, x_dot)) / (2 * h);
    x(j) = q(j);
    x_dot(j) += h_v;
    const Eigen::VectorXd plus_v = residual(x, x_dot);
    x_dot(j) -= 2 * h_v;
    ref_d.col(j) = -(plus_v - residual(x, x_dot)) / (2 * h_v);
  }
  const Eigen::MatrixXd mass = eq->full_mass_matrix(q);
  EXPECT_LT((blocks.mass.dense() - mass).cwiseAbs().maxCoeff(), 1e-12 * mass.cwiseAbs().maxCoeff());
  const double error = newton_matrix_error(mass, blocks.damping.dense(), blocks.stiffness.dense(), ref_d, ref_k);
  std::printf("%s %s: full Newton matrix error %.2e\n", c.scene.c_str(), c.choice.label().c_str(), error);
  EXPECT_LT(error, kNewtonMatrixTolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Crane, NewtonJacobians,
    ::testing::Values(Case{"paper_floating_crane.toml", {.kind = scene::BoomKind::rigid}, 31.0},
                      Case{"paper_floating_crane.toml", {.kind = scene::BoomKind::nodal, .elements = 4}, 31.0},
                      Case{"paper_floating_crane.toml",
                           {.kind = scene::BoomKind::nodal, .elements = 16, .stiffening = scene::Stiffening::static_load}, 7.0},
                      Case{"paper_floating_crane.toml", {.kind = scene::BoomKind::modal, .elements = 16, .modes = 2, .static_modes = true}, 31.0},
                      Case{"spin_up_beam.toml", {.kind = scene::BoomKind::nodal, .elements = 10, .stiffening = scene::Stiffening::centrifugal}, 9.0},
                      Case{"pinned_luffing_crane.toml", {.kind = scene::BoomKind::nodal, .elements = 4}, 31.0},
                      Case{"a_frame_crane.toml", {.kind = scene::BoomKind::rigid}, 31.0},
                      Case{"a_frame_crane.toml", {.kind = scene::BoomKind::nodal, .elements = 4}, 31.0},
                      Case{"a_frame_crane.toml", {.kind = scene::BoomKind::modal, .elements = 16, .modes = 2, .static_modes = true}, 31.0}));

// IDA's residual of the stabilized index-2 DAE (as solve/integrate_lagrange.cpp writes it), over
// y = (q, v, λ, μ) with m = constraint_count() multipliers each (the heel's and the pins' rows).
Eigen::VectorXd dae_residual(CraneEquations& eq, double t, const Eigen::VectorXd& y, const Eigen::VectorXd& y_dot) {
  const int n = eq.full_size(), m = eq.constraint_count();
  const auto q = y.head(n), v = y.segment(n, n);
  const Eigen::VectorXd lambda = y.segment(2 * n, m), mu = y.segment(2 * n + m, m);
  Eigen::MatrixXd cq;
  eq.constraint_jacobian(q, cq);
  Eigen::VectorXd r(2 * n + 2 * m), forces(n), inertia(n);
  eq.full_forces(t, q, v, forces);
  eq.full_mass_times(q, y_dot.segment(n, n), inertia);
  r.head(n) = y_dot.head(n) - v + cq.transpose() * mu;
  r.segment(n, n) = inertia - forces + cq.transpose() * lambda;
  solve::ConstraintVector c(m), c_t(m);
  eq.constraint(t, q, c);
  eq.constraint_time_derivative(t, c_t);
  r.segment(2 * n, m) = c;
  r.tail(m) = cq * v + c_t;
  return r;
}

// IDA's Newton matrix J = ∂G/∂y + c_j ∂G/∂ẏ assembled densely from the blocks (K, D, M of
// full_jacobian and the constraint's second derivatives by central differences here).
Eigen::MatrixXd assembled_index_two_matrix(CraneEquations& eq, double t, const Eigen::VectorXd& y, const Eigen::VectorXd& y_dot,
                                           double cj) {
  const int n = eq.full_size(), m = eq.constraint_count(), total = 2 * n + 2 * m;
  SecondOrderJacobian blocks(eq.full_structure());
  eq.full_jacobian(t, y.head(n), y.segment(n, n), y_dot.segment(n, n), blocks);
  Eigen::MatrixXd cq, plus, minus;
  eq.constraint_jacobian(y.head(n), cq);
  const Eigen::VectorXd v = y.segment(n, n);
  const Eigen::VectorXd lambda = y.segment(2 * n, m), mu = y.segment(2 * n + m, m);
  Eigen::MatrixXd h_lambda(n, n), h_mu(n, n), g_v(m, n);
  for (int j = 0; j < n; ++j) {
    const double h = 1e-5 * std::max(std::abs(y(j)), 1e-2);
    Eigen::VectorXd q = y.head(n);
    q(j) += h;
    eq.constraint_jacobian(q, plus);
    q(j) -= 2 * h;
    eq.constraint_jacobian(q, minus);
    const Eigen::MatrixXd slope = (plus - minus) / (2 * h);
    h_lambda.col(j) = slope.transpose() * lambda;
    h_mu.col(j) = slope.transpose() * mu;
    g_v.col(j) = slope * v;
  }
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(total, total);
  j.topLeftCorner(n, n) = cj * Eigen::MatrixXd::Identity(n, n) + h_mu;
  j.block(0, n, n, n) = -Eigen::MatrixXd::Identity(n, n);
  j.block(0, 2 * n + m, n, m) = cq.transpose();
  j.block(n, 0, n, n) = blocks.stiffness.dense() + h_lambda;
  j.block(n, n, n, n) = cj * blocks.mass.dense() + blocks.damping.dense();
  j.block(n, 2 * n, n, m) = cq.transpose();
  j.block(2 * n, 0, m, n) = cq;
  j.block(2 * n + m, 0, m, n) = g_v;
  j.block(2 * n + m, n, m, n) = cq;
  return j;
}

// IDA's Newton matrix and step: the blocks assembled densely against central differences of the
// residual (entry by entry, relative to the geometric mean of its row's and column's largest entries:
// the unknowns' scales differ by 10 orders of magnitude), and the structured solve (the reduction of
// solve/ida_newton.hpp, bordered band LU) against Eigen's dense LU of the same matrix, at a state
// with nonzero multipliers so that every curvature term of the constraint counts.
TEST_P(NewtonJacobians, IndexTwoNewtonStepMatchesTheDenseSystem) {
  const Case c = GetParam();
  auto eq = build(c);
  const int n = eq->full_size(), m = eq->constraint_count(), total = 2 * n + 2 * m;
  Eigen::VectorXd z, z_dot;
  moving_state(*eq, z, z_dot);
  Eigen::VectorXd y(total), y_dot(total);
  eq->full_from_minimal(c.t, z, z_dot, y.head(n), y.segment(n, n));
  // Multipliers of the order of the system's own loads (its largest inertia × 1 /s²).
  const double load = eq->full_mass_matrix(y.head(n)).diagonal().maxCoeff();
  const double lambda_pattern[] = {1e-4, -2e-3, 3e-2, -1e-3, 2e-2, -3e-4}, mu_pattern[] = {1e-4, -2e-4, 5e-5, -1e-4, 2e-4, -5e-5};
  for (int i = 0; i < m; ++i) {
    y(2 * n + i) = load * lambda_pattern[i];
    y(2 * n + m + i) = mu_pattern[i];
  }
  for (int i = 0; i < total; ++i) y_dot(i) = 0.1 * std::sin(0.7 * i + 0.2);
  const double cj = 37.0;
  const Eigen::MatrixXd assembled = assembled_index_two_matrix(*eq, c.t, y, y_dot, cj);
  Eigen::MatrixXd differences(total, total);
  for (int j = 0; j < total; ++j) {
    const double h = 1e-4 * std::max(std::abs(y(j)), j < 2 * n ? 1e-2 : 1.0);
    Eigen::VectorXd yp = y, ym = y, dp = y_dot, dm = y_dot;
    yp(j) += h;
    ym(j) -= h;
    dp(j) += cj * h;  // ∂G/∂y + c_j ∂G/∂ẏ along one perturbation
    dm(j) -= cj * h;
    differences.col(j) = (dae_residual(*eq, c.t, yp, dp) - dae_residual(*eq, c.t, ym, dm)) / (2 * h);
  }
  const Eigen::VectorXd row_size = assembled.cwiseAbs().rowwise().maxCoeff(), col_size = assembled.cwiseAbs().colwise().maxCoeff();
  double worst = 0.0;
  for (int j = 0; j < total; ++j) {
    for (int i = 0; i < total; ++i) {
      const double e = std::abs(assembled(i, j) - differences(i, j)) / std::sqrt(row_size(i) * col_size(j));
      if (e > worst && std::getenv("FFRF_DEBUG_JACOBIAN")) std::printf("  (%d, %d) %.6e vs %.6e\n", i, j, assembled(i, j), differences(i, j));
      worst = std::max(worst, e);
    }
  }
  EXPECT_LT(worst, kNewtonMatrixTolerance) << c.choice.label();

  Eigen::VectorXd rhs(total);
  for (int i = 0; i < total; ++i) rhs(i) = std::cos(1.3 * i);
  // Reference: the equilibrated dense system (rows and columns scaled to unit largest entry).
  const Eigen::VectorXd row_scale = row_size.cwiseInverse();
  const Eigen::MatrixXd scaled_rows = row_scale.asDiagonal() * assembled;
  const Eigen::VectorXd column_scale = scaled_rows.cwiseAbs().colwise().maxCoeff().transpose().cwiseInverse();
  const Eigen::VectorXd reference =
      column_scale.asDiagonal() * (scaled_rows * column_scale.asDiagonal()).partialPivLu().solve(row_scale.asDiagonal() * rhs);

  SUNContext context = nullptr;
  ASSERT_EQ(SUNContext_Create(nullptr, &context), 0);
  {
    const Eigen::VectorXd scale = y.head(n).cwiseAbs().cwiseMax(Eigen::VectorXd::Constant(n, 1e-2));
    solve::sundials::IndexTwoNewton newton(*eq, context, scale);
    N_Vector state = N_VNew_Serial(total, context), rate = N_VNew_Serial(total, context), b = N_VNew_Serial(total, context),
             x = N_VNew_Serial(total, context);
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(state), total) = y;
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(rate), total) = y_dot;
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(b), total) = rhs;
    ASSERT_EQ(solve::sundials::IndexTwoNewton::jacobian(c.t, cj, state, rate, nullptr, newton.matrix(), nullptr, nullptr,
                                                          nullptr, nullptr), 0);
    ASSERT_EQ(SUNLinSolSetup(newton.solver(), newton.matrix()), 0);
    ASSERT_EQ(SUNLinSolSolve(newton.solver(), newton.matrix(), x, b, 0.0), 0);
    const Eigen::VectorXd structured = Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(x), total);
    for (const auto& [from, count] : {std::pair{0, n}, std::pair{n, n}, std::pair{2 * n, m}, std::pair{2 * n + m, m}}) {
      const double size = reference.segment(from, count).cwiseAbs().maxCoeff();
      const double error = (structured.segment(from, count) - reference.segment(from, count)).cwiseAbs().maxCoeff();
      EXPECT_LT(error, 1e-7 * size) << c.choice.label() << " block at " << from;
    }
    std::printf("%s: IDA matrix error %.2e, step residual %.2e\n", c.choice.label().c_str(), worst,
                (row_scale.asDiagonal() * (assembled * structured - rhs)).cwiseAbs().maxCoeff());
    for (N_Vector v : {state, rate, b, x}) N_VDestroy(v);
  }
  SUNContext_Free(&context);
}

TEST(NewtonJacobians, NodalBoomsAreBandedModalOnesDense) {
  scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  const auto nodal = scene::build_crane_equations(scene, {.kind = scene::BoomKind::nodal, .elements = 32});
  EXPECT_EQ(nodal->minimal_structure().border, 6);
  EXPECT_EQ(nodal->minimal_structure().band_size, 96);
  EXPECT_LE(nodal->minimal_structure().lower, 5);  // element couples two nodes of 3 DOFs
  EXPECT_EQ(nodal->full_structure().border, 9);
  const auto modal = scene::build_crane_equations(scene, {.kind = scene::BoomKind::modal, .elements = 16, .modes = 2, .static_modes = true});
  EXPECT_EQ(modal->minimal_structure().band_size, 0);
  EXPECT_EQ(modal->minimal_structure().border, modal->minimal_size());
}

TEST(BorderedBandLU, SolvesLikeDenseLU) {
  for (const solve::BandStructure s : {solve::BandStructure{6, 40, 5, 5}, solve::BandStructure{0, 30, 2, 3},
                                          solve::BandStructure{9, 0, 0, 0}, solve::BandStructure{15, 25, 4, 4}}) {
    solve::BorderedBandMatrix m(s);
    for (int i = 0; i < m.size(); ++i) {
      for (int j = 0; j < m.size(); ++j) {
        if (m.in_structure(i, j)) m.at(i, j) = std::sin(1.3 * i + 0.7 * j * j) + (i == j ? 6.0 : 0.0);
      }
    }
    Eigen::VectorXd b(m.size()), x(m.size()), product(m.size());
    for (int i = 0; i < b.size(); ++i) b(i) = std::cos(0.37 * i);
    const Eigen::MatrixXd dense = m.dense();
    x = b;
    solve::BorderedBandLU lu(s);
    ASSERT_TRUE(lu.factorize(m));
    lu.solve(x);
    const Eigen::VectorXd reference = dense.partialPivLu().solve(b);
    EXPECT_LT((x - reference).cwiseAbs().maxCoeff(), 1e-12 * reference.cwiseAbs().maxCoeff());
    m.multiply(reference, product);
    EXPECT_LT((product - dense * reference).cwiseAbs().maxCoeff(), 1e-12 * b.cwiseAbs().maxCoeff());
  }
  solve::BorderedBandMatrix singular(solve::BandStructure{2, 5, 1, 1});
  solve::BorderedBandLU lu(singular.structure());
  EXPECT_FALSE(lu.factorize(singular));
}

}  // namespace newton_jacobians_test
