// Bordered band matrices and their LU factorization (see bordered_band_matrix.hpp): LAPACK's band
// LU (dgbtrf/dgbtrs) for the banded block, Eigen's PartialPivLU for the Schur complement of the
// border.
#include "solve/bordered_band_matrix.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>

extern "C" {
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku, double* ab, const int* ldab, int* ipiv, int* info);
void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku, const int* nrhs, const double* ab,
             const int* ldab, const int* ipiv, double* b, const int* ldb, int* info, std::size_t trans_length);
}

namespace ffrf::solve {

BorderedBandMatrix::BorderedBandMatrix(const BandStructure& structure)
    : structure_(structure),
      corner_(Eigen::MatrixXd::Zero(structure.border, structure.border)),
      border_rows_(Eigen::MatrixXd::Zero(structure.border, structure.band_size)),
      border_columns_(Eigen::MatrixXd::Zero(structure.band_size, structure.border)),
      band_(Eigen::MatrixXd::Zero(structure.lower + structure.upper + 1, structure.band_size)) {}

void BorderedBandMatrix::set_zero() {
  corner_.setZero();
  border_rows_.setZero();
  border_columns_.setZero();
  band_.setZero();
}

bool BorderedBandMatrix::in_structure(int i, int j) const {
  const int b = structure_.border;
  if (i < 0 || j < 0 || i >= size() || j >= size()) return false;
  if (i < b || j < b) return true;
  const int offset = i - j;
  return offset <= structure_.lower && -offset <= structure_.upper;
}

double& BorderedBandMatrix::at(int i, int j) {
  assert(in_structure(i, j));
  const int b = structure_.border;
  if (i < b) return j < b ? corner_(i, j) : border_rows_(i, j - b);
  if (j < b) return border_columns_(i - b, j);
  return band(i - b, j - b);
}

double BorderedBandMatrix::at(int i, int j) const {
  if (!in_structure(i, j)) return 0.0;
  const int b = structure_.border;
  if (i < b) return j < b ? corner_(i, j) : border_rows_(i, j - b);
  if (j < b) return border_columns_(i - b, j);
  return band(i - b, j - b);
}

void BorderedBandMatrix::assign_combination(double a, const BorderedBandMatrix& x, double b, const BorderedBandMatrix& y,
                                            double c, const BorderedBandMatrix& z) {
  corner_ = a * x.corner_ + b * y.corner_ + c * z.corner_;
  border_rows_ = a * x.border_rows_ + b * y.border_rows_ + c * z.border_rows_;
  border_columns_ = a * x.border_columns_ + b * y.border_columns_ + c * z.border_columns_;
  band_ = a * x.band_ + b * y.band_ + c * z.band_;
}

void BorderedBandMatrix::multiply(const Eigen::Ref<const Eigen::VectorXd>& v, Eigen::Ref<Eigen::VectorXd> out) const {
  const int b = structure_.border, n = structure_.band_size;
  out.head(b).noalias() = corner_ * v.head(b);
  out.head(b).noalias() += border_rows_ * v.tail(n);
  out.tail(n).noalias() = border_columns_ * v.head(b);
  for (int j = 0; j < n; ++j) {
    const int first = std::max(0, j - structure_.upper), last = std::min(n - 1, j + structure_.lower);
    const double vj = v(b + j);
    for (int i = first; i <= last; ++i) out(b + i) += band(i, j) * vj;
  }
}

Eigen::MatrixXd BorderedBandMatrix::dense() const {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(size(), size());
  for (int i = 0; i < size(); ++i) {
    for (int j = 0; j < size(); ++j) m(i, j) = at(i, j);
  }
  return m;
}

BorderedBandLU::BorderedBandLU(const BandStructure& structure)
    : structure_(structure),
      factored_band_(2 * structure.lower + structure.upper + 1, structure.band_size),
      pivots_(static_cast<std::size_t>(structure.band_size)),
      band_inverse_columns_(structure.band_size, structure.border),
      border_rows_(structure.border, structure.band_size),
      border_row_scale_(structure.border),
      border_column_scale_(structure.border),
      schur_(structure.border, structure.border),
      schur_lu_(structure.border),
      border_work_(structure.border) {}

bool BorderedBandLU::factorize(const BorderedBandMatrix& matrix) {
  const int b = structure_.border, n = structure_.band_size, kl = structure_.lower, ku = structure_.upper;
  // Equilibrate the border (rows, then columns, to unit largest entry; LAPACK dgeequ's idea): its
  // rows mix hull inertias of 1e10 with constraint rows of 1, and partial pivoting on the unscaled
  // Schur complement would lose the small rows to round-off.
  for (int i = 0; i < b; ++i) {
    double largest = matrix.corner_.row(i).cwiseAbs().maxCoeff();
    if (n > 0) largest = std::max(largest, matrix.border_rows_.row(i).cwiseAbs().maxCoeff());
    border_row_scale_(i) = largest > 0.0 && std::isfinite(largest) ? 1.0 / largest : 1.0;
  }
  for (int j = 0; j < b; ++j) {
    double largest = (border_row_scale_.asDiagonal() * matrix.corner_.col(j)).cwiseAbs().maxCoeff();
    if (n > 0) largest = std::max(largest, matrix.border_columns_.col(j).cwiseAbs().maxCoeff());
    border_column_scale_(j) = largest > 0.0 && std::isfinite(largest) ? 1.0 / largest : 1.0;
  }
  if (n > 0) {
    // dgbtrf wants E in rows kl … 2kl + ku of its (2 kl + ku + 1) × n array (the top kl rows take the fill).
    factored_band_.topRows(kl).setZero();
    factored_band_.bottomRows(kl + ku + 1) = matrix.band_;
    if (!factored_band_.allFinite()) return false;
    const int ldab = 2 * kl + ku + 1;
    int info = 0;
    dgbtrf_(&n, &n, &kl, &ku, factored_band_.data(), &ldab, pivots_.data(), &info);
    if (info != 0) return false;
    if (b > 0) {
      band_inverse_columns_ = matrix.border_columns_ * border_column_scale_.asDiagonal();
      const char trans = 'N';
      dgbtrs_(&trans, &n, &kl, &ku, &b, factored_band_.data(), &ldab, pivots_.data(), band_inverse_columns_.data(), &n,
              &info, 1);
      if (info != 0) return false;
    }
  }
  if (b > 0) {
    border_rows_ = border_row_scale_.asDiagonal() * matrix.border_rows_;
    schur_ = border_row_scale_.asDiagonal() * matrix.corner_ * border_column_scale_.asDiagonal();
    if (n > 0) schur_.noalias() -= border_rows_ * band_inverse_columns_;
    if (!schur_.allFinite()) return false;
    schur_lu_.compute(schur_);
    // PartialPivLU does not report singularity: a zero pivot shows as a zero on U's diagonal.
    const auto pivots = schur_lu_.matrixLU().diagonal();
    if (!(pivots.cwiseAbs().minCoeff() > 0.0) || !pivots.allFinite()) return false;
  }
  return true;
}

void BorderedBandLU::solve(Eigen::Ref<Eigen::VectorXd> x) {
  const int b = structure_.border, n = structure_.band_size, kl = structure_.lower, ku = structure_.upper;
  if (n > 0) {  // y = E⁻¹ x_e
    const int ldab = 2 * kl + ku + 1, one = 1;
    int info = 0;
    const char trans = 'N';
    dgbtrs_(&trans, &n, &kl, &ku, &one, factored_band_.data(), &ldab, pivots_.data(), x.tail(n).data(), &n, &info, 1);
  }
  if (b == 0) return;
  border_work_ = border_row_scale_.cwiseProduct(x.head(b));
  if (n > 0) border_work_.noalias() -= border_rows_ * x.tail(n);  // R (x_b − B y)
  x.head(b) = schur_lu_.solve(border_work_);                     // the scaled border unknowns C⁻¹ x_b
  if (n > 0) x.tail(n).noalias() -= band_inverse_columns_ * x.head(b);  // y − E⁻¹C x_b
  x.head(b) = border_column_scale_.cwiseProduct(x.head(b));
}

}  // namespace ffrf::solve
