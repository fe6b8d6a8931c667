// IDA's Newton systems for a system's stabilized index-2 DAE (solve/integrate_lagrange.cpp) in
// y = (q, v, λ, μ), through SUNDIALS' linear-solver interface (a custom SUNMatrix holding the
// structured blocks and a custom direct SUNLinearSolver). With the residual
//   G1 = q̇ − v + C_qᵀμ,  G2 = M v̇ − Q + C_qᵀλ,  G3 = C,  G4 = C_q v + C_t
// and K, D, M from SecondOrderSystem::full_jacobian, H_w = ∂(C_qᵀw)/∂q, G_v = ∂(C_q v)/∂q, the system
// J δ = r with J = ∂G/∂y + c_j ∂G/∂ẏ is, after δv = (c_j I + H_μ) δq + C_qᵀ δμ − r₁ and W = c_j M + D,
//   [ K + c_j D + c_j² M + H_λ + W H_μ   C_qᵀ   W C_qᵀ ] [δq]   [r₂ + W r₁ ]
//   [ C_q                                 0      0     ] [δλ] = [r₃       ]
//   [ G_v + c_j C_q + C_q H_μ            0      C_qC_qᵀ] [δμ]   [r₄ + C_q r₁]
// whose matrix keeps the bordered band structure (solve/constrained_newton.hpp): cost linear in
// the element count, against IDA's dense (2n + 6)² LU with a difference-quotient Jacobian before.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

#include <functional>
#include <string>

#include "solve/constrained_newton.hpp"
#include "solve/custom_linear_solver.hpp"
#include "solve/second_order_system.hpp"
#include "solve/failure.hpp"

namespace ffrf::solve::sundials {

class IndexTwoNewton {
 public:
  IndexTwoNewton(SecondOrderSystem& equations, SUNContext context, Eigen::VectorXd coordinate_scale);
  IndexTwoNewton(const IndexTwoNewton&) = delete;
  IndexTwoNewton& operator=(const IndexTwoNewton&) = delete;

  SUNMatrix matrix() const { return linear_.matrix(); }
  SUNLinearSolver solver() const { return linear_.solver(); }
  // IDALsJacFn: register with IDASetJacFn after IDASetLinearSolver(solver(), matrix()); the user
  // data pointer is not used (the matrix carries this object). The model's exceptions propagate: call
  // it inside the adapter's callback guard (sundials::CallbackGuard), never directly from C.
  static int jacobian(double t, double cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix J, void* user, N_Vector,
                      N_Vector, N_Vector);

 private:
  static int setup(SUNLinearSolver solver, SUNMatrix A);
  static int solve(SUNLinearSolver solver, SUNMatrix A, N_Vector x, N_Vector b, double tolerance);
  // Column i (a border coordinate) of W = c_j M + D into column_.
  void weighted_column(int i);

  SecondOrderSystem& equations_;
  int nq_, border_;
  Eigen::VectorXd scale_;
  SecondOrderJacobian blocks_;
  ConstraintCurvature curvature_;
  ConstrainedNewtonMatrix reduced_;
  double cj_ = 0.0;
  ConstraintVector lambda_, mu_;  // λ, μ of the last Jacobian (m each)
  Eigen::VectorXd velocity_, column_, reduced_rhs_, product_, delta_q_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic> mu_curvature_;  // H_μ over the border (b × b)
  CustomLinearSolver linear_;  // last: built on the complete object
};

}  // namespace ffrf::solve::sundials
