// CVODE's Newton systems for a second-order ODE y = (x, ẋ), ẏ = (ẋ, a(x, ẋ)) with M(x) a = Q(x, ẋ),
// through SUNDIALS' linear-solver interface: a custom SUNMatrix that holds the structured blocks
// M, K = −∂(Q − Ma)/∂x, D = −∂(Q − Ma)/∂ẋ (solve/second_order_jacobian.hpp) and γ, and a custom
// direct SUNLinearSolver. With J = [[0, I], [−M⁻¹K, −M⁻¹D]], (I − γJ)(x₁, x₂) = (b₁, b₂) reduces to
//   S x₂ = M b₂ − γ K b₁,  S = M + γ D + γ² K,   x₁ = b₁ + γ x₂,
// and S (bordered band for a nodal boom, dense for a modal one) is factored by BorderedBandLU:
// cost linear in the element count, where the dense (2n)² Jacobian of I − γJ is dense because of M⁻¹.
// CVodeSetLinSysFn supplies γ at every set-up and says whether CVODE keeps its Jacobian (jok): the
// blocks are re-evaluated only when CVODE asks for a new Jacobian (its usual reuse heuristics), and
// only S is re-formed and re-factored when γ changed.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

#include <Eigen/Dense>
#include <functional>

#include "solve/custom_linear_solver.hpp"
#include "solve/second_order_jacobian.hpp"

namespace ffrf::solve::sundials {

class SecondOrderNewton {
 public:
  // evaluate(t, x, ẋ, a, blocks) fills the blocks at a state; returns 0, > 0 for a recoverable
  // failure (CVODE retries with a smaller step), < 0 for an unrecoverable one.
  using Evaluate = std::function<int(double, const Eigen::Ref<const Eigen::VectorXd>&, const Eigen::Ref<const Eigen::VectorXd>&,
                                     const Eigen::Ref<const Eigen::VectorXd>&, SecondOrderJacobian&)>;

  SecondOrderNewton(const BandStructure& structure, SUNContext context, Evaluate evaluate);
  SecondOrderNewton(const SecondOrderNewton&) = delete;
  SecondOrderNewton& operator=(const SecondOrderNewton&) = delete;

  SUNMatrix matrix() const { return linear_.matrix(); }
  SUNLinearSolver solver() const { return linear_.solver(); }
  long factorizations() const { return factorizations_; }

  // CVLsLinSysFn: register with CVodeSetLinSysFn (after CVodeSetLinearSolver(solver(), matrix())).
  static int linear_system(double t, N_Vector y, N_Vector fy, SUNMatrix A, int jok, int* jcur, double gamma, void* user,
                           N_Vector, N_Vector, N_Vector);

 private:
  static int setup(SUNLinearSolver solver, SUNMatrix A);
  static int solve(SUNLinearSolver solver, SUNMatrix A, N_Vector x, N_Vector b, double tolerance);

  int size_;
  Evaluate evaluate_;
  SecondOrderJacobian blocks_;
  BorderedBandMatrix effective_;  // S
  BorderedBandLU lu_;
  double gamma_ = 0.0;
  Eigen::VectorXd reduced_, stiffness_times_;
  long factorizations_ = 0;
  CustomLinearSolver linear_;  // last: built on the complete object
};

}  // namespace ffrf::solve::sundials
