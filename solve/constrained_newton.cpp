// Reduced Newton matrices of constrained systems and the constraint's second derivatives (see
// constrained_newton.hpp).
#include "solve/constrained_newton.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ffrf::solve {

ConstrainedNewtonMatrix::ConstrainedNewtonMatrix(const BandStructure& full, int extra)
    : full_(full), extra_(extra), matrix_({full.border + extra, full.band_size, full.lower, full.upper}), lu_(matrix_.structure()) {}

void ConstrainedNewtonMatrix::assign_coordinate_block(double a, const BorderedBandMatrix& x, double b, const BorderedBandMatrix& y,
                                                      double c, const BorderedBandMatrix& z) {
  const int nb = full_.border;
  matrix_.set_zero();
  matrix_.corner().topLeftCorner(nb, nb) = a * x.corner() + b * y.corner() + c * z.corner();
  matrix_.border_rows().topRows(nb) = a * x.border_rows() + b * y.border_rows() + c * z.border_rows();
  matrix_.border_columns().leftCols(nb) = a * x.border_columns() + b * y.border_columns() + c * z.border_columns();
  matrix_.band_storage() = a * x.band_storage() + b * y.band_storage() + c * z.band_storage();
}

void ConstrainedNewtonMatrix::pack(const Eigen::Ref<const Eigen::VectorXd>& q_part, const Eigen::Ref<const Eigen::VectorXd>& extra_part,
                                   Eigen::Ref<Eigen::VectorXd> out) const {
  const int nb = full_.border, n = full_.band_size;
  out.head(nb) = q_part.head(nb);
  out.segment(nb, extra_) = extra_part;
  out.tail(n) = q_part.tail(n);
}

void ConstrainedNewtonMatrix::unpack(const Eigen::Ref<const Eigen::VectorXd>& reduced, Eigen::Ref<Eigen::VectorXd> q_part,
                                     Eigen::Ref<Eigen::VectorXd> extra_part) const {
  const int nb = full_.border, n = full_.band_size;
  q_part.head(nb) = reduced.head(nb);
  extra_part = reduced.segment(nb, extra_);
  q_part.tail(n) = reduced.tail(n);
}

void ConstraintCurvature::evaluate(SecondOrderSystem& equations, const Eigen::Ref<const Eigen::VectorXd>& q,
                                   const Eigen::VectorXd& scale) {
  border = equations.full_structure().border;
  const int nq = equations.full_size();
  equations.constraint_jacobian(q, jacobian);
  if (border < nq && !jacobian.rightCols(nq - border).isZero(0.0)) {
    throw std::logic_error("ConstraintCurvature: the constraint involves coordinates outside the border");
  }
  slope.resize(static_cast<std::size_t>(border));
  Eigen::VectorXd shifted = q;
  Eigen::MatrixXd moved;
  for (int j = 0; j < border; ++j) {
    const double delta = 1e-7 * std::max(std::abs(q(j)), scale(j));
    shifted(j) = q(j) + delta;
    equations.constraint_jacobian(shifted, moved);
    shifted(j) = q(j);
    slope[static_cast<std::size_t>(j)] = (moved.leftCols(border) - jacobian.leftCols(border)) / delta;
  }
}

void consistent_accelerations(SecondOrderSystem& equations, double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                              const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> v_dot,
                              Eigen::Ref<Eigen::VectorXd> lambda) {
  const int constraints = equations.constraint_count();
  const int n = equations.full_size();
  const BandStructure structure = equations.full_structure();
  SecondOrderJacobian blocks(structure);
  equations.full_jacobian(t, q, v, Eigen::VectorXd::Zero(n), blocks);  // only its mass matrix is used
  ConstrainedNewtonMatrix augmented(structure, constraints);
  augmented.assign_coordinate_block(1.0, blocks.mass, 0.0, blocks.damping, 0.0, blocks.stiffness);
  Eigen::MatrixXd cq;
  equations.constraint_jacobian(q, cq);
  for (int k = 0; k < constraints; ++k) {
    for (int j = 0; j < structure.border; ++j) {
      augmented.at(augmented.reduced(j), augmented.reduced_extra(k)) = cq(k, j);
      augmented.at(augmented.reduced_extra(k), augmented.reduced(j)) = cq(k, j);
    }
  }
  Eigen::VectorXd forces(n), solution(n + constraints);
  equations.full_forces(t, q, v, forces);
  ConstraintVector gamma(constraints);
  equations.constraint_rate_terms(t, q, v, gamma);
  augmented.pack(forces, gamma, solution);
  if (!augmented.factorize()) throw MassMatrixError(0.0);
  augmented.solve(solution);
  ConstraintVector multipliers(constraints);
  augmented.unpack(solution, v_dot, multipliers);
  lambda = multipliers;
}

void multipliers_from_accelerations(SecondOrderSystem& equations, double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                                    const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& v_dot,
                                    Eigen::Ref<Eigen::VectorXd> lambda) {
  const int n = equations.full_size();
  Eigen::VectorXd forces(n), inertia(n);
  Eigen::MatrixXd cq;
  equations.full_forces(t, q, v, forces);
  equations.full_mass_times(q, v_dot, inertia);
  equations.constraint_jacobian(q, cq);
  const ConstraintMatrix normal = cq * cq.transpose();
  lambda = normal.ldlt().solve(cq * (forces - inertia));
}

}  // namespace ffrf::solve
