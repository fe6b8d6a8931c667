// The structured Newton solve for IDA (see ida_newton.hpp).
#include "solve/ida_newton.hpp"

#include <nvector/nvector_serial.h>

#include "solve/nvector_view.hpp"

namespace ffrf::solve::sundials {

IndexTwoNewton::IndexTwoNewton(SecondOrderSystem& equations, SUNContext context, Eigen::VectorXd coordinate_scale)
    : equations_(equations), nq_(equations.full_size()), border_(equations.full_structure().border),
      scale_(std::move(coordinate_scale)), blocks_(equations.full_structure()),
      reduced_(equations.full_structure(), 2 * equations.constraint_count()), velocity_(nq_), column_(nq_),
      reduced_rhs_(nq_ + 2 * equations.constraint_count()), product_(nq_), delta_q_(nq_), mu_curvature_(border_, border_),
      linear_(context, this, setup, solve) {}

int IndexTwoNewton::jacobian(double t, double cj, N_Vector y, N_Vector yp, N_Vector, SUNMatrix J, void*, N_Vector,
                             N_Vector, N_Vector) {
  auto* self = static_cast<IndexTwoNewton*>(J->content);
  const int n = self->nq_;
  const auto state = view(y);
  const auto rate = view(yp);
  if (!state.allFinite() || !rate.allFinite()) return 1;
  self->equations_.full_jacobian(t, state.head(n), state.segment(n, n), rate.segment(n, n), self->blocks_);
  self->curvature_.evaluate(self->equations_, state.head(n), self->scale_);
  self->cj_ = cj;
  self->velocity_ = state.segment(n, n);
  const int constraints = self->equations_.constraint_count();
  self->lambda_ = state.segment(2 * n, constraints);
  self->mu_ = state.segment(2 * n + constraints, constraints);
  return 0;
}

void IndexTwoNewton::weighted_column(int i) {
  for (int r = 0; r < nq_; ++r) column_(r) = cj_ * blocks_.mass.at(r, i) + blocks_.damping.at(r, i);
}

int IndexTwoNewton::setup(SUNLinearSolver solver, SUNMatrix) {
  auto* self = static_cast<IndexTwoNewton*>(solver->content);
  const int b = self->border_, n = self->nq_, constraints = self->equations_.constraint_count();
  const double cj = self->cj_;
  ConstrainedNewtonMatrix& m = self->reduced_;
  const ConstraintCurvature& curvature = self->curvature_;
  const Eigen::MatrixXd& cq = curvature.jacobian;
  m.assign_coordinate_block(cj * cj, self->blocks_.mass, cj, self->blocks_.damping, 1.0, self->blocks_.stiffness);
  for (int j = 0; j < b; ++j) {
    for (int i = 0; i < b; ++i) {
      m.at(m.reduced(i), m.reduced(j)) += curvature.transpose_product(self->lambda_, i, j);  // H_λ
      self->mu_curvature_(i, j) = curvature.transpose_product(self->mu_, i, j);            // H_μ
    }
  }
  for (int i = 0; i < b; ++i) {  // W H_μ and W C_qᵀ from W's border columns
    self->weighted_column(i);
    for (int r = 0; r < n; ++r) {
      const double w = self->column_(r);
      if (w == 0.0) continue;
      for (int j = 0; j < b; ++j) m.at(m.reduced(r), m.reduced(j)) += w * self->mu_curvature_(i, j);
      for (int k = 0; k < constraints; ++k) m.at(m.reduced(r), m.reduced_extra(constraints + k)) += w * cq(k, i);
    }
  }
  const ConstraintMatrix cq_cqt = cq.leftCols(b) * cq.leftCols(b).transpose();
  for (int k = 0; k < constraints; ++k) {
    for (int j = 0; j < b; ++j) {
      m.at(m.reduced(j), m.reduced_extra(k)) = cq(k, j);  // C_qᵀ
      m.at(m.reduced_extra(k), m.reduced(j)) = cq(k, j);  // C_q
      double row = curvature.velocity_product(self->velocity_, k, j) + cj * cq(k, j);
      for (int i = 0; i < b; ++i) row += cq(k, i) * self->mu_curvature_(i, j);
      m.at(m.reduced_extra(constraints + k), m.reduced(j)) = row;
    }
    for (int l = 0; l < constraints; ++l) m.at(m.reduced_extra(constraints + k), m.reduced_extra(constraints + l)) = cq_cqt(k, l);
  }
  return m.factorize() ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
}

int IndexTwoNewton::solve(SUNLinearSolver solver, SUNMatrix, N_Vector x, N_Vector b_vector, double) {
  auto* self = static_cast<IndexTwoNewton*>(solver->content);
  const int n = self->nq_, b = self->border_, constraints = self->equations_.constraint_count();
  const auto rhs = view(b_vector);
  auto out = view(x);
  const auto r1 = rhs.head(n), r2 = rhs.segment(n, n);
  const auto r3 = rhs.segment(2 * n, constraints), r4 = rhs.segment(2 * n + constraints, constraints);
  const Eigen::MatrixXd& cq = self->curvature_.jacobian;
  // q rows: r₂ + (c_j M + D) r₁; λ rows: r₃; μ rows: r₄ + C_q r₁.
  self->blocks_.mass.multiply(r1, self->product_);
  self->delta_q_ = r2 + self->cj_ * self->product_;
  self->blocks_.damping.multiply(r1, self->product_);
  self->delta_q_ += self->product_;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2 * max_constraints, 1> extra(2 * constraints);
  extra.head(constraints) = r3;
  extra.tail(constraints) = r4 + cq.leftCols(b) * r1.head(b);
  self->reduced_.pack(self->delta_q_, extra, self->reduced_rhs_);
  self->reduced_.solve(self->reduced_rhs_);
  self->reduced_.unpack(self->reduced_rhs_, self->delta_q_, extra);
  auto dq = out.head(n), dv = out.segment(n, n);
  dq = self->delta_q_;
  dv = self->cj_ * self->delta_q_ - r1;
  dv.head(b) += self->mu_curvature_ * self->delta_q_.head(b) + cq.leftCols(b).transpose() * extra.tail(constraints);
  out.segment(2 * n, constraints) = extra.head(constraints);
  out.segment(2 * n + constraints, constraints) = extra.tail(constraints);
  return out.allFinite() ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_REC;
}

}  // namespace ffrf::solve::sundials
