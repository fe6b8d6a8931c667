// A custom direct SUNLinearSolver with its custom SUNMatrix, both carrying a C++ object as content
// (the structured Newton solvers of second_order_newton.hpp and ida_newton.hpp): the SUNDIALS ops
// every integrator's linear-solver interface needs (type, id, set-up, solve, free; a matrix that can
// be "zeroed" — the Jacobian functions overwrite it — and destroyed), created and freed in one place.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

namespace ffrf::solve::sundials {

class CustomLinearSolver {
 public:
  using Setup = int (*)(SUNLinearSolver, SUNMatrix);
  using Solve = int (*)(SUNLinearSolver, SUNMatrix, N_Vector, N_Vector, double);
  // `content` is what setup and solve find in solver->content and matrix->content.
  CustomLinearSolver(SUNContext context, void* content, Setup setup, Solve solve);
  ~CustomLinearSolver();
  CustomLinearSolver(const CustomLinearSolver&) = delete;
  CustomLinearSolver& operator=(const CustomLinearSolver&) = delete;
  SUNMatrix matrix() const { return matrix_; }
  SUNLinearSolver solver() const { return solver_; }

 private:
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver solver_ = nullptr;
};

}  // namespace ffrf::solve::sundials
