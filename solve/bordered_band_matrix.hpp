// Square matrices with the structure of a multibody system's Newton matrices: a dense border (the
// first `border` rows and columns: rigid bodies, reference frames, multipliers) around a banded block
// (a beam's nodal elastic coordinates, whose elements couple only neighbouring nodes):
//   [ A  B ]   A: border × border, B: border × n, C: n × border (dense),
//   [ C  E ]   E: n × n with lower/upper bandwidths kl, ku.
// A small or modal system is the case n = 0 (all border: dense). BorderedBandLU factorizes by the
// band LU of E (LAPACK dgbtrf, partial pivoting inside the band), E⁻¹C, and the dense LU of the
// Schur complement A − B E⁻¹ C (Eigen PartialPivLU): cost O(n (kl + ku)(kl + 1) + n · border²),
// linear in n. Everything is sized once; factorize and solve allocate nothing.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "linalg/dense_solvers.hpp"

namespace ffrf::solve {

struct BandStructure {
  int border = 0;     // dense leading rows/columns
  int band_size = 0;  // n, the banded block's size
  int lower = 0;      // kl
  int upper = 0;      // ku
  int size() const { return border + band_size; }
};

class BorderedBandMatrix {
 public:
  BorderedBandMatrix() = default;
  explicit BorderedBandMatrix(const BandStructure& structure);

  const BandStructure& structure() const { return structure_; }
  int size() const { return structure_.size(); }
  void set_zero();

  // Entry (i, j) in the whole matrix's indices; must lie in the structure (assert-checked in debug).
  double& at(int i, int j);
  double at(int i, int j) const;
  bool in_structure(int i, int j) const;

  Eigen::MatrixXd& corner() { return corner_; }             // A
  Eigen::MatrixXd& border_rows() { return border_rows_; }   // B
  Eigen::MatrixXd& border_columns() { return border_columns_; }  // C
  const Eigen::MatrixXd& corner() const { return corner_; }
  const Eigen::MatrixXd& border_rows() const { return border_rows_; }
  const Eigen::MatrixXd& border_columns() const { return border_columns_; }
  // E(i, j) for band indices i, j (0-based inside E), |i − j| within the band.
  double& band(int i, int j) { return band_(structure_.upper + i - j, j); }
  double band(int i, int j) const { return band_(structure_.upper + i - j, j); }
  // E in LAPACK band storage ((ku + kl + 1) × n, column j holds E(j − ku … j + kl, j)).
  Eigen::MatrixXd& band_storage() { return band_; }
  const Eigen::MatrixXd& band_storage() const { return band_; }

  // this = a x + b y + c z for matrices of the same structure.
  void assign_combination(double a, const BorderedBandMatrix& x, double b, const BorderedBandMatrix& y, double c,
                          const BorderedBandMatrix& z);
  // out = this · v (out may not alias v).
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> out) const;
  Eigen::MatrixXd dense() const;  // for tests and diagnostics

 private:
  friend class BorderedBandLU;
  BandStructure structure_;
  Eigen::MatrixXd corner_, border_rows_, border_columns_;
  Eigen::MatrixXd band_;  // (ku + kl + 1) × n, column j holds E(j − ku … j + kl, j) (LAPACK band storage)
};

class BorderedBandLU {
 public:
  BorderedBandLU() = default;
  explicit BorderedBandLU(const BandStructure& structure);
  // false when E or the Schur complement is singular (a zero pivot) or not finite.
  bool factorize(const BorderedBandMatrix& matrix);
  // x ← M⁻¹ x (after a successful factorize).
  void solve(Eigen::Ref<Eigen::VectorXd> x);

 private:
  BandStructure structure_;
  Eigen::MatrixXd factored_band_;      // (2 kl + ku + 1) × n: dgbtrf's layout with room for fill
  std::vector<int> pivots_;
  Eigen::MatrixXd band_inverse_columns_;  // E⁻¹ C_border (n × border), C_border's columns scaled
  Eigen::MatrixXd border_rows_;           // R B (R, C: the border's row and column equilibration)
  Eigen::VectorXd border_row_scale_, border_column_scale_;
  Eigen::MatrixXd schur_;                 // R (A − B E⁻¹ C) C
  Eigen::PartialPivLU<Eigen::MatrixXd> schur_lu_;
  Eigen::VectorXd border_work_;
};

}  // namespace ffrf::solve
