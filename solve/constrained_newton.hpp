// Newton matrices of the constrained second-order systems in full coordinates (IDA's stabilized
// index-2 DAE, generalized-α's index-3 step): the coordinates q = (border b | elastic band n) keep the
// bordered band structure of solve/second_order_jacobian.hpp, and the `extra` unknowns (the
// multipliers λ, and μ for IDA) join the border. Reduced unknowns in the order
//   [q_0 … q_{b−1} | extra_0 … extra_{m−1} | q_b … q_{b+n−1}],
// so one BorderedBandLU (band LU of the elastic block, dense LU of the border's Schur complement) solves
// them at a cost linear in n. Also the constraint's second derivatives the Newton matrices need,
// ∂(C_qᵀw)/∂q and ∂(C_q v)/∂q, by forward differences of C_q over the border coordinates (the system's
// constraints may involve only the border: C_q is zero over the banded coordinates).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "solve/bordered_band_matrix.hpp"
#include "solve/second_order_system.hpp"

namespace ffrf::solve {

class ConstrainedNewtonMatrix {
 public:
  ConstrainedNewtonMatrix() = default;
  ConstrainedNewtonMatrix(const BandStructure& full, int extra);

  int size() const { return matrix_.size(); }
  int coordinate_count() const { return full_.size(); }
  int extra() const { return extra_; }
  int reduced(int q_index) const { return q_index < full_.border ? q_index : q_index + extra_; }
  int reduced_extra(int k) const { return full_.border + k; }

  // The q-block = a·x + b·y + c·z (same structure as `full`); the extra rows and columns zeroed.
  void assign_coordinate_block(double a, const BorderedBandMatrix& x, double b, const BorderedBandMatrix& y, double c,
                               const BorderedBandMatrix& z);
  double& at(int i, int j) { return matrix_.at(i, j); }  // reduced indices
  BorderedBandMatrix& matrix() { return matrix_; }

  // Reduced vector ↔ (q part, extra part).
  void pack(const Eigen::Ref<const Eigen::VectorXd>& q_part, const Eigen::Ref<const Eigen::VectorXd>& extra_part,
            Eigen::Ref<Eigen::VectorXd> out) const;
  void unpack(const Eigen::Ref<const Eigen::VectorXd>& reduced, Eigen::Ref<Eigen::VectorXd> q_part,
              Eigen::Ref<Eigen::VectorXd> extra_part) const;

  bool factorize() { return lu_.factorize(matrix_); }
  void solve(Eigen::Ref<Eigen::VectorXd> x) { lu_.solve(x); }

 private:
  BandStructure full_;
  int extra_ = 0;
  BorderedBandMatrix matrix_;
  BorderedBandLU lu_;
};

// C_q at q and its first derivatives over the border coordinates: slope(j) = ∂C_q/∂q_j for j < b
// (m × b: C_q's border columns only). Then ∂(C_qᵀ w)/∂q has the border block Σ_k w_k slope(j)(k, ·)ᵀ
// in column j and ∂(C_q v)/∂q the column slope(j) v_border.
struct ConstraintCurvature {
  int border = 0;
  Eigen::MatrixXd jacobian;           // C_q (m × nq)
  std::vector<Eigen::MatrixXd> slope;  // b of them, m × b
  void evaluate(SecondOrderSystem& equations, const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::VectorXd& scale);
  // (∂(C_qᵀ w)/∂q)(i, j) for border i, j.
  double transpose_product(const ConstraintVector& w, int i, int j) const { return slope[static_cast<std::size_t>(j)].col(i).dot(w); }
  // (∂(C_q v)/∂q)(k, j) for border j.
  double velocity_product(const Eigen::Ref<const Eigen::VectorXd>& v, int k, int j) const {
    return slope[static_cast<std::size_t>(j)].row(k).dot(v.head(border));
  }
};

// Consistent accelerations and multipliers at (t, q, v): [M C_qᵀ; C_q 0][v̇; λ] = [Q; γ] with
// γ = −(C_q v)_q v − C_tt (SecondOrderSystem::constraint_rate_terms), solved with the structure above.
// Throws MassMatrixError when the augmented matrix is singular.
void consistent_accelerations(SecondOrderSystem& equations, double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                              const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> v_dot,
                              Eigen::Ref<Eigen::VectorXd> lambda);

// λ at (t, q, v) with v̇ known (an integrator's interpolant): least squares on C_qᵀλ = Q − M v̇.
void multipliers_from_accelerations(SecondOrderSystem& equations, double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                                    const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& v_dot,
                                    Eigen::Ref<Eigen::VectorXd> lambda);

}  // namespace ffrf::solve
