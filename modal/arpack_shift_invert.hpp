// ARPACK (dsaupd/dseupd, arpack-ng's arpack/arpack.hpp) in shift-invert mode 3 for
// K φ = λ M φ: OP = (K − σM)⁻¹M with B = M, K − σM factored once by a sparse LDLᵀ
// (Eigen::SimplicialLDLT). A Spectra-style class: compute(nev, ncv, sigma), eigenvalues(),
// eigenvectors(), info() and info_message() that explains ARPACK's status in words.
// The reverse-communication loop lives here; the operator products are small functions beside it.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <string>

#include "modal/eigen_solver.hpp"

namespace ffrf::modal {

enum class ArpackInfo { not_computed, successful, not_converging, numerical_issue };

class ArpackShiftInvert {
 public:
  ArpackShiftInvert(const SparseMatrix& stiffness, const SparseMatrix& mass);

  // Returns the number of converged eigenpairs; info() tells success or failure.
  int compute(int nev, int ncv, double sigma, double tolerance = 0.0, int max_iterations = 3000);

  const Eigen::VectorXd& eigenvalues() const { return eigenvalues_; }    // ascending
  const Eigen::MatrixXd& eigenvectors() const { return eigenvectors_; }  // M-normalized
  ArpackInfo info() const { return info_; }
  const std::string& info_message() const { return message_; }
  const EigenStats& stats() const { return stats_; }

 private:
  const SparseMatrix& stiffness_;
  const SparseMatrix& mass_;
  Eigen::VectorXd eigenvalues_;
  Eigen::MatrixXd eigenvectors_;
  ArpackInfo info_ = ArpackInfo::not_computed;
  std::string message_ = "not computed";
  EigenStats stats_;
};

}  // namespace ffrf::modal
