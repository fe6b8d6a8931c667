// The one instantiation of each dense Eigen solver declared `extern` in linalg/dense_solvers.hpp.
#include "linalg/dense_solvers.hpp"

namespace Eigen {

template class SelfAdjointEigenSolver<MatrixXd>;
template SelfAdjointEigenSolver<MatrixXd>& SelfAdjointEigenSolver<MatrixXd>::compute<MatrixXd>(
    const EigenBase<MatrixXd>&, int);

template class GeneralizedSelfAdjointEigenSolver<MatrixXd>;

template class EigenSolver<MatrixXd>;
template EigenSolver<MatrixXd>& EigenSolver<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&, bool);

template class FullPivLU<MatrixXcd>;

template class PartialPivLU<MatrixXcd>;

template class PartialPivLU<MatrixXd>;

template class LLT<MatrixXd>;
template LLT<MatrixXd>& LLT<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&);

template class LDLT<MatrixXd>;
template LDLT<MatrixXd>& LDLT<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&);

template class ColPivHouseholderQR<MatrixXd>;
template ColPivHouseholderQR<MatrixXd>& ColPivHouseholderQR<MatrixXd>::compute<MatrixXd>(const EigenBase<MatrixXd>&);

}  // namespace Eigen
