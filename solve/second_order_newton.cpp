// The structured Newton solve for CVODE (see second_order_newton.hpp): custom SUNMatrix and
// SUNLinearSolver objects whose content is the SecondOrderNewton.
#include "solve/second_order_newton.hpp"

#include <nvector/nvector_serial.h>

#include "solve/nvector_view.hpp"

namespace ffrf::solve::sundials {

SecondOrderNewton::SecondOrderNewton(const BandStructure& structure, SUNContext context, Evaluate evaluate)
    : size_(structure.size()), evaluate_(std::move(evaluate)), blocks_(structure), effective_(structure), lu_(structure),
      reduced_(structure.size()), stiffness_times_(structure.size()), linear_(context, this, setup, solve) {}

int SecondOrderNewton::linear_system(double t, N_Vector y, N_Vector fy, SUNMatrix A, int jok, int* jcur, double gamma, void*,
                                     N_Vector, N_Vector, N_Vector) {
  auto* self = static_cast<SecondOrderNewton*>(A->content);
  if (!jok) {
    const auto state = view(y);
    const auto rate = view(fy);
    const int n = self->size_;
    const int flag = self->evaluate_(t, state.head(n), state.tail(n), rate.tail(n), self->blocks_);
    if (flag != 0) return flag;
    *jcur = 1;
  } else {
    *jcur = 0;
  }
  self->gamma_ = gamma;
  return 0;
}

int SecondOrderNewton::setup(SUNLinearSolver solver, SUNMatrix) {
  auto* self = static_cast<SecondOrderNewton*>(solver->content);
  const double gamma = self->gamma_;
  self->effective_.assign_combination(1.0, self->blocks_.mass, gamma, self->blocks_.damping, gamma * gamma,
                                      self->blocks_.stiffness);
  ++self->factorizations_;
  return self->lu_.factorize(self->effective_) ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
}

int SecondOrderNewton::solve(SUNLinearSolver solver, SUNMatrix, N_Vector x, N_Vector b, double) {
  auto* self = static_cast<SecondOrderNewton*>(solver->content);
  const int n = self->size_;
  const auto rhs = view(b);
  auto solution = view(x);
  self->blocks_.mass.multiply(rhs.tail(n), self->reduced_);
  self->blocks_.stiffness.multiply(rhs.head(n), self->stiffness_times_);
  self->reduced_ -= self->gamma_ * self->stiffness_times_;
  self->lu_.solve(self->reduced_);
  solution.tail(n) = self->reduced_;
  solution.head(n) = rhs.head(n) + self->gamma_ * self->reduced_;
  return self->reduced_.allFinite() ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_REC;
}

}  // namespace ffrf::solve::sundials
