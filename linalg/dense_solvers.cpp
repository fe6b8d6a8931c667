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

}  // namespace Eigen
