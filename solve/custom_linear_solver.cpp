// Custom SUNLinearSolver/SUNMatrix pair (see custom_linear_solver.hpp).
#include "solve/custom_linear_solver.hpp"

#include <stdexcept>

namespace ffrf::solve::sundials {

namespace {

SUNMatrix_ID matrix_id(SUNMatrix) { return SUNMATRIX_CUSTOM; }
int matrix_zero(SUNMatrix) { return 0; }  // the Jacobian functions overwrite every block
void matrix_destroy(SUNMatrix A) { SUNMatFreeEmpty(A); }
SUNLinearSolver_Type solver_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID solver_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int solver_free(SUNLinearSolver S) {
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

CustomLinearSolver::CustomLinearSolver(SUNContext context, void* content, Setup setup, Solve solve)
    : matrix_(SUNMatNewEmpty(context)), solver_(SUNLinSolNewEmpty(context)) {
  if (!matrix_ || !solver_) {
    if (solver_) SUNLinSolFreeEmpty(solver_);
    if (matrix_) SUNMatFreeEmpty(matrix_);
    throw std::runtime_error("SUNDIALS custom Newton matrix/solver allocation failed");
  }
  matrix_->content = content;
  matrix_->ops->getid = matrix_id;
  matrix_->ops->zero = matrix_zero;
  matrix_->ops->destroy = matrix_destroy;
  solver_->content = content;
  solver_->ops->gettype = solver_type;
  solver_->ops->getid = solver_id;
  solver_->ops->setup = setup;
  solver_->ops->solve = solve;
  solver_->ops->free = solver_free;
}

CustomLinearSolver::~CustomLinearSolver() {
  SUNLinSolFree(solver_);
  SUNMatDestroy(matrix_);
}

}  // namespace ffrf::solve::sundials
