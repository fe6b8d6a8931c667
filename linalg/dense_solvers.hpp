// Dense Eigen eigen solvers and factorizations compiled once for the whole project.
//
// Eigen's dense eigen solvers and factorizations are templates that every translation unit using
// them instantiates and optimises again: one instantiation of a self-adjoint or general eigen solver
// on a MatrixXd costs GCC 7-12 CPU-seconds at -O3, a Cholesky, LDLT, LU or QR factorization 1-4, and
// about thirty files of the libraries and the tests use them.
// Including this header instead of <Eigen/Eigenvalues> declares those instantiations `extern`
// (C++ explicit instantiation declarations), so a file that uses them only calls them; the one
// definition of each is compiled in linalg/dense_solvers.cpp (ffrf_linalg). An explicit
// instantiation declaration of a class does not cover its member templates, so the constructors'
// and compute()'s templates are declared for a MatrixXd argument, the form every caller uses; a
// call with another argument type (an expression) still compiles, instantiated locally.
// Nothing here changes what is computed: the same Eigen code runs, compiled in one place.
#pragma once

#include <Eigen/Dense>

namespace Eigen {

extern template class SelfAdjointEigenSolver<MatrixXd>;
extern template SelfAdjointEigenSolver<MatrixXd>& SelfAdjointEigenSolver<MatrixXd>::compute<MatrixXd>(
    const EigenBase<MatrixXd>&, int);

extern template class GeneralizedSelfAdjointEigenSolver<MatrixXd>;

extern template class EigenSolver<MatrixXd>;
extern template EigenSolver<MatrixXd>& EigenSolver<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&, bool);

extern template class FullPivLU<MatrixXcd>;

extern template class PartialPivLU<MatrixXcd>;

// The real factorizations: the class covers PartialPivLU's factorization (its compute() is not a
// template); the others factor in compute<InputType>, declared here for a MatrixXd argument.
extern template class PartialPivLU<MatrixXd>;

extern template class LLT<MatrixXd>;
extern template LLT<MatrixXd>& LLT<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&);

extern template class LDLT<MatrixXd>;
extern template LDLT<MatrixXd>& LDLT<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&);

extern template class ColPivHouseholderQR<MatrixXd>;
extern template ColPivHouseholderQR<MatrixXd>& ColPivHouseholderQR<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&);

}  // namespace Eigen
